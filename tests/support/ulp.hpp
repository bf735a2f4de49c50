// SPDX-License-Identifier: BSL-1.0
// Test support: floating-point values compared by their bits: the same bits, and the distance
// in units in the last place.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include <pointmass/vector3.hpp>

namespace pointmass::test {

/// The same bits (so NaN == NaN, and +0 != -0). The value's bits only: x86's long double
/// keeps its 80 bits in the first 10 of its bytes, and the padding after them is no part of
/// the value (and need not match: a sanitized build leaves it as it finds it).
template <class R>
bool same_bits(R a, R b) {
  constexpr bool x87 =
      std::is_same_v<R, long double> && std::numeric_limits<long double>::digits == 64;
  return std::memcmp(&a, &b, x87 ? 10 : sizeof(R)) == 0;
}
template <class R>
bool same_bits(const Vector3<R>& a, const Vector3<R>& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

/// Distance in ulps between two values of R (float or double) of any sign: the difference of
/// their bit patterns, ordered so that -0 and +0 are 0 apart.
template <class R>
long long ulp_distance(R a, R b) {
  using Bits = std::conditional_t<sizeof(R) == 4, std::int32_t, std::int64_t>;
  Bits ia = 0, ib = 0;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  const long long oa = ia < 0 ? -static_cast<long long>(ia & std::numeric_limits<Bits>::max()) : ia;
  const long long ob = ib < 0 ? -static_cast<long long>(ib & std::numeric_limits<Bits>::max()) : ib;
  return oa > ob ? oa - ob : ob - oa;
}

}  // namespace pointmass::test
