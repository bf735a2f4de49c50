// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/logarithm.hpp — ln d of a damping value, stored as the exponential needs it.
//
//   detail::split_log(d)    ln d for d in [0, 1], stored as hi + lo (once, when a damping value
//                           is set), from the library's own log_double / log_double_double
//   detail::ExpTraits<R>    the constants of float's and double's exponential and logarithm
//   detail::split_high(x)   the high half of x's significand (split_log's hi, split_time's)
//
// ln d comes from + - * / alone, not from the C library's log, so hi + lo has the same bits on
// every platform (split_log says why). detail/exponential.hpp computes d^t = e^(t ln d) from it.
//
// Owns: ln d as split_log stores it (log_double, log_double_double and the double-double
// arithmetic under them), and what the exponential shares with it (ExpTraits, split_high).
// Must not include: anything but config.hpp and real.hpp (the exponential builds on it).
#pragma once

#include <bit>
#include <cfloat>
#include <cstdint>
#include <type_traits>

#include "../config.hpp"
#include "../real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

/// What the exponential and split_log need of each precision (float and double).
template <class R>
struct ExpTraits;

template <>
struct ExpTraits<float> {
  using bits = std::uint32_t;
  static constexpr int significand_bits = 24;
  static constexpr int exponent_bias = 127;
  static constexpr bits split_mask = 0xFFFFF000u;  ///< keeps 12 significant bits
  static constexpr float shifter = 0x1.8p23f;      ///< 1.5 * 2^23: x + shifter rounds x
  static constexpr float inv_ln2 = 0x1.715476p+0f;
  static constexpr float ln2_hi = 0x1.62e4p-1f;      ///< 15 bits: n ln2_hi exact for |n| < 2^9
  static constexpr float ln2_lo = 0x1.7f7d1cp-20f;   ///< ln 2 - ln2_hi
  static constexpr float x_min = -104.0f;            ///< e^-104 < 2^-150: rounds to 0
  static constexpr float x_max = 89.0f;              ///< e^89 > FLT_MAX: overflows
  static constexpr int series_terms = 6;             ///< 1/2! .. 1/7!
  static constexpr float expm1_exact_scale = 20.0f;  ///< 2^n - 1 exact for n <= 20
  static constexpr float log_of_zero = -0x1p96f;     ///< ln 0: t ln 0 < x_min for t >= 2^-89
  static constexpr float normal_x_min = -86.0f;      ///< e^x normal for x_hi >= this: n >= -124
  static constexpr float normal_x_max = 87.0f;       ///< and <= this: n <= 126
};

template <>
struct ExpTraits<double> {
  using bits = std::uint64_t;
  static constexpr int significand_bits = 53;
  static constexpr int exponent_bias = 1023;
  static constexpr bits split_mask = 0xFFFFFFFFF8000000u;  ///< keeps 26 significant bits
  static constexpr double shifter = 0x1.8p52;
  static constexpr double inv_ln2 = 0x1.71547652b82fep+0;
  static constexpr double ln2_hi = 0x1.62e42fee00000p-1;  ///< 32 bits: n ln2_hi exact
  static constexpr double ln2_lo = 0x1.a39ef35793c76p-33;
  static constexpr double x_min = -746.0;  ///< e^-746 < 2^-1075: rounds to 0
  static constexpr double x_max = 710.0;   ///< e^710 > DBL_MAX: overflows
  static constexpr int series_terms = 12;  ///< 1/2! .. 1/13!
  static constexpr double expm1_exact_scale = 40.0;
  static constexpr double log_of_zero = -0x1p960;  ///< ln 0: t ln 0 < x_min for t >= 2^-950
  static constexpr double normal_x_min = -700.0;   ///< e^x normal for x_hi >= this: n >= -1010
  static constexpr double normal_x_max = 700.0;    ///< and <= this: n <= 1010
};

