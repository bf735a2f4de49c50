// SPDX-License-Identifier: BSL-1.0
// Test support: the distance between two floating-point values in units in the last place.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace pointmass::test {

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
