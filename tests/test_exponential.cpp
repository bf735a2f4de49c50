// SPDX-License-Identifier: BSL-1.0
// detail/exponential.hpp: d^t, d^t - 1, e^x and e^x - 1 against long double's expl, expm1l
// and logl (an oracle that shares no code with them; 11 more bits than double), the exact
// values at the ends, and use in constant expressions.
// (tests/reference/exponential_accuracy.cpp measures the worst cases against __float128.)
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include <pointmass/detail/exponential.hpp>

#include "log_oracle.hpp"
#include "ulp.hpp"

namespace {

namespace detail = pointmass::detail;

using pointmass::test::ulp_distance;

// The bound the library states (docs/numerics.md), for d in [1e-3, 1] and t in [0, 1] s.
constexpr long long stated_ulps = 4;

/// The bits the split high parts may have: half of R's significand (exponential.hpp: 12 of
/// float's 24, 26 of double's 53).
template <class R>
constexpr int half_significand = std::numeric_limits<R>::digits / 2;

/// The significant bits of a finite x: the fewest k such that x is an integer below 2^k times
/// a power of 2 (0 for 0). Counted by doubling the fraction of frexp: each step is exact.
template <class R>
int significant_bits(R x) {
  int exponent = 0;
  R fraction = std::frexp(std::fabs(x), &exponent);  // in [1/2, 1), or 0
  int bits = 0;
  while (fraction > R(0)) {
    fraction *= R(2);
    fraction -= std::floor(fraction);
    ++bits;
  }
  return bits;
}

// Usable in constant expressions, and exact where it must be.
static_assert(detail::exp(0.0f) == 1.0f && detail::exp(0.0) == 1.0);
static_assert(detail::expm1(0.0f) == 0.0f && detail::expm1(0.0) == 0.0);
static_assert(detail::exp(-1000.0) == 0.0 && detail::exp(-200.0f) == 0.0f);
static_assert(detail::expm1(-1000.0) == -1.0);
static_assert(detail::exp(2.0) > 7.389056098930649 && detail::exp(2.0) < 7.389056098930651);
static_assert(detail::pow_unit(detail::SplitLog<double>{}, 0.5) == 1.0);                 // d = 1
static_assert(detail::pow_unit(detail::SplitLog<float>{-0.6875f, 0.0f}, 0.0f) == 1.0f);  // t = 0
// (Overflow to infinity, and d = 0, where 0 * infinity is computed and then dropped, are not
// constant expressions: checked at run time below.)

}  // namespace

TEST_CASE_TEMPLATE(
    "d^t and d^t - 1 are within 4 ulp of long double's for d in [1e-3, 1], t in [0, 1] s", R, float,
    double) {
  if constexpr (!pointmass::wider_than_double_v<long double> && std::is_same_v<R, double>) {
    // Where long double is double (32-bit ARM) there is no wider oracle here: the oracle's own
    // t * log(d), rounded to double, errs by up to |x| / 2 ulp of d^t, more than the library's
    // (whose d^t is the same code and bits as on x86-64, where this case runs; its ln d is
    // checked on this platform against correctly rounded values below).
    MESSAGE("no oracle wider than double here: the double case runs where long double is wider");
    return;
  }
  long long worst_power = 0;
  long long worst_minus_one = 0;
  for (int i = 0; i <= 300; ++i) {
    // d log-spaced from 1e-3 to 1, and as many just below 1 (the usual damping values).
    const R d_far = static_cast<R>(std::pow(1e-3L, static_cast<long double>(i) / 300));
    const R d_near = static_cast<R>(1.0L - 1e-5L * static_cast<long double>(i));
    for (const R d : {d_far, d_near}) {
      const auto ln_d = detail::split_log(d);
      for (int j = 0; j <= 200; ++j) {
        const R t = static_cast<R>(static_cast<long double>(j) / 200 + 1e-3L * (j % 7));
        if (t > R(1)) continue;
        const long double x = static_cast<long double>(t) * std::log(static_cast<long double>(d));
        const long long power =
            ulp_distance(detail::pow_unit(ln_d, t), static_cast<R>(std::exp(x)));
        const long long minus_one =
            ulp_distance(detail::exp_unit(ln_d, t).kept_minus_one, static_cast<R>(std::expm1(x)));
        worst_power = power > worst_power ? power : worst_power;
        worst_minus_one = minus_one > worst_minus_one ? minus_one : worst_minus_one;
      }
    }
  }
  CAPTURE(worst_power);
  CAPTURE(worst_minus_one);
  CHECK(worst_power <= stated_ulps);
  CHECK(worst_minus_one <= stated_ulps);
}