#if LDBL_MANT_DIG == DBL_MANT_DIG && LDBL_MAX_EXP == DBL_MAX_EXP
/// long double where it is double itself (32-bit ARM, Windows): double's traits, so that it
/// takes the same exponential, bit for bit. (Where long double is wider, it calls the C
/// library instead, and this is not defined: using it there does not compile.)
template <>
struct ExpTraits<long double> {
  using D = ExpTraits<double>;
  using bits = D::bits;
  static constexpr int significand_bits = D::significand_bits;
  static constexpr int exponent_bias = D::exponent_bias;
  static constexpr bits split_mask = D::split_mask;
  static constexpr long double shifter = D::shifter;
  static constexpr long double inv_ln2 = D::inv_ln2;
  static constexpr long double ln2_hi = D::ln2_hi;
  static constexpr long double ln2_lo = D::ln2_lo;
  static constexpr long double x_min = D::x_min;
  static constexpr long double x_max = D::x_max;
  static constexpr int series_terms = D::series_terms;
  static constexpr long double expm1_exact_scale = D::expm1_exact_scale;
  static constexpr long double log_of_zero = D::log_of_zero;
  static constexpr long double normal_x_min = D::normal_x_min;
  static constexpr long double normal_x_max = D::normal_x_max;
};
#endif

/// A number split into a high part of half the significand and the rest: hi + lo == x.
template <class R>
POINTMASS_HD constexpr R split_high(R x) noexcept {
  using T = ExpTraits<R>;
  return __builtin_bit_cast(
      R, static_cast<typename T::bits>(__builtin_bit_cast(typename T::bits, x) & T::split_mask));
}

/// A double-double: the number hi + lo, |lo| at most about an ulp of hi (some 106 bits).
struct DoubleDouble {
  double hi;
  double lo;
};

/// a + b as s + e, exactly (Knuth's TwoSum: whatever the magnitudes).
POINTMASS_HD constexpr DoubleDouble two_sum(double a, double b) noexcept {
  const double s = a + b;
  const double b_virtual = s - a;
  const double a_virtual = s - b_virtual;
  return {s, (a - a_virtual) + (b - b_virtual)};
}

/// a + b as s + e, exactly, where |a| >= |b| or a is 0 (Fast2Sum).
POINTMASS_HD constexpr DoubleDouble fast_two_sum(double a, double b) noexcept {
  POINTMASS_DETAIL_IN_ORDER  // reordered, the error would be 0 (config.hpp)
  const double s = a + b;
  return {s, b - (s - a)};
}

/// a * b as p + e, to within 2^-104 |a b| (for products far from the subnormals): Dekker's
/// product over split_high's halves. The halves are cut by a bit mask, not by Veltkamp's
/// multiplication, which a compiler that contracts into fused multiply-adds would change;
/// every partial product but lo * lo (27 bits by 27) is exact, so contraction changes at
/// most that one's last bit.
POINTMASS_HD constexpr DoubleDouble two_product(double a, double b) noexcept {
  POINTMASS_DETAIL_IN_ORDER  // each partial sum exact only in this order (config.hpp)
  const double p = a * b;
  const double a_hi = split_high(a);
  const double a_lo = a - a_hi;
  const double b_hi = split_high(b);
  const double b_lo = b - b_hi;
  return {p, (((a_hi * b_hi - p) + a_hi * b_lo) + a_lo * b_hi) + a_lo * b_lo};
}

/// x + y and x * y for double-doubles, to within a few 2^-104 of the result.
POINTMASS_HD constexpr DoubleDouble dd_add(DoubleDouble x, DoubleDouble y) noexcept {
  const DoubleDouble s = two_sum(x.hi, y.hi);
  return fast_two_sum(s.hi, s.lo + (x.lo + y.lo));
}
/// x + y where |x.hi| >= |y.hi| (or x.hi is 0): dd_add with a Fast2Sum for the leading parts.
POINTMASS_HD constexpr DoubleDouble dd_add_smaller(DoubleDouble x, DoubleDouble y) noexcept {
  const DoubleDouble s = fast_two_sum(x.hi, y.hi);
  return fast_two_sum(s.hi, s.lo + (x.lo + y.lo));
}
POINTMASS_HD constexpr DoubleDouble dd_mul(DoubleDouble x, DoubleDouble y) noexcept {
  const DoubleDouble p = two_product(x.hi, y.hi);
  return fast_two_sum(p.hi, p.lo + (x.hi * y.lo + x.lo * y.hi));
}

