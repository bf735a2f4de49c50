// SPDX-License-Identifier: BSL-1.0
// What setting a damping value costs with PerSecond and Exact: damping::LogDamping<R>(d),
// which stores d and ln d as hi + lo (detail::split_log, the library's own logarithm), beside
// the C library's log and logl, in the same run. It is paid once per value set
// (Particle::set_damping, ParticleSystem::set_damping(i, d)), not per step.
//
//   build/<dir>/benchmarks/damping_set --benchmark_repetitions=9
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
// prints, after Google Benchmark's table, one line per precision:
//   ratio <name>/<baseline>: <median CPU time / the baseline's median>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <pointmass/damping.hpp>

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

/// Collects each run's median CPU time, to print the ratios after the table.
class Medians : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
        medians[run.run_name.function_name] = run.GetAdjustedCPUTime();
      }
    }
  }
  std::map<std::string, double> medians;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Medians reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const auto ratio = [&](const char* name, const char* baseline) {
    const auto a = reporter.medians.find(name);
    const auto b = reporter.medians.find(baseline);
    if (a != reporter.medians.end() && b != reporter.medians.end() && b->second > 0) {
      std::printf("ratio %s/%s: %.2f\n", name, baseline, a->second / b->second);
    }
  };
  ratio("LogDamping<float>", "log(double) of a float");
  ratio("LogDamping<double>", "logl of a double");
  benchmark::Shutdown();
  return 0;
}