TEST_CASE_TEMPLATE("d^t is exact at the ends: 0, 1, and t = 0", R, float, double, long double) {
  const auto zero = detail::split_log(R(0));
  const auto one = detail::split_log(R(1));
  // d = 0 gives 0 from t = 2^-89 s on (float; double 2^-950 s): a finite stand-in for ln 0.
  R shortest = R(0x1p-89);
  if constexpr (!std::is_same_v<R, float>) shortest = R(0x1p-950);
  for (const R t : {shortest, R(1e-25), R(1) / R(60), R(1), R(10), R(1e9)}) {
    CAPTURE(t);
    CHECK(detail::pow_unit(zero, t) == R(0));
    CHECK(detail::pow_unit(one, t) == R(1));
    const auto none = detail::exp_unit(zero, t);
    CHECK(none.kept == R(0));
    CHECK(none.kept_minus_one == R(-1));
    CHECK(none.exponent <= R(-104));
    const auto all = detail::exp_unit(one, t);
    CHECK(all.kept == R(1));
    CHECK(all.kept_minus_one == R(0));
    CHECK(all.exponent == R(0));
  }
  for (const R d : {R(0), std::numeric_limits<R>::denorm_min(), R(1e-3), R(0.5), R(1)}) {
    CAPTURE(d);
    const auto ln_d = detail::split_log(d);
    CHECK(detail::pow_unit(ln_d, R(0)) == R(1));
    CHECK(detail::exp_unit(ln_d, R(0)).kept == R(1));
    CHECK(detail::exp_unit(ln_d, R(0)).kept_minus_one == R(0));
    CHECK(detail::exp_unit(ln_d, R(0)).exponent == R(0));
  }
}

TEST_CASE_TEMPLATE("the split logarithm is ln d to half again the precision", R, float, double) {
  for (const R d : {R(1e-3), R(0.5), R(0.99), R(0.999999), std::numeric_limits<R>::min()}) {
    CAPTURE(d);
    const auto ln_d = detail::split_log(d);
    const long double exact = std::log(static_cast<long double>(d));
    const long double sum = static_cast<long double>(ln_d.hi) + static_cast<long double>(ln_d.lo);
    // hi has at most half the significand's bits (12 in float, 26 in double: exponential.hpp),
    // and so does a step length's high part split the same way: their product, x_hi, is then
    // exact (24 bits fit float's 24, 52 double's 53), which is what keeps x = t ln d free of
    // an error growing with |x|. Exact: the product's rounding error, which fma computes
    // exactly, is zero (the products here are far from the subnormals).
    CHECK(significant_bits(ln_d.hi) <= half_significand<R>);
    for (const R t : {R(1) / R(60), R(1) / R(30), R(0.1), R(1) / R(3), R(0.7), R(0.999)}) {
      CAPTURE(t);
      const R t_hi = detail::split_time(t).hi;
      CHECK(significant_bits(t_hi) <= half_significand<R>);
      const R x_hi = t_hi * ln_d.hi;
      CHECK(std::fma(t_hi, ln_d.hi, -x_hi) == R(0));
      CHECK(static_cast<long double>(t_hi) * static_cast<long double>(ln_d.hi) ==
            static_cast<long double>(x_hi));
    }
    // lo carries R's significand below hi's half: 1.5 significands in all (float 36 bits;
    // double 64, long double's). Checked to 10 bits beyond R's.
    CHECK(std::fabs(sum - exact) <=
          std::fabs(exact) * static_cast<long double>(std::numeric_limits<R>::epsilon()) / 1024);
  }
}

namespace {

using pointmass::test::LogOracle;

/// How far hi + lo is from the oracle's ln d, relative to ln d. The pairs agree in their
/// leading bits, so each difference is exact or errs by 2^-79 of ln d at most.
template <class R>
double relative_error(R hi, R lo, const LogOracle& oracle) {
  return std::fabs((static_cast<double>(hi) - oracle.hi) + (static_cast<double>(lo) - oracle.lo)) /
         std::fabs(oracle.hi);
}

/// split_log for double, or long double where it is double: hi of half the significand, and
/// hi + lo within 2^-72 of ln d (logarithm.hpp states about 2^-75; lo alone is rounded at
/// 2^-79). Every platform, whatever its long double and C library: the logarithm is the
/// library's own.
template <class R>
void check_double_split_log() {
  double worst = 0;
  for (const LogOracle& oracle : pointmass::test::log_oracle_double) {
    CAPTURE(oracle.d);
    const auto ln_d = detail::split_log(static_cast<R>(oracle.d));
    CHECK(significant_bits(ln_d.hi) <= half_significand<double>);
    const double error = relative_error(ln_d.hi, ln_d.lo, oracle);
    worst = error > worst ? error : worst;
    CHECK(error <= 0x1p-72);
  }
  MESSAGE("split_log's worst relative error over the table: ", worst);
}

}  // namespace