/// 1 / n as a double-double (n a small odd integer): the quotient and its remainder's.
POINTMASS_HD constexpr DoubleDouble dd_reciprocal(double n) noexcept {
  const double q = 1.0 / n;
  const DoubleDouble p = two_product(q, n);
  return {q, ((1.0 - p.hi) - p.lo) / n};
}

/// A finite d > 0 as 2^k m with m in [sqrt(1/2), sqrt(2)], exactly (a subnormal d is scaled
/// into the normal range first).
struct LogReduced {
  double k;
  double m;
};
POINTMASS_HD constexpr LogReduced log_reduce(double d) noexcept {
  using B = std::uint64_t;
  double k = 0.0;
  if (d < 0x1p-1022) {
    d *= 0x1p54;
    k = -54.0;
  }
  const B bits = __builtin_bit_cast(B, d);
  k += static_cast<double>(static_cast<int>((bits >> 52) & 0x7FFu) - 1023);
  double m = __builtin_bit_cast(
      double, static_cast<B>((bits & 0x000FFFFFFFFFFFFFu) | 0x3FF0000000000000u));  // [1, 2)
  if (m > 0x1.6a09e667f3bcdp+0) {  // above sqrt(2): halve it
    m *= 0.5;
    k += 1.0;
  }
  return {k, m};
}

/// ln 2 in two parts: the first of 42 bits, so that k times it is exact for |k| < 2^11.
inline constexpr double log2_hi = 0x1.62e42fefa3800p-1;
inline constexpr double log2_lo = 0x1.ef35793c76730p-45;

/// sum_{j=J..Last} z^(j-J) / (2j + 1) by Horner's rule, in double (straight-line code).
template <int J, int Last>
POINTMASS_HD constexpr double atanh_tail(double z) noexcept {
  constexpr double coefficient = 1.0 / (2 * J + 1);
  if constexpr (J == Last) {
    return coefficient;
  } else {
    return atanh_tail<J + 1, Last>(z) * z + coefficient;
  }
}

/// ln d for a finite d > 0 in double, to within about 2^-51 |ln d|, from + - * / alone (no C
/// library: the same bits wherever IEEE double arithmetic is, without contraction). For
/// float's split_log, which keeps 36 bits of it. ln d = k ln 2 + 2 atanh f with
/// f = (m - 1) / (m + 1), |f| <= 0.1716, and 2 atanh f = 2f (1 + z / 3 + z^2 / 5 + ...),
/// z = f^2 <= 0.0295, to z^10 (the first term left out is below 2^-60 of the sum).
POINTMASS_HD constexpr double log_double(double d) noexcept {
  const LogReduced a = log_reduce(d);
  const double f = (a.m - 1.0) / (a.m + 1.0);
  const double z = f * f;
  const double twice_f = 2.0 * f;
  return (a.k * log2_hi + twice_f) + (a.k * log2_lo + twice_f * (z * atanh_tail<1, 10>(z)));
}

