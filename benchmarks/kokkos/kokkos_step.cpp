// SPDX-License-Identifier: BSL-1.0
// A ParticleSystem's step on Kokkos (pointmass/kokkos.hpp) against, in the same run: the
// library's own steps (ParticleSystem::step on one thread, pointmass::step(par_unseq, ...) on
// TBB's threads) and the read-modify-write bandwidth of the same six arrays on one and on two
// threads (the memory bound of a step). Kokkos rows for each host backend this Kokkos has:
// Serial always, OpenMP (2 threads) where it was built with it.
// scripts/benchmark-kokkos.sh runs it and writes the table of docs/results/kokkos.md.
// Counters: items_per_second = particle-steps per second (real time: threads run).
#include <pointmass/kokkos.hpp>
#include <pointmass/parallel.hpp>

#include <pointmass/gravity.hpp>

#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <execution>
#include <new>
#include <random>
#include <vector>

#include "../support/bench_parallel.hpp"

namespace {

using namespace pointmass;
using namespace pointmass_benchmarks;

template <class R>
using Sparks = ParticleSystem<R>;

template <class R>
Sparks<R> make_sparks(std::size_t count) {
  Sparks<R> system(count);
  std::mt19937 engine(1);
  std::uniform_real_distribution<R> position(R(-100), R(100));
  std::uniform_real_distribution<R> velocity(R(-10), R(10));
  for (std::size_t i = 0; i < count; ++i) {
    system.spawn({position(engine), position(engine), position(engine)},
                 {velocity(engine), velocity(engine), velocity(engine)});
  }
  system.set_acceleration(gravity<R>());
  system.set_damping(R(0.9));
  return system;
}

// Per-second damping 0.9 keeps 0.9^(t / 1 s) of a velocity: a run of these benchmarks takes
// some thousands of steps of 1/60 s at most, far from float's subnormal range.

template <class R>
void BM_SystemStep(benchmark::State& state) {
  auto system = make_sparks<R>(static_cast<std::size_t>(state.range(0)));
  const R t = duration<R>();
  for (auto _ : state) {
    system.step(t);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class R>
void BM_SystemParallel(benchmark::State& state) {
  auto system = make_sparks<R>(static_cast<std::size_t>(state.range(0)));
  const R t = duration<R>();
  for (auto _ : state) {
    pointmass::step(std::execution::par_unseq, system, t);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class R, class Space>
void BM_Kokkos(benchmark::State& state) {
  const auto host = make_sparks<R>(static_cast<std::size_t>(state.range(0)));
  KokkosSystem<Sparks<R>, typename Space::memory_space> device(host);
  const R t = duration<R>();
  for (auto _ : state) {
    device.step(Space(), t);  // returns when the step is complete (fenced)
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Read-modify-write of the same six arrays on one and on two threads (values 1).
template <class R>
void BM_Bandwidth(benchmark::State& state) {
  StaggeredArrays<R> arrays(static_cast<std::size_t>(state.range(0)), R(1));
  bandwidth(state, arrays);
}

template <class R>
void BM_BandwidthParallel(benchmark::State& state) {
  StaggeredArrays<R> arrays(static_cast<std::size_t>(state.range(0)), R(1));
  bandwidth_parallel(state, arrays);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(10'000'000)->Arg(100'000)->UseRealTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK_TEMPLATE(BM_SystemStep, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_SystemStep, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_SystemParallel, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_SystemParallel, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Kokkos, float, Kokkos::Serial)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Kokkos, double, Kokkos::Serial)->Apply(sizes);
#if defined(KOKKOS_ENABLE_OPENMP)
BENCHMARK_TEMPLATE(BM_Kokkos, float, Kokkos::OpenMP)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Kokkos, double, Kokkos::OpenMP)->Apply(sizes);
#endif
BENCHMARK_TEMPLATE(BM_Bandwidth, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Bandwidth, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_BandwidthParallel, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_BandwidthParallel, double)->Apply(sizes);

// A Kokkos step moves the particles as ParticleSystem::step does (else the timings are void).
template <class R>
bool kokkos_step_moves_particles() {
  auto host = make_sparks<R>(32);
  KokkosSystem<Sparks<R>, Kokkos::HostSpace> device(host);
  device.step(Kokkos::Serial(), duration<R>());
  host.step(duration<R>());
  Sparks<R> back;
  device.copy_to(back);
  return duration<R>() > R(0) && back.position(31) == host.position(31) &&
         !(back.position(31) == make_sparks<R>(32).position(31));
}

}  // namespace

int main(int argc, char** argv) {
  set_duration(argc);
#if KOKKOS_VERSION >= 30700
  Kokkos::initialize(Kokkos::InitializationSettings().set_num_threads(2));
#else
  Kokkos::InitArguments kokkos_arguments;
  kokkos_arguments.num_threads = 2;
  Kokkos::initialize(kokkos_arguments);
#endif
  int result = 0;
  if (!kokkos_step_moves_particles<float>() || !kokkos_step_moves_particles<double>()) {
    std::fputs("kokkos_step: a Kokkos step did not move the particles as step does\n", stderr);
    result = 1;
  } else {
    // The smoke test (POINTMASS_BENCHMARK_SMOKE) runs the 100,000 sizes only.
    result = run_benchmarks(argc, argv, "--benchmark_filter=/100000/");
  }
  Kokkos::finalize();
  return result;
}
