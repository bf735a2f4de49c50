// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/exponential.hpp — the library's own exponential: e^x, e^x - 1 and d^t.
//
//   detail::exp(x), detail::expm1(x)     e^x and e^x - 1 in the precision of x
//   detail::pow_unit(split_log(d), t)    d^t = e^(t ln d) for d in [0, 1], t >= 0 (split_log:
//                                        ln d as hi + lo, detail/logarithm.hpp)
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
// It relies on IEEE arithmetic rounding to nearest, in the order written (under
// -fassociative-math: POINTMASS_DETAIL_IN_ORDER, config.hpp) and unfused: contracted (g++
// without -ffp-contract=off), the steps are more accurate but no longer the same bits.
//
// Owns: the library's own exponential and d^t, the branch-free selects, and the phi series.
// Must not include: anything but config.hpp, real.hpp and detail/logarithm.hpp (the policies
// build on it).
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../real.hpp"
#include "logarithm.hpp"

// These functions are inlined into the caller's loop at any optimisation level
// (POINTMASS_DETAIL_ALWAYS_INLINE): clang and g++ would otherwise call the larger of them
// (exp_unit) from a loop, and a call stops vectorisation.

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

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

/// condition ? if_true : if_false, as bit operations (g++ -O2 does not if-convert `?:` in the
/// batch's step loop).
template <class T>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr T select_if(bool condition, T if_true,
                                                                  T if_false) noexcept {
  if constexpr (sizeof(T) == 4 || sizeof(T) == 8) {
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const Bits mask = Bits(0) - static_cast<Bits>(condition);
    return __builtin_bit_cast(T, static_cast<Bits>((__builtin_bit_cast(Bits, if_true) & mask) |
                                                   (__builtin_bit_cast(Bits, if_false) & ~mask)));
  } else {
    return condition ? if_true : if_false;
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
  POINTMASS_DETAIL_IN_ORDER  // every step below is error-free only in this order
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
    POINTMASS_DETAIL_IN_ORDER  // exp_reduce's steps, error-free only in this order
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
POINTMASS_DETAIL_UNFUSED_END
