// SPDX-License-Identifier: BSL-1.0
// What setting a damping value costs with PerSecond and Exact: damping::LogDamping<R>(d),
// which stores d and ln d as hi + lo (detail::split_log, the library's own logarithm), beside
// the C library's log and logl, in the same run. It is paid once per value set
// (Particle::set_damping, ParticleSystem::set_damping(i, d)), not per step.
//
//   build/<dir>/benchmarks/damping_set --benchmark_repetitions=9
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
// prints, after Google Benchmark's table, a Markdown table: each precision's median CPU time,
// its baseline's and their ratio (scripts/benchmark-damping-set.sh writes it into
// docs/results/numerics.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <pointmass/damping.hpp>

#include "support/bench_support.hpp"

namespace {

/// 1,024 damping values spread over [1e-3, 1), most of them near 1, as games set them.
template <class R>
const std::vector<R>& damping_values() {
  static const std::vector<R> values = [] {
    std::vector<R> out;
    for (int i = 0; i < 1024; ++i) {
      const double d = i % 2 ? 1.0 - 1e-3 * (i % 97 + 1) : std::pow(1e-3, (i % 101) / 101.0);
      out.push_back(static_cast<R>(d));
    }
    return out;
  }();
  return values;
}

template <class R>
void set_damping(benchmark::State& state) {
  const std::vector<R>& values = damping_values<R>();
  std::size_t i = 0;
  for (auto _ : state) {
    pointmass::damping::LogDamping<R> damping(values[i++ & 1023]);
    benchmark::DoNotOptimize(damping);
  }
}

template <class Wide, class R>
void c_library_log(benchmark::State& state) {
  const std::vector<R>& values = damping_values<R>();
  std::size_t i = 0;
  for (auto _ : state) {
    Wide ln_d = std::log(static_cast<Wide>(values[i++ & 1023]));
    benchmark::DoNotOptimize(ln_d);
  }
}

BENCHMARK(set_damping<float>)->Name("LogDamping<float>");
BENCHMARK(c_library_log<double, float>)->Name("log(double) of a float");
BENCHMARK(set_damping<double>)->Name("LogDamping<double>");
BENCHMARK(c_library_log<long double, double>)->Name("logl of a double");

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  pointmass_benchmarks::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  // The table docs/results/numerics.md shows (scripts/benchmark-damping-set.sh writes it there).
  const auto row = [&](const char* name, const char* set, const char* baseline,
                       const char* baseline_label) {
    const auto a = reporter.times().find(name);
    const auto b = reporter.times().find(baseline);
    if (a == reporter.times().end() || b == reporter.times().end() || !(b->second > 0)) return;
    std::printf("| `%s` | %.1f ns | %s: %.1f ns | %.2f |\n", set, a->second, baseline_label,
                b->second, a->second / b->second);
  };
  std::printf("| set | median | the C library's log in the same precision | ratio |\n");
  std::printf("|---|---|---|---|\n");
  row("LogDamping<float>", "damping::LogDamping<float>(d)", "log(double) of a float",
      "`log` of the float as a double");
  row("LogDamping<double>", "damping::LogDamping<double>(d)", "logl of a double",
      "`logl` of the double (x87's 80 bits)");
  benchmark::Shutdown();
  return 0;
}
