// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/square_root.hpp — sqrt correctly rounded, in arithmetic a loop vectorises.
//
// ::sqrtf and ::sqrt may set errno, so under -fmath-errno (the default) a loop that calls
// them stays scalar. square_root(x) is IEEE's sqrt bit for bit for every float and double
// (NaN for a negative x, a NaN's own payload kept), from additions, multiplications, bit
// operations and selects alone; ordinary_root(x) is the same for a positive normal x only,
// with no select at all, so that it vectorises at g++ -O2 on SSE2 too. 1/sqrt(x) is estimated
// from the bit pattern and refined by Newton's (or Goldschmidt's) iteration, then the root is
// decided exactly between two neighbours (a float's in float and 32-bit lanes alone).
// No branch, and no exception but inexact that IEEE's sqrt would not raise (nor the invalid
// one it raises for a negative x).
//
// Exact decision: for neighbours a < b (b = a + ulp(a)), sqrt(x) > (a + b) / 2 exactly when
// x > a b: with a = A 2^q (A an integer of R's digits), x / 4^q is an integer X near A^2, and
// 4X > (2A + 1)^2 <=> X > A (A + 1), the midpoint's square being odd. a b is split into exact
// partial products (halves cut on the bit pattern, not by Veltkamp's multiplication), whose
// differences from x are exact too: no value depends on contraction into fused multiply-adds.
//
// Owns: detail::square_root, detail::ordinary_root.
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

/// The sign bit of v, as 0 or 1 (a mask built from a double comparison does not vectorise
/// at g++ -O2 with SSE2; a shift does).
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr std::uint64_t sign_of(double v) noexcept {
  return __builtin_bit_cast(std::uint64_t, v) >> 63;
}

/// 1 if m > a b, else 0, exactly, for m in [1, 4) and neighbours a < b near sqrt(m) (the
/// midpoint of a and b within an ulp of sqrt(m)). The 26-bit halves (split on the bit
/// pattern) make every partial product exact, and each difference is exact too: m - a_h b_h
/// is a multiple of 2^-52 under 2^-23, the next one of 2^-77 under 2^-24. With no rounded
/// product, contraction into fused multiply-adds cannot change any value (only exact products
/// and exact sums are fused), and the last difference's sign is exact either way.
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr std::uint64_t above_product(
    double m, double a, double b) noexcept {
  constexpr std::uint64_t low_bits = (std::uint64_t{1} << 27) - 1;
  const auto high = [](double v) {  // the 26 leading bits, rounded
    return __builtin_bit_cast(
        double, (__builtin_bit_cast(std::uint64_t, v) + (std::uint64_t{1} << 26)) & ~low_bits);
  };
  const double a_high = high(a);
  const double a_low = a - a_high;
  const double b_high = high(b);
  const double b_low = b - b_high;
  const double rest = ((m - a_high * b_high) - a_high * b_low) - a_low * b_high;
  const double over = rest - a_low * b_low;  // m - a b
  return sign_of(0.0 - over);  // 0 - z: +0 for either zero (a -0 would read as "above")
}

/// 1 if m > a (a + 2^-23), else 0, exactly, for m in [1, 4) and a float a near sqrt(m), in
/// [1, 2] or 1 - 2^-24 (whose test then says "above": m >= 1): a and its upper neighbour when
/// a < 2. With a = a_h + a_l, a_h a multiple of 2^-11 and |a_l| <= 2^-12 (a_l a multiple of
/// 2^-23), m - a b = m - a_h a_h - a_h (2 a_l) - a_h 2^-23 - a_l (a_l + 2^-23): each product
/// exact (12 bits by 12, 11 by 12 unless a_l = +-2^-12), the first sum a multiple of 2^-23
/// under 2^-9 and the next two of 2^-34 under 2^-20 (all exact), the last one's sign exact,
/// fused or not. Computed as a b - m, which is never -0, so its sign bit is the answer.
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr std::uint32_t above_product(
    float m, float a) noexcept {
  constexpr std::uint32_t low_bits = (std::uint32_t{1} << 12) - 1;
  constexpr float ulp = 0x1p-23f;           // of a in [1, 2)
  const float a_high = __builtin_bit_cast(  // the 12 leading bits, rounded
      float, (__builtin_bit_cast(std::uint32_t, a) + (std::uint32_t{1} << 11)) & ~low_bits);
  const float a_low = a - a_high;
  const float rest = ((a_high * a_high - m) + a_high * (a_low + a_low)) + a_high * ulp;
  return __builtin_bit_cast(std::uint32_t, rest + a_low * (a_low + ulp)) >> 31;
}