/// ln d for a finite d > 0 as a double-double, to within about 2^-75 |ln d| (the tests hold
/// it to 2^-72 against correctly rounded values): what split_log keeps for double, 79 bits,
/// to within its last few; it moves d^t = e^(t ln d) by at most 2^-65 of itself, at the
/// largest |t ln d| of any d^t that is not 0. From + - * / alone, like log_double.
/// ln m = 2f + 2f^3 / 3 + 2f^5 / 5 + ... to f^31: f to f^7 / 7 in double-double, the rest
/// (below 2^-23 of the sum) in double.
POINTMASS_HD constexpr DoubleDouble log_double_double(double d) noexcept {
  POINTMASS_DETAIL_IN_ORDER  // the remainder's steps are exact only in this order (config.hpp)
  const LogReduced a = log_reduce(d);
  // f = (m - 1) / (m + 1): m - 1 is exact (Sterbenz), m + 1 a TwoSum; the quotient, then
  // its remainder's quotient (both through one reciprocal).
  const double numerator = a.m - 1.0;
  const DoubleDouble denominator = fast_two_sum(1.0, a.m);  // m's exponent is at most 1's
  const double reciprocal = 1.0 / denominator.hi;
  const double f_hi = numerator * reciprocal;
  const DoubleDouble product = two_product(f_hi, denominator.hi);
  const double f_lo =
      (((numerator - product.hi) - product.lo) - f_hi * denominator.lo) * reciprocal;
  const DoubleDouble f = fast_two_sum(f_hi, f_lo);
  const DoubleDouble z = dd_mul(f, f);
  const DoubleDouble z2 = dd_mul(z, z);
  const DoubleDouble cube = dd_mul(f, z);
  const DoubleDouble fifth = dd_mul(cube, z);
  const DoubleDouble seventh = dd_mul(cube, z2);
  constexpr DoubleDouble third_coefficient = dd_reciprocal(3.0);
  constexpr DoubleDouble fifth_coefficient = dd_reciprocal(5.0);
  constexpr DoubleDouble seventh_coefficient = dd_reciprocal(7.0);
  const double rest = seventh.hi * (z.hi * atanh_tail<4, 15>(z.hi));
  // The terms share f's sign and shrink (|f| <= 0.1716): each sum a Fast2Sum, smallest first.
  const DoubleDouble half_ln_m = dd_add_smaller(
      f, dd_add_smaller(dd_mul(cube, third_coefficient),
                        dd_add_smaller(dd_mul(fifth, fifth_coefficient),
                                       dd_add_smaller(dd_mul(seventh, seventh_coefficient),
                                                      DoubleDouble{rest, 0.0}))));
  // ln d = k log2_hi (exact) + 2 half_ln_m + k log2_lo; |k ln 2| >= ln 2 > |ln m| unless k = 0.
  const DoubleDouble sum = fast_two_sum(a.k * log2_hi, 2.0 * half_ln_m.hi);
  return fast_two_sum(sum.hi, sum.lo + (2.0 * half_ln_m.lo + a.k * log2_lo));
}

/// ln d for a damping value d in [0, 1], as hi + lo: hi has half the significand (so that
/// t_hi * hi is exact), lo the rest to about twice R's precision. d = 0 gives hi = -infinity
/// and lo = 0; d = 1 gives 0 and 0. For a long double wider than double, hi = ln d, lo = 0.
template <class R>
struct SplitLog {
  R hi = R(0);
  R lo = R(0);
};

/// Computes ln d with the library's own logarithm (log_double for float, log_double_double
/// for double and for long double where it is double), so hi + lo is the same everywhere: on
/// a CUDA device, on 32-bit ARM and with MSVC as on x86-64, whatever the C library's log.
/// Where long double is wider than double, the C library's logl, with lo = 0. Not on the hot
/// path: called when a damping value is set (docs/results/numerics.md measures what that costs). A
/// constant expression for float and double (and long double where it is double): a damping
/// value can be set at compile time.
template <Real R>
POINTMASS_HD constexpr SplitLog<R> split_log(R d) noexcept {
  if (real_equal(d, R(1))) return {R(0), R(0)};
  if constexpr (wider_than_double_v<R>) {
    return {d > R(0) ? real_log(d) : -real_infinity<R>, R(0)};
  } else {
    // ln 0 as a finite stand-in, so that t ln d at t = 0 is 0, not 0 * -infinity (an
    // invalid operation), and d^t is exactly 0 from a tiny t on.
    if (!(d > R(0))) return {ExpTraits<R>::log_of_zero, R(0)};
    if constexpr (std::is_same_v<R, float>) {
      const double wide = log_double(static_cast<double>(d));
      const R hi = split_high(static_cast<R>(wide));
      return {hi, static_cast<R>(wide - static_cast<double>(hi))};  // the difference is exact
    } else {
      const DoubleDouble wide = log_double_double(static_cast<double>(d));
      const R hi = split_high(static_cast<R>(wide.hi));
      return {hi, static_cast<R>((wide.hi - static_cast<double>(hi)) + wide.lo)};
    }
  }
}

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END
