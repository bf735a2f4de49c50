// SPDX-License-Identifier: BSL-1.0
// The accuracy of detail/exponential.hpp's d^t = pow_unit(split_log(d), t) and of
// d^t - 1 = exp_unit(split_log(d), t).kept_minus_one, against an oracle that shares none of
// its code: __float128 (libquadmath's expq / expm1q / logq, 113-bit significand) where the
// compiler has it (g++ on x86-64), else long double (expl / expm1l / logl, 64-bit).
//
// For each precision and each domain it samples d (log-uniform, plus d just below 1 and the
// ends) and t (uniform, plus 1/30, 1/60, 1/120 and the ends) and prints, as a Markdown table,
// the largest distance in units in the last place between the result and the oracle rounded
// to R (the correctly rounded result, save for a tie within the oracle's own error), and
// where it occurs. Exits 1 when the bound the library states (4 ulp for d in [1e-3, 1] and
// t in [0, 1] s) is exceeded anywhere it sampled.
// Usage: pointmass_exponential_accuracy [samples per domain and precision]  (default 2000000)
#include <pointmass/detail/exponential.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>

#include "ulp.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <quadmath.h>
#define POINTMASS_ORACLE_QUAD 1
#else
#define POINTMASS_ORACLE_QUAD 0
#endif

namespace {

namespace detail = pointmass::detail;

#if POINTMASS_ORACLE_QUAD
using Oracle = __float128;
Oracle oracle_log(Oracle x) { return logq(x); }
Oracle oracle_exp(Oracle x) { return expq(x); }
Oracle oracle_expm1(Oracle x) { return expm1q(x); }
const char* const oracle_name = "__float128 (libquadmath)";
#else
using Oracle = long double;
Oracle oracle_log(Oracle x) { return logl(x); }
Oracle oracle_exp(Oracle x) { return expl(x); }
Oracle oracle_expm1(Oracle x) { return expm1l(x); }
const char* const oracle_name = "long double";
#endif

using pointmass::test::ulp_distance;

struct Worst {
  long long ulps = 0;
  double d = 1;
  double t = 0;
};

template <class R>
struct Result {
  Worst power;
  Worst minus_one;
};

template <class R>
Result<R> measure(double d_min, double t_max, long samples, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double log_min = std::log(d_min);
  const R steps[] = {R(0), R(1) / R(120), R(1) / R(60), R(1) / R(30), static_cast<R>(t_max)};
  Result<R> result;
  for (long i = 0; i < samples; ++i) {
    R d = static_cast<R>(std::exp(log_min * unit(engine)));
    if (i % 8 == 1) d = static_cast<R>(1.0 - unit(engine) * 1e-4);  // the usual: just below 1
    if (i % 8 == 2) d = static_cast<R>(1.0 - unit(engine) * 1e-7);
    if (i == 3) d = static_cast<R>(d_min);
    if (!(d > R(0))) d = std::numeric_limits<R>::denorm_min();
    R t = static_cast<R>(t_max * unit(engine));
    if (i % 16 == 5) t = steps[(i / 16) % 5];
    const auto ln_d = detail::split_log(d);
    const R power = detail::pow_unit(ln_d, t);
    const R minus_one = detail::exp_unit(ln_d, t).kept_minus_one;
    const Oracle x = static_cast<Oracle>(t) * oracle_log(static_cast<Oracle>(d));
    const auto power_ulps = ulp_distance(power, static_cast<R>(oracle_exp(x)));
    const auto minus_one_ulps = ulp_distance(minus_one, static_cast<R>(oracle_expm1(x)));
    if (power_ulps > result.power.ulps) result.power = {power_ulps, double(d), double(t)};
    if (minus_one_ulps > result.minus_one.ulps) {
      result.minus_one = {minus_one_ulps, double(d), double(t)};
    }
  }
  return result;
}

template <class R>
void row(const char* real, const char* domain, const Result<R>& r) {
  std::printf("| %s | %s | %lld (d = %.9g, t = %.9g) | %lld (d = %.9g, t = %.9g) |\n", real, domain,
              r.power.ulps, r.power.d, r.power.t, r.minus_one.ulps, r.minus_one.d, r.minus_one.t);
}

}  // namespace

int main(int argc, char** argv) {
  const long samples = argc > 1 ? std::atol(argv[1]) : 2000000;
  std::printf("Oracle: %s; %ld samples per row.\n\n", oracle_name, samples);
  std::printf("| real | domain | d^t: worst ulps (where) | d^t - 1: worst ulps (where) |\n");
  std::printf("|---|---|---|---|\n");
  const auto float_stated = measure<float>(1e-3, 1.0, samples, 1);
  const auto double_stated = measure<double>(1e-3, 1.0, samples, 2);
  row("float", "d in [1e-3, 1], t in [0, 1] s", float_stated);
  row("double", "d in [1e-3, 1], t in [0, 1] s", double_stated);
  row("float", "d in (0, 1], t in [0, 10] s",
      measure<float>(double(std::numeric_limits<float>::denorm_min()), 10.0, samples, 3));
  row("double", "d in (0, 1], t in [0, 10] s",
      measure<double>(std::numeric_limits<double>::denorm_min(), 10.0, samples, 4));
  const long long stated = 4;
  const bool within = float_stated.power.ulps <= stated && float_stated.minus_one.ulps <= stated &&
                      double_stated.power.ulps <= stated && double_stated.minus_one.ulps <= stated;
  std::printf("\n%s: at most %lld ulp for d in [1e-3, 1], t in [0, 1] s\n",
              within ? "within the stated bound" : "EXCEEDS the stated bound", stated);
  return within ? 0 : 1;
}