/// sqrt(x) for a positive normal float, in float and 32-bit integer lanes alone (twice the
/// lanes of double steps, and no conversions; masks never need 64-bit lanes). x = m 4^k with
/// m in [1, 4), so no step overflows or underflows; 1/(2 sqrt(m)) from the bit pattern (3.4%
/// off) and two of Goldschmidt's coupled steps (about 5e-6); Heron's correction gives s within
/// e = 0.36 ulp of sqrt(m) (y y's rounding if unfused, times g <= 0.354; 0.25 ulp for m < 2).
/// t = fl(s - 7/16 ulp) then has sqrt(m) in [t - ulp/2, t + 3 ulp/2] (as 7/16 >= e and
/// 7/16 + e <= 1), so the root is t or its upper neighbour, which the exact test decides;
/// near 1, 7/16 + 0.25 < 3/4 keeps t >= 1 - 2^-24, and t = 2 is kept (m < 4 < 2 (2 + 2^-23)).
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr float ordinary_root(float x) noexcept {
  const auto bits = __builtin_bit_cast(std::uint32_t, x);
  // m's biased exponent is 127 or 128, of x's parity (so x / m is an even power of 2).
  const std::uint32_t m_bits = ((bits ^ 0x00800000u) & 0x00ffffffu) + 0x3f800000u;
  const std::uint32_t half_m_bits = m_bits >> 1;
  const auto shift = static_cast<std::uint32_t>((bits >> 1) - half_m_bits);  // k << 23
  const auto m = __builtin_bit_cast(float, m_bits);
  float g = __builtin_bit_cast(float, static_cast<std::uint32_t>(0x5eb759dfu - half_m_bits));
  float y = m * (g + g);
  for (int step = 0; step < 2; ++step) {  // y -> sqrt(m), g -> 1 / (2 sqrt(m))
    const float e = 0.5f - y * g;
    y = y + y * e;
    g = g + g * e;
  }
  const float t = y + ((m - y * y) * g - 0x1.cp-25f);
  const std::uint32_t root = __builtin_bit_cast(std::uint32_t, t) + above_product(m, t);
  return __builtin_bit_cast(float, static_cast<std::uint32_t>(root + shift));
}

/// sqrt(x) for a positive normal double. x = m 4^k with m in [1, 4) by integer arithmetic,
/// so no step can overflow or underflow; 1/sqrt(m) by the bit pattern and three Newton steps
/// (about 3e-11), Heron's correction to t = y + d within 0.4 ulp of sqrt(m), and of the two
/// doubles around the midpoint nearest t (t's side of y = fl(t), from Fast2Sum's error) the
/// one the exact test picks: within 0.9 ulp, sqrt(m) rounds to one of those two.
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr double ordinary_root(double x) noexcept {
  constexpr std::uint64_t exponent = 0xfff0000000000000u;
  const auto bits = __builtin_bit_cast(std::uint64_t, x);
  // (k + 512) << 52, k = floor((E - 1023) / 2) for the biased exponent E; then k << 52.
  const std::uint64_t shift =
      (((bits + (std::uint64_t{1} << 52)) >> 1) & exponent) - (std::uint64_t{512} << 52);
  const double m = __builtin_bit_cast(double, static_cast<std::uint64_t>(bits - (shift + shift)));
  double r =
      __builtin_bit_cast(double, 0x5fe6eb50c7b537a9u - (__builtin_bit_cast(std::uint64_t, m) >> 1));
  const double half = m * 0.5;
  for (int step = 0; step < 3; ++step) r = r * (1.5 - half * r * r);
  const double y = m * r;
  const double d = (m - y * y) * (r * 0.5);
  const double t = y + d;
  const double error = d - (t - y);  // t's rounding error, whose sign says where y + d lies
  const std::uint64_t low_bits = __builtin_bit_cast(std::uint64_t, t) - sign_of(error);
  const auto low = __builtin_bit_cast(double, low_bits);
  const double high = __builtin_bit_cast(double, static_cast<std::uint64_t>(low_bits + 1));
  const std::uint64_t root = low_bits + above_product(m, low, high);
  return __builtin_bit_cast(double, static_cast<std::uint64_t>(root + shift));
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
  // A subnormal x is scaled into the normals by an even power of 2 (exact both ways).
  constexpr Bits least_normal = Bits{1} << (sizeof(R) == 4 ? 23 : 52);
  const bool subnormal = bits < least_normal;
  const R scale = pick(subnormal, sizeof(R) == 4 ? R(0x1p24) : R(0x1p54), R(1));
  const R unscale = pick(subnormal, sizeof(R) == 4 ? R(0x1p-12) : R(0x1p-27), R(1));
  const R root = ordinary_root(pick(ordinary, x, R(1)) * scale) * unscale;
  // ±0, +infinity and NaN are their own root (x + x quiets a NaN, as sqrt does); a negative
  // x's is a quiet NaN, by its bits (no division: 0 / 0 is a division by zero to a sanitizer,
  // and a NaN's payload is not part of sqrt's result).
  const R itself = pick(ordinary | negative, R(0), x);
  constexpr R quiet_nan = __builtin_bit_cast(
      R, static_cast<Bits>(infinity |
                           (static_cast<Bits>(FloatBits<R>::magnitude_mask ^ infinity) + 1) / 2));
  const R special = pick(negative, quiet_nan, itself + itself);
  return pick(ordinary, root, special);
}

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