TEST_CASE(
    "split_log for double is ln d to 2^-72 against correctly rounded values, on every platform") {
  check_double_split_log<double>();
  if constexpr (!pointmass::wider_than_double_v<long double>) {
    check_double_split_log<long double>();  // long double is double here: the same path
  }
}

TEST_CASE(
    "split_log for float is ln d to 2^-35 against correctly rounded values, on every platform") {
  for (const LogOracle& oracle : pointmass::test::log_oracle_float) {
    CAPTURE(oracle.d);
    const auto ln_d = detail::split_log(static_cast<float>(oracle.d));
    CHECK(significant_bits(ln_d.hi) <= half_significand<float>);
    // hi's 12 bits and lo's 24: lo's rounding is below 2^-36 of ln d.
    CHECK(relative_error(ln_d.hi, ln_d.lo, oracle) <= 0x1p-35);
    // log_double itself, the double float's split is cut from: 2^-50 (it states 2^-51).
    CHECK(std::fabs(detail::log_double(oracle.d) - oracle.hi) <= std::fabs(oracle.hi) * 0x1p-50);
  }
}

TEST_CASE(
    "the library's logarithms over the whole double range: subnormals, both sides of sqrt(1/2), d "
    "near 1") {
  for (const LogOracle& oracle : pointmass::test::log_oracle_double) {
    CAPTURE(oracle.d);
    const detail::DoubleDouble wide = detail::log_double_double(oracle.d);
    CHECK(relative_error(wide.hi, wide.lo, oracle) <= 0x1p-72);
    CHECK(std::fabs(detail::log_double(oracle.d) - oracle.hi) <= std::fabs(oracle.hi) * 0x1p-50);
  }
  // Constant expressions too (every step is + - * / and bit casts).
  static_assert(detail::log_double_double(0.5).hi == -0x1.62e42fefa39efp-1);
  static_assert(detail::log_double_double(1.0).hi == 0.0 && detail::log_double(1.0) == 0.0);
}

TEST_CASE_TEMPLATE("e^x and e^x - 1 over the whole range: overflow, underflow, NaN", R, float,
                   double) {
  const R inf = std::numeric_limits<R>::infinity();
  const R nan = std::numeric_limits<R>::quiet_NaN();
  long long worst = 0;
  for (int i = -2000; i <= 2000; ++i) {
    const R x = static_cast<R>(i) * (sizeof(R) == 4 ? R(0.0437) : R(0.3547));
    CAPTURE(x);
    const long double lx = static_cast<long double>(x);
    const long long e = ulp_distance(detail::exp(x), static_cast<R>(std::exp(lx)));
    const long long m = ulp_distance(detail::expm1(x), static_cast<R>(std::expm1(lx)));
    worst = e > worst ? e : worst;
    worst = m > worst ? m : worst;
  }
  CAPTURE(worst);
  CHECK(worst <= stated_ulps);

  // The sweep above stops short of both ends of the finite results (|x| <= 87.4 in float,
  // 709.4 in double). The overflow edge: x across ln(largest finite) (float 88.72, double
  // 709.78) and the clamp x_max (89, 710), every result finite or infinite as the oracle's.
  // (ulp_distance puts infinity 1 from the largest finite value: the overflow is compared on
  // its own.)
  {
    const long double from = sizeof(R) == 4 ? 88.5L : 709.5L;
    long long worst_edge = 0;
    int finite_near_top = 0;  // oracle finite and above half the largest finite value
    int overflowed = 0;       // oracle infinite
    for (int i = 0; i <= 20000; ++i) {
      const R x = static_cast<R>(from + static_cast<long double>(i) / 20000);
      CAPTURE(x);
      const long double lx = static_cast<long double>(x);
      const R expected = static_cast<R>(std::exp(lx));
      const R expected_m1 = static_cast<R>(std::expm1(lx));
      const R actual = detail::exp(x);
      const R actual_m1 = detail::expm1(x);
      if (std::isinf(expected) != std::isinf(actual) ||
          std::isinf(expected_m1) != std::isinf(actual_m1)) {
        CHECK(std::isinf(actual) == std::isinf(expected));
        CHECK(std::isinf(actual_m1) == std::isinf(expected_m1));
      }
      const long long e = ulp_distance(actual, expected);
      const long long m = ulp_distance(actual_m1, expected_m1);
      worst_edge = e > worst_edge ? e : worst_edge;
      worst_edge = m > worst_edge ? m : worst_edge;
      overflowed += std::isinf(expected);
      finite_near_top += !std::isinf(expected) && expected > std::numeric_limits<R>::max() / 2;
    }
    CAPTURE(worst_edge);
    CHECK(worst_edge <= stated_ulps);
    CHECK(overflowed > 1000);
    CHECK(finite_near_top > 1000);
  }
  // The subnormal results: x from just above ln(smallest normal) (float -87.34, double
  // -708.40) to below ln(smallest subnormal / 2) (float -103.97, double -745.13), where e^x
  // rounds to 0. An ulp here is the smallest subnormal: the results round once (exp_from).
  {
    const long double from = sizeof(R) == 4 ? -104.0L : -745.2L;
    const long double to = sizeof(R) == 4 ? -87.0L : -708.0L;
    long long worst_band = 0;
    int subnormal = 0;  // oracle subnormal
    int zero = 0;       // oracle 0
    for (int i = 0; i <= 40000; ++i) {
      const R x = static_cast<R>(from + (to - from) * static_cast<long double>(i) / 40000);
      CAPTURE(x);
      const long double lx = static_cast<long double>(x);
      const R expected = static_cast<R>(std::exp(lx));
      const long long e = ulp_distance(detail::exp(x), expected);
      const long long m = ulp_distance(detail::expm1(x), static_cast<R>(std::expm1(lx)));
      worst_band = e > worst_band ? e : worst_band;
      worst_band = m > worst_band ? m : worst_band;
      subnormal += std::fpclassify(expected) == FP_SUBNORMAL;
      zero += std::fpclassify(expected) == FP_ZERO;
    }
    CAPTURE(worst_band);
    CHECK(worst_band <= 1);
    CHECK(subnormal > 30000);
    CHECK(zero > 50);
  }

  CHECK(detail::exp(inf) == inf);
  CHECK(detail::exp(-inf) == R(0));
  CHECK(detail::expm1(inf) == inf);
  CHECK(detail::expm1(-inf) == R(-1));
  CHECK(std::isnan(detail::exp(nan)));
  CHECK(std::isnan(detail::exp(-nan)));
  CHECK(std::isnan(detail::expm1(nan)));
  CHECK(std::isnan(detail::expm1(-nan)));
  // The smallest results round into the subnormals correctly.
  CHECK(detail::exp(static_cast<R>(std::log(static_cast<long double>(
            std::numeric_limits<R>::denorm_min())))) == std::numeric_limits<R>::denorm_min());
}

