// SPDX-License-Identifier: BSL-1.0
// The cost of Boost.Units: the same scene through the plain particle and the SI particle, in
// one run, and the ratio of their median times (1.00 = free).
//
// The scene: 1024 particles launched with the four ballistic shots in turn, each given a push
// (add_force) and integrated for 150 frames of 1/30 s; the launch is timed too (it is a
// small part, and it crosses the quantity boundary as well). The SI particle stores raw numbers and
// takes and returns quantities; the comparison shows whether that boundary costs anything.
//
//   build/<dir>/benchmarks/units_cost --benchmark_repetitions=15
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
// prints, after Google Benchmark's table, one line per configuration:
//   ratio SI/plain <configuration>: <median SI CPU time / median plain CPU time>
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <pointmass/extras/scenes.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/units.hpp>

#include "support/bench_support.hpp"
#include "units_scene.hpp"

namespace pm = pointmass;
namespace si = boost::units::si;

namespace {

template <class Particle, class R>
void run_scene(benchmark::State& state, const auto& frame, const auto& push) {
  std::vector<Particle> particles(pm::test::units_scene_particles);
  for (auto _ : state) {
    pm::test::launch_units_scene(particles);
    pm::test::fly_units_scene(particles, frame, push);
    benchmark::DoNotOptimize(particles.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(pm::test::units_scene_particles) *
                          pm::test::units_scene_frames);
}

template <class R, class D, class P>
void plain(benchmark::State& state) {
  run_scene<pm::Particle<R, D, P>, R>(state, R(1) / R(30), pm::Vector3<R>{R(0.5), R(-2), R(1)});
}
template <class R, class D, class P>
void with_units(benchmark::State& state) {
  run_scene<pm::units::Particle<R, D, P>, R>(state, (R(1) / R(30)) * si::seconds,
                                             pm::Vector3<R>{R(0.5), R(-2), R(1)} * si::newtons);
}

using pm::damping::Exact;
using pm::damping::None;
using pm::damping::PerSecond;
using pm::position::ConstantAcceleration;
using pm::position::Euler;

#define POINTMASS_PAIR(name, ...)                                                             \
  BENCHMARK_TEMPLATE(plain, __VA_ARGS__)->Name("plain/" name)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_TEMPLATE(with_units, __VA_ARGS__)->Name("si/" name)->Unit(benchmark::kMicrosecond)

POINTMASS_PAIR("float PerSecond Euler", float, PerSecond, Euler);
POINTMASS_PAIR("double PerSecond Euler", double, PerSecond, Euler);
POINTMASS_PAIR("float None ConstantAcceleration", float, None, ConstantAcceleration);
POINTMASS_PAIR("double Exact Exact", double, Exact, pm::position::Exact);

/// The console table as usual, plus the SI/plain ratio of each configuration's median CPU
/// time (or of its single run, without repetitions).
class RatioReporter : public pointmass_benchmarks::MedianReporter {
 public:
  void Finalize() override {
    MedianReporter::Finalize();
    for (const auto& [name, time] : times()) {
      if (name.rfind("plain/", 0) != 0) continue;
      const std::string configuration = name.substr(6);
      const auto si_time = times().find("si/" + configuration);
      if (si_time == times().end()) continue;
      std::printf("ratio SI/plain %-24s %.3f\n", (configuration + ":").c_str(),
                  si_time->second / time);
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
