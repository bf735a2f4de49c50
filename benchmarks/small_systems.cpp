// SPDX-License-Identifier: BSL-1.0
// Small systems at a fixed step: what keeping the uniform damping factors saves. A game has
// many small emitters (a muzzle flash, a spark shower, the dust of one impact): tens to hundreds
// of particles each, stepped at one fixed length. Then a step's own work, the exponential of
// d^t most of all, weighs as much as its particles do. `ParticleSystem::step` keeps the factors
// of the last step length (BM_Step); the same step with the factors computed afresh every time
// (BM_Afresh: begin_step, step_range over step_parameters of a system that never kept any,
// finish_step: the step as it was before the system kept them) runs in the same program.
// Sizes up to 512, where every storage's arrays fit 32 KiB and `step` walks forwards, as the
// loop of one's own does. scripts/benchmark-small-systems.sh runs it and writes the table of
// docs/results/small-systems.md.
#include <pointmass/particle_system.hpp>

#include <pointmass/gravity.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "support/bench_refresh.hpp"
#include "support/bench_support.hpp"

namespace {

using namespace pointmass;
using namespace pointmass_benchmarks;

template <class System>
System make_system(std::size_t count) {
  using R = typename System::real;
  using Value = typename System::position_value;
  System system(count);
  std::mt19937 engine(1);
  std::uniform_real_distribution<double> position(-100.0, 100.0);
  std::uniform_real_distribution<double> velocity(-10.0, 10.0);
  for (std::size_t i = 0; i < count; ++i) {
    system.spawn({static_cast<Value>(position(engine)), static_cast<Value>(position(engine)),
                  static_cast<Value>(position(engine))},
                 {static_cast<R>(velocity(engine)), static_cast<R>(velocity(engine)),
                  static_cast<R>(velocity(engine))});
  }
  system.set_acceleration(gravity<R>());
  system.set_damping(R(0.9));
  return system;
}

// The step as a loop of one's own takes it: the factors computed every time (step_parameters
// of a system whose step never kept any).
template <class System>
void step_afresh(System& system, typename System::real t) {
  if (auto view = system.begin_step(t)) {
    view.step_range(0, view.size());
    system.finish_step(std::move(view));
  }
}

// Afresh = false: system.step, which keeps the factors. True: step_afresh.
template <class System, bool Afresh>
void step_loop(benchmark::State& state) {
  using R = typename System::real;
  static_assert(!pointmass::detail::SystemAccess::Kernel<System>::alternates(512),
                "the loops compared walk forwards");
  const auto count = static_cast<std::size_t>(state.range(0));
  System system = make_system<System>(count);
  const SavedVelocities<System> start(system);
  const R t = duration<R>();
  std::int64_t steps = 0;
  for (auto _ : state) {
    if constexpr (Afresh) {
      step_afresh(system, t);
    } else {
      system.step(t);
    }
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] { start.restore(system); });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}
template <class System>
void BM_Step(benchmark::State& state) {
  step_loop<System, false>(state);
}
template <class System>
void BM_Afresh(benchmark::State& state) {
  step_loop<System, true>(state);
}

using FloatSparks = ParticleSystem<float>;
using DoubleSparks = ParticleSystem<double>;
using FarSparks = ParticleSystem<Precision<float, double>>;
using FloatShots = ParticleSystem<float, damping::Exact, position::Exact>;

void sizes(benchmark::internal::Benchmark* b) { b->Arg(16)->Arg(64)->Arg(256)->Arg(512); }

#define POINTMASS_SMALL_SYSTEMS(System)              \
  BENCHMARK_TEMPLATE(BM_Step, System)->Apply(sizes); \
  BENCHMARK_TEMPLATE(BM_Afresh, System)->Apply(sizes)
POINTMASS_SMALL_SYSTEMS(FloatSparks);
POINTMASS_SMALL_SYSTEMS(DoubleSparks);
POINTMASS_SMALL_SYSTEMS(FarSparks);
POINTMASS_SMALL_SYSTEMS(FloatShots);

// Both loops give the same particles, bit for bit (the kept factors are those computed).
template <class System>
bool same_steps() {
  using R = typename System::real;
  System kept = make_system<System>(37);
  System afresh = make_system<System>(37);
  for (int i = 0; i < 10; ++i) {
    kept.step(duration<R>());
    step_afresh(afresh, duration<R>());
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (!(kept.position(i) == afresh.position(i)) || !(kept.velocity(i) == afresh.velocity(i))) {
      return false;
    }
  }
  return !(kept.position(0) == make_system<System>(1).position(0));  // and they moved
}

}  // namespace

int main(int argc, char** argv) {
  set_duration(argc);
  if (!same_steps<FloatSparks>() || !same_steps<DoubleSparks>() || !same_steps<FarSparks>() ||
      !same_steps<FloatShots>()) {
    std::fputs("small_systems: the compared loops do not give the same particles\n", stderr);
    return EXIT_FAILURE;
  }
  return run_benchmarks(argc, argv);
}
