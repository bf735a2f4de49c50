// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/exponential.hpp — the library's own exponential: e^x, e^x - 1 and d^t.
//
//   detail::exp(x), detail::expm1(x)     e^x and e^x - 1 in the precision of x
//   detail::split_log(d)                 ln d for d in [0, 1], stored as hi + lo (once, when a
//                                        damping value is set), from the library's own
//                                        log_double / log_double_double
//   detail::pow_unit(split_log(d), t)    d^t = e^(t ln d) for d in [0, 1], t >= 0
//   detail::exp_unit(split_log(d), t)    d^t and d^t - 1 from one evaluation (damping::Exact)
//   detail::phi_series<Offset>(x)        phi_Offset(x) = sum x^n / (n + Offset)! for |x| < 1
//                                        (damping::Exact; the stiff springs' over-damped step)
//
// Why not the C library's pow and expm1: they are calls the compiler cannot vectorise, about
// 5 ns each, and a loop over particles that each have their own damping paid one per particle
// per step. These are header-only, branch-free (every condition is a select), constexpr and
// POINTMASS_HD, so a loop `out[i] = pow_unit(ln_d[i], t)` vectorises (tests/system checks the
// compilers' reports) and device code can call them.
//
// Method (float and double; long double calls expl / expm1l):
//   1. x = t ln d without rounding error that grows with |x|: ln d is stored as hi + lo with hi
//      of half the significand (12 bits in float, 26 in double), t is split the same way
//      (t_hi + t_lo, once per loop), so x_hi = t_hi hi is exact and x_lo = t_lo hi + t lo
//      carries the rest. (A plain product t * ln d, with ln d rounded, errs by up to |x| / 2
//      ulp twice over: 7 ulp of d^t at d = 1e-3, t = 1 s.)
//   2. x is clamped to [x_min, x_max], beyond which e^x is 0 or infinity in R;
//      n = round(x / ln 2) by the shifter trick (adding 1.5 * 2^(p-1) rounds to an integer),
//      r = (x_hi - n ln2_hi) + (x_lo - n ln2_lo), |r| <= ln 2 / 2: n ln2_hi is exact (ln2_hi
//      has few bits) and so is x_hi - n ln2_hi (the two are within a factor 2).
//   3. e^r = 1 + s, s = r + r^2 q(r), q the Taylor series of (e^r - 1 - r) / r^2 to degree 5
//      (float) or 11 (double): the first omitted term is below 0.1 ulp at |r| = ln 2 / 2.
//   4. e^x = ((1 + s) 2^m1) 2^m2 with m1 + m2 = n, each factor built from its exponent bits:
//      two factors so that subnormal results (n < -126 in float) round once, correctly.
//      e^x - 1 = (2^n - 1) + 2^n s while 2^n - 1 is exact (n <= 20), which keeps the relative
//      accuracy near x = 0, and e^x - 1 beyond.
// No integer conversion of a float and no 64-bit arithmetic shift: SSE2 (plain -O2 on x86-64)
// vectorises it all. Accuracy, measured against long double and __float128:
// docs/results/numerics.md (scripts/exponential-accuracy.sh writes it;
// tests/test_exponential.cpp checks the bounds).
//
// It relies on IEEE arithmetic rounding to nearest: not valid under -ffast-math (which may
// reassociate the shifter trick away). Fused multiply-adds, where the compiler contracts,
// only make the steps more accurate.
//
// Owns: the library's own exponential, logarithm of d and d^t, and the phi series.
// Must not include: anything but config.hpp and real.hpp (the policies build on it).
#pragma once

#include <bit>
#include <cfloat>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../real.hpp"

// These functions are inlined into the caller's loop at any optimisation level
// (POINTMASS_DETAIL_ALWAYS_INLINE): clang and g++ would otherwise call the larger of them
// (exp_unit) from a loop, and a call stops vectorisation.

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

/// What the exponential needs of each precision (float and double).
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

/// 1 / (k + 2)!, the coefficient of r^k in (e^r - 1 - r) / r^2, computed at compile time.
template <class R, int K>
inline constexpr R exp_coefficient = [] {
  R factorial = R(1);
  for (int n = 2; n <= K + 2; ++n) factorial *= R(n);
  return R(1) / factorial;
}();

/// (e^r - 1 - r) / r^2 by Horner's rule over the series' first terms, as straight-line code
/// (a loop over a coefficient array would stay a loop at -O2 and stop vectorisation).
template <class R, int K = 0>
POINTMASS_HD constexpr R exp_series(R r) noexcept {
  if constexpr (K == ExpTraits<R>::series_terms - 1) {
    return exp_coefficient<R, K>;
  } else {
    return exp_series<R, K + 1>(r) * r + exp_coefficient<R, K>;
  }
}

