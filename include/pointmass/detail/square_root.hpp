// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/square_root.hpp — sqrt correctly rounded, in arithmetic a loop vectorises.
//
// ::sqrtf and ::sqrt may set errno, so under -fmath-errno (the default) a loop that calls
// them stays scalar. square_root(x) is IEEE's sqrt bit for bit for every float and double
// (NaN for a negative x, a NaN's own payload kept), from additions, multiplications,
// comparisons and selects alone: 1/sqrt(x) estimated from the bit pattern and refined by
// Newton's iteration, then of the three Reals nearest the estimate the one whose rounding
// interval holds sqrt(x), decided exactly. No branch, and no exception but inexact that IEEE's
// sqrt would not raise (a special input takes the arithmetic with 1 in its place).
//
// Exact decision: for neighbours a < b (b = a + ulp(a)), sqrt(x) > (a + b) / 2 exactly when
// x > a b: with a = A 2^q (A an integer of R's digits), x / 4^q is an integer X near A^2, and
// 4X > (2A + 1)^2 <=> X > A (A + 1), the midpoint's square being odd. A float's a b is exact
// in double; a double's is p + e by Dekker's product, p within a factor 2 of x, so x - p is
// exact and x > a b <=> x - p > e. The split is done on the bit pattern, not by Veltkamp's
// multiplication, so that a compiler contracting to fused multiply-adds cannot change it.
//
// Owns: detail::square_root.
// Must not include: anything but config.hpp and real.hpp.
#pragma once

#include <cstdint>

#include "../config.hpp"
#include "../real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

/// c ? a : b as bit operations: g++ does not if-convert a `?:` in a loop (whose arms it then
/// keeps apart), and a branch stops vectorisation.
template <class T>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr T pick(bool c, T a, T b) noexcept {
  if constexpr (has_ieee_bits_v<T>) {
    using Bits = typename FloatBits<T>::type;
    const Bits mask = Bits(0) - static_cast<Bits>(c);
    return __builtin_bit_cast(T, static_cast<Bits>((__builtin_bit_cast(Bits, a) & mask) |
                                                   (__builtin_bit_cast(Bits, b) & ~mask)));
  } else {
    return c ? a : b;
  }
}

template <class R, class Bits>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R step_bits(
    R x, Bits by) noexcept {  // the Real `by` steps above x > 0
  return __builtin_bit_cast(R, static_cast<Bits>(__builtin_bit_cast(Bits, x) + by));
}

/// 1/sqrt(x) for a double x in [2^-1000, 2^1000], to about 2^-(2^n 4.9): the bit pattern's
/// estimate (3.4% off at most) and n steps of Newton's iteration.
template <int Steps>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr double inverse_root(double x) noexcept {
  const std::uint64_t estimate = 0x5fe6eb50c7b537a9u - (__builtin_bit_cast(std::uint64_t, x) >> 1);
  double r = __builtin_bit_cast(double, estimate);
  const double half = x * 0.5;
  for (int step = 0; step < Steps; ++step) r = r * (1.5 - half * r * r);
  return r;
}

/// x > a b, exactly, for doubles a, b > 0 whose rounded product lies within a factor 2 of x
/// and whose partial products neither overflow nor underflow.
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr bool above_product(double x, double a,
                                                                         double b) noexcept {
  // The high half: the 26 leading bits, rounded (the low half then fits in 26 bits too).
  constexpr std::uint64_t low_bits = (std::uint64_t{1} << 27) - 1;
  const auto high = [](double v) {
    return __builtin_bit_cast(
        double, (__builtin_bit_cast(std::uint64_t, v) + (std::uint64_t{1} << 26)) & ~low_bits);
  };
  const double a_high = high(a);
  const double a_low = a - a_high;
  const double b_high = high(b);
  const double b_low = b - b_high;
  const double p = a * b;
  const double high_product = a_high * b_high;
  double e = high_product - p;
  e += a_high * b_low;
  e += a_low * b_high;
  e += a_low * b_low;  // a b = p + e
  return x - p > e;
}

/// sqrt(x) for a float in [2^-149, 2^128): the double estimate rounded to float, then the
/// neighbour whose interval holds the root.
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr float root_of_ordinary(float x) noexcept {
  const auto wide = static_cast<double>(x);
  const auto y = static_cast<float>(wide * inverse_root<3>(wide));  // within 2^-34 of it
  const float below = step_bits(y, ~std::uint32_t{0});
  const float above = step_bits(y, std::uint32_t{1});
  const auto y_wide = static_cast<double>(y);
  const bool over_low = wide > static_cast<double>(below) * y_wide;
  const bool over_high = wide > y_wide * static_cast<double>(above);
  // Chosen among doubles: a double comparison's mask is 64 bits wide (SSE2 cannot narrow it).
  return static_cast<float>(pick(over_high, static_cast<double>(above),
                                 pick(over_low, y_wide, static_cast<double>(below))));
}

/// sqrt(x) for a positive finite double: scaled by an even power of 2 into [2^-500, 2^500]
/// (exact both ways), estimated to within an ulp by one Heron step on Newton's 1/sqrt, and
/// decided among the three nearest doubles.
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr double root_of_ordinary(double x) noexcept {
  const bool tiny = x < 0x1p-500;
  const bool huge = x > 0x1p500;
  const double scaled = x * pick(tiny, 0x1p600, pick(huge, 0x1p-600, 1.0));
  const double r = inverse_root<4>(scaled);
  const double estimate = scaled * r;
  const double square = estimate * estimate;
  const double y = estimate + (r * 0.5) * (scaled - square);  // scaled - square is exact
  const double below = step_bits(y, ~std::uint64_t{0});
  const double above = step_bits(y, std::uint64_t{1});
  const bool over_low = above_product(scaled, below, y);
  const bool over_high = above_product(scaled, y, above);
  const double root = pick(over_high, above, pick(over_low, y, below));
  return root * pick(tiny, 0x1p-300, pick(huge, 0x1p300, 1.0));
}

/// IEEE's sqrt(x), bit for bit, for float and double; see the header's comment.
template <class R>
  requires(has_ieee_bits_v<R>)
[[nodiscard]] POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R square_root(R x) noexcept {
  using Bits = typename FloatBits<R>::type;
  constexpr Bits sign = static_cast<Bits>(FloatBits<R>::magnitude_mask + Bits{1});
  constexpr Bits infinity = FloatBits<R>::exponent_mask;
  const Bits bits = __builtin_bit_cast(Bits, x);
  const bool ordinary = static_cast<Bits>(bits - Bits{1}) < static_cast<Bits>(infinity - 1);
  const bool negative = static_cast<Bits>(bits - sign - Bits{1}) < infinity;  // -0 < x, no NaN
  const R root = root_of_ordinary(pick(ordinary, x, R(1)));
  // ±0, +infinity and NaN are their own root (x + x quiets a NaN, as sqrt does); a negative
  // x's is 0 / 0 (or, for -infinity, NaN / NaN), formed only where x is negative.
  const R itself = pick(ordinary | negative, R(0), x);
  const R negative_x = pick(negative, x, R(0));
  const R zero = pick(negative, negative_x - negative_x, R(1));
  const R special = pick(negative, zero / zero, itself + itself);
  return pick(ordinary, root, special);
}

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