TEST_CASE_TEMPLATE("pow_unit_scalar, a Particle's d^t, is pow_unit bit for bit", R, float, double,
                   long double) {
  // Its branch on the range must change only the work, never a bit: over d from 0 to 1 and t
  // from 0 to 2000 s (results down into the subnormals and 0), and at the branch's edges.
  // The same value with the same sign (+0 and -0 differ), or both NaN. Not the bytes: long
  // double's padding bytes are no part of its value, and need not match.
  auto same = [](R a, R b) {
    return (!(a < b) && !(b < a) && !std::isnan(a) && std::signbit(a) == std::signbit(b)) ||
           (std::isnan(a) && std::isnan(b));
  };
  std::uint32_t state = 12345;
  auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<R>(state >> 8) / static_cast<R>(1u << 24);
  };
  int normal_below_one = 0;
  int subnormal_or_zero = 0;
  for (int i = 0; i < 200000; ++i) {
    const R d = i % 1000 == 0 ? R(0) : (i % 1000 == 1 ? R(1) : uniform());
    const R t = i % 3 == 0 ? uniform() : (i % 3 == 1 ? uniform() * R(2000) : uniform() / R(1e6));
    const auto ln_d = detail::split_log(d);
    const R expected = detail::pow_unit(ln_d, t);
    const R actual = detail::pow_unit_scalar(ln_d, t);
    if (!same(expected, actual)) {
      CAPTURE(d);
      CAPTURE(t);
      CHECK(same(actual, expected));  // bits: +0 and -0 differ
    }
    if (expected < std::numeric_limits<R>::min()) ++subnormal_or_zero;
    if (expected >= std::numeric_limits<R>::min() && expected < R(1)) ++normal_below_one;
  }
  // Both roads are taken many times (the branch exists for float and double): d^t a normal
  // number below 1 is the fast path's (but for x_hi within 1.4 of its lower edge, float;
  // 8.4, double), a subnormal or zero d^t the fallback's.
  CHECK(normal_below_one > 100000);
  if constexpr (!std::is_same_v<R, long double>) {
    CHECK(subnormal_or_zero > 1000);  // the fallback ran, not only the fast path
    // x_hi at the lower edge of the fast path (t ln d <= 0: the upper one is out of reach),
    // a few ulps either side.
    const R x = detail::ExpTraits<R>::normal_x_min;
    const auto ln_d = detail::split_log(std::exp(R(-1)));  // ln d about -1: t about -x
    for (int k = -4; k <= 4; ++k) {
      const R t = (x / ln_d.hi) * (R(1) + R(k) * std::numeric_limits<R>::epsilon());
      CAPTURE(t);
      CHECK(same(detail::pow_unit(ln_d, t), detail::pow_unit_scalar(ln_d, t)));
    }
  }
}