/// condition ? if_true : if_false, as bit operations, for a condition that is the same for
/// every element of a loop (on t): g++ -O2 does not if-convert `?:` in a loop, and a branch
/// stops vectorisation. The mask is loop-invariant, so it is computed once, outside.
template <class R>
POINTMASS_HD constexpr R bit_select(bool condition, R if_true, R if_false) noexcept {
  if constexpr (std::is_same_v<R, float> || std::is_same_v<R, double>) {
    using B = typename ExpTraits<R>::bits;
    const B mask = B(0) - static_cast<B>(condition);
    return __builtin_bit_cast(R, static_cast<B>((__builtin_bit_cast(B, if_true) & mask) |
                                                (__builtin_bit_cast(B, if_false) & ~mask)));
  } else {
    return condition ? if_true : if_false;
  }
}

/// All ones where a < b, else zero, from sign bits alone (and where a = -0, b = +0: use
/// select_if_less where zeros of either sign meet). A per-element comparison made into a
/// mask does not vectorise at g++ -O2 for double (SSE2 has no pattern for a 64-bit mask from a
/// double comparison); a logical shift and a subtraction do. a - b and b - a are both
/// negative or both not only when one is NaN (which propagates its sign into both): false.
template <class R>
POINTMASS_HD constexpr typename ExpTraits<R>::bits less_mask(R a, R b) noexcept {
  using B = typename ExpTraits<R>::bits;
  constexpr int sign_shift = static_cast<int>(sizeof(B)) * 8 - 1;
  const B a_below = static_cast<B>(__builtin_bit_cast(B, a - b) >> sign_shift);
  const B b_below = static_cast<B>(__builtin_bit_cast(B, b - a) >> sign_shift);
  return static_cast<B>(B(0) - (a_below & (b_below ^ B(1))));
}

/// mask ? if_set : if_clear, bit by bit.
template <class R>
POINTMASS_HD constexpr R mask_select(typename ExpTraits<R>::bits mask, R if_set,
                                     R if_clear) noexcept {
  using B = typename ExpTraits<R>::bits;
  return __builtin_bit_cast(R, static_cast<B>((__builtin_bit_cast(B, if_set) & mask) |
                                              (__builtin_bit_cast(B, if_clear) & ~mask)));
}

/// a < b ? if_less : otherwise, per element without a branch (masks for float and double).
/// -0 and +0 compare equal, as with `<` (less_mask alone reads -0 - +0 = -0 as "less").
template <Real R>
POINTMASS_HD constexpr R select_if_less(R a, R b, R if_less, R otherwise) noexcept {
  if constexpr (wider_than_double_v<R>) {
    return a < b ? if_less : otherwise;
  } else {
    return mask_select(less_mask(a + R(0), b + R(0)), if_less, otherwise);  // -0 + 0 = +0
  }
}

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
  const double s = a + b;
  return {s, b - (s - a)};
}

