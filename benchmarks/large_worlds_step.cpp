// SPDX-License-Identifier: BSL-1.0
// The cost of wide positions (precision.hpp) side by side with all-float, in the same run:
// ParticleSystem::step of the default sparks (per-second damping, p + v t, gravity) with
// positions stored as float (6 arrays, 24 bytes per particle), as double (36 bytes) and as a
// compensated float pair (9 arrays, 36 bytes), at 1,000, 100,000 and 10,000,000 particles;
// and the same for the artillery configuration (damping::Exact, position::Exact).
// scripts/large-worlds.sh runs it and writes the ratios into docs/large-worlds.md.
// Counters: items_per_second = particle-steps per second.
#include <pointmass/particle_system.hpp>

#include <pointmass/gravity.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "support/bench_support.hpp"

namespace {

using namespace pointmass;
using namespace pointmass_benchmarks;

template <class System>
System make_system(std::size_t count) {
  System system(count);
  std::mt19937 engine(1);
  std::uniform_real_distribution<double> position(-100.0, 100.0);
  std::uniform_real_distribution<float> velocity(-10.0f, 10.0f);
  for (std::size_t i = 0; i < count; ++i) {
    // Far from the origin, where the wide positions matter (the cost does not depend on it).
    using Value = typename System::position_value;
    system.spawn({static_cast<Value>(1e6 + position(engine)), static_cast<Value>(position(engine)),
                  static_cast<Value>(position(engine))},
                 {velocity(engine), velocity(engine), velocity(engine)});
  }
  system.set_acceleration(gravity<float>());
  system.set_damping(0.9f);
  return system;
}

template <class System>
void BM_Step(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  System system = make_system<System>(count);
  for (auto _ : state) {
    system.step(duration<float>());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
  state.counters["bytes_per_particle"] = static_cast<double>(System::storage_bytes_per_particle);
}

using FloatSparks = ParticleSystem<float>;
using DoubleSparks = ParticleSystem<Precision<float, double>>;
using CompensatedSparks = ParticleSystem<Precision<float, Compensated<float>>>;
using FloatShots = ParticleSystem<float, damping::Exact, position::Exact>;
using DoubleShots = ParticleSystem<Precision<float, double>, damping::Exact, position::Exact>;
using CompensatedShots =
    ParticleSystem<Precision<float, Compensated<float>>, damping::Exact, position::Exact>;

#define POINTMASS_LARGE_WORLDS_BENCHMARK(System) \
  BENCHMARK_TEMPLATE(BM_Step, System)->Arg(1000)->Arg(100000)->Arg(10000000)

POINTMASS_LARGE_WORLDS_BENCHMARK(FloatSparks);
POINTMASS_LARGE_WORLDS_BENCHMARK(DoubleSparks);
POINTMASS_LARGE_WORLDS_BENCHMARK(CompensatedSparks);
POINTMASS_LARGE_WORLDS_BENCHMARK(FloatShots);
POINTMASS_LARGE_WORLDS_BENCHMARK(DoubleShots);
POINTMASS_LARGE_WORLDS_BENCHMARK(CompensatedShots);

}  // namespace

int main(int argc, char** argv) {
  set_duration(argc);
  // A step must move the particles (else the timed loops could be doing nothing).
  auto probe = make_system<CompensatedSparks>(4);
  const auto before = probe.position(0);
  probe.step(duration<float>());
  if (!(probe.position(0).x != before.x)) {
    std::fputs("large_worlds_step: a step did not move the particles\n", stderr);
    return EXIT_FAILURE;
  }
  return run_benchmarks(argc, argv);
}