/// a * b as p + e, to within 2^-104 |a b| (for products far from the subnormals): Dekker's
/// product over split_high's halves. The halves are cut by a bit mask, not by Veltkamp's
/// multiplication, which a compiler that contracts into fused multiply-adds would change;
/// every partial product but lo * lo (27 bits by 27) is exact, so contraction changes at
/// most that one's last bit.
POINTMASS_HD constexpr DoubleDouble two_product(double a, double b) noexcept {
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

/// The reduction of x = x_hi + x_lo: e^x = (1 + s) * scale1 * scale2, 2^n = scale1 * scale2.
template <class R>
struct ExpReduced {
  R s;
  R scale1;
  R scale2;
  R n;
};

/// 2^m for an integer-valued m in R's normal exponent range, from the bits of m + shifter.
template <class R>
POINTMASS_HD constexpr R power_of_two(R m) noexcept {
  using T = ExpTraits<R>;
  using B = typename T::bits;
  const B shifted = __builtin_bit_cast(B, m + T::shifter);  // low bits: m, two's complement
  return __builtin_bit_cast(R, static_cast<B>(static_cast<B>(shifted + B(T::exponent_bias))
                                              << (T::significand_bits - 1)));
}

template <class R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr ExpReduced<R> exp_reduce(R x_hi,
                                                                               R x_lo) noexcept {
  using T = ExpTraits<R>;
  // Clamp (NaN passes through); a clamped x drops its low part.
  using B = typename T::bits;
  const B below = less_mask(x_hi, T::x_min);
  const B above = less_mask(T::x_max, x_hi);
  const R x = mask_select(below, T::x_min, mask_select(above, T::x_max, x_hi));
  const R low = mask_select(static_cast<B>(below | above), R(0), x_lo);
  const R n = (x * T::inv_ln2 + T::shifter) - T::shifter;  // round(x / ln 2)
  const R r_hi = x - n * T::ln2_hi;                        // exact
  const R r_lo = low - n * T::ln2_lo;
  const R r = r_hi + r_lo;
  const R s = r_hi + (r_lo + (r * r) * exp_series(r));
  // n = m1 + m2, each within the normal exponents (|n| <= 1076 in double, 150 in float).
  const R m1 = (n * R(0.5) + T::shifter) - T::shifter;
  const R m2 = n - m1;
  return {s, power_of_two(m1), power_of_two(m2), n};
}

/// e^x from the reduction: one rounding in 1 + s, then exact scaling (or one rounding into
/// the subnormals).
template <class R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R exp_from(const ExpReduced<R>& e) noexcept {
  return ((R(1) + e.s) * e.scale1) * e.scale2;
}

/// e^x - 1 from the reduction: (2^n - 1) + 2^n s while 2^n - 1 is exact, else e^x - 1.
template <class R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R expm1_from(
    const ExpReduced<R>& e) noexcept {
  const R two_n = e.scale1 * e.scale2;
  const R near = (two_n - R(1)) + two_n * e.s;
  return mask_select(less_mask(ExpTraits<R>::expm1_exact_scale, e.n), exp_from(e) - R(1), near);
}

/// e^x (MinusOne false) or e^x - 1 (MinusOne true) in R: one reduction, then exp_from or
/// expm1_from, branch-free and constexpr for float and double; expl / expm1l for long double.
template <bool MinusOne, Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R exp_or_expm1(R x) noexcept {
  if constexpr (wider_than_double_v<R>) {
    return MinusOne ? real_expm1(x) : real_exp(x);
  } else {
    const ExpReduced<R> e = exp_reduce(x, R(0));
    return MinusOne ? expm1_from(e) : exp_from(e);
  }
}

/// e^x in R.
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R exp(R x) noexcept {
  return exp_or_expm1<false>(x);
}

/// e^x - 1 in R, accurate near x = 0.
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R expm1(R x) noexcept {
  return exp_or_expm1<true>(x);
}

/// A step length split like split_log's hi: t = hi + lo, hi of half the significand (or t
/// itself when that would be 0: t below 2^-114 in float, where e^(t ln d) rounds to 1 anyway).
/// The same for every particle of a step, so a loop computes it once.
template <class R>
struct SplitTime {
  R hi;
  R lo;
};
template <class R>
POINTMASS_HD constexpr SplitTime<R> split_time(R t) noexcept {
  const R hi = split_high(t);
  return {bit_select(real_equal(hi, R(0)), t, hi), bit_select(real_equal(hi, R(0)), R(0), t - hi)};
}

/// d^t and d^t - 1, and x = t ln d rounded to R, from one evaluation.
template <class R>
struct UnitPower {
  R kept;            ///< d^t
  R kept_minus_one;  ///< d^t - 1
  R exponent;        ///< t ln d, rounded (0 for t = 0; for d = 0, t times split_log's ln 0)
};

/// d^t and d^t - 1 for d in [0, 1] (ln d from split_log) and t >= 0. Exactly 1 and 0 for
/// t = 0 (even d = 0) and for d = 1; exactly 0 and -1 for d = 0 and t >= 2^-89 s. Raises no
/// floating-point exception but inexact and underflow.
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr UnitPower<R> exp_unit(const SplitLog<R>& ln_d,
                                                                            R t) noexcept {
  const bool none_taken = real_equal(t, R(0));
  if constexpr (wider_than_double_v<R>) {
    const bool all_taken = real_equal(ln_d.hi, -real_infinity<R>) && !none_taken;
    const R x = none_taken ? R(0) : (all_taken ? -real_infinity<R> : t * ln_d.hi);
    const R kept_minus_one = real_expm1(x);
    return {kept_minus_one + R(1), kept_minus_one, x};
  } else {
    // d = 0 needs no case of its own: x_hi = t ln 0 is below x_min, so clamped.
    const SplitTime<R> split = split_time(t);
    const R x_hi = split.hi * ln_d.hi;
    const R x_lo = split.lo * ln_d.hi + t * ln_d.lo;
    const ExpReduced<R> e = exp_reduce(x_hi, x_lo);
    const R x = x_hi + x_lo;
    return {bit_select(none_taken, R(1), exp_from(e)), bit_select(none_taken, R(0), expm1_from(e)),
            bit_select(none_taken, R(0), x)};
  }
}

/// d^t = e^(t ln d) for d in [0, 1] (ln d from split_log, computed once) and t >= 0.
/// Exactly 1 for t = 0 (even d = 0) and for d = 1; exactly 0 for d = 0 and t >= 2^-89 s
/// (float; double 2^-950 s). Raises no floating-point exception but inexact and underflow.
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R pow_unit(const SplitLog<R>& ln_d,
                                                                 R t) noexcept {
  const bool none_taken = real_equal(t, R(0));
  if constexpr (wider_than_double_v<R>) {
    const bool all_taken = real_equal(ln_d.hi, -real_infinity<R>);
    return none_taken ? R(1) : (all_taken ? R(0) : real_exp(t * ln_d.hi));
  } else {
    const SplitTime<R> split = split_time(t);
    const R kept = exp_from(exp_reduce(split.hi * ln_d.hi, split.lo * ln_d.hi + t * ln_d.lo));
    return bit_select(none_taken, R(1), kept);
  }
}

/// pow_unit for one value at a time, the same bits (a Particle, against a batch's pow_unit):
/// where e^x is a normal number (x_hi in [normal_x_min, normal_x_max], every damping and
/// step a game uses) it needs no clamp and one scale factor, since ((1 + s) 2^m1) 2^m2 and
/// (1 + s) 2^n are then the same exact scaling; elsewhere, and for t = 0, it is pow_unit.
/// The branch is what a batch's vectorised loop cannot have and a scalar loop predicts (it
/// goes the same way particle after particle), so a Particle's step skips the selects.
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R pow_unit_scalar(const SplitLog<R>& ln_d,
                                                                        R t) noexcept {
  if constexpr (wider_than_double_v<R>) {
    return pow_unit(ln_d, t);
  } else {
    using T = ExpTraits<R>;
    // split_time(t) as branches (the same values).
    const R high = split_high(t);
    const bool high_is_zero = real_equal(high, R(0));
    const R t_hi = high_is_zero ? t : high;
    const R t_lo = high_is_zero ? R(0) : t - high;
    const R x_hi = t_hi * ln_d.hi;
    if (!(x_hi >= T::normal_x_min && x_hi <= T::normal_x_max) || real_equal(t, R(0))) {
      return pow_unit(ln_d, t);
    }
    // exp_reduce and exp_from without the clamp, term for term.
    const R x_lo = t_lo * ln_d.hi + t * ln_d.lo;
    const R n = (x_hi * T::inv_ln2 + T::shifter) - T::shifter;
    const R r_hi = x_hi - n * T::ln2_hi;
    const R r_lo = x_lo - n * T::ln2_lo;
    const R r = r_hi + r_lo;
    const R s = r_hi + (r_lo + (r * r) * exp_series(r));
    return (R(1) + s) * power_of_two(n);
  }
}

/// How many terms of the phi series reach a precision of `digits` bits for |x| < 1: the
/// fewest n for which the first omitted term of phi_1, 1 / (n + 1)!, is below 2^-(digits + 2),
/// a quarter of an ulp of 1 (24 digits: 11, 53: 18, 64: 21, 113: 31).
constexpr int phi_terms_for(int digits) noexcept {
  double limit = 0.25;
  for (int i = 0; i < digits; ++i) limit /= 2;
  double term = 1;  // 1 / (n + 1)! at n = 0
  int n = 0;
  while (!(term < limit)) {
    ++n;
    term /= n + 1;
  }
  return n;
}
template <class R>
inline constexpr int phi_terms = phi_terms_for(std::numeric_limits<R>::digits);

/// 1 / (n + Offset)! for n = 0 .. phi_terms<R> - 1 (a plain array: usable in device code).
template <class R>
struct PhiCoefficients {
  R value[phi_terms<R>];
};
template <int Offset, class R>
POINTMASS_HD constexpr PhiCoefficients<R> make_phi_coefficients() noexcept {
  PhiCoefficients<R> coefficients{};
  R factorial = R(1);
  for (int n = 2; n <= Offset; ++n) factorial *= R(n);
  for (int n = 0; n < phi_terms<R>; ++n) {
    coefficients.value[n] = R(1) / factorial;
    factorial *= R(n + Offset + 1);
  }
  return coefficients;
}

/// phi_Offset(x) = sum_{n>=0} x^n / (n + Offset)!, by Horner's rule, for |x| < 1, from
/// term N on. The coefficients are compile-time constants, so device code can read them; the
/// rule is straight-line code (a loop over the coefficients stays a loop at g++ -O2, which
/// then does not vectorise a batch's loop around it).
template <int Offset, class R, int N = 0>
POINTMASS_HD constexpr R phi_series(R x) noexcept {
  constexpr R coefficient = make_phi_coefficients<Offset, R>().value[N];
  if constexpr (N == phi_terms<R> - 1) {
    return coefficient;
  } else {
    return phi_series<Offset, R, N + 1>(x) * x + coefficient;
  }
}

}  // namespace pointmass::detail
