// SPDX-License-Identifier: BSL-1.0
// A ParticleSystem's step on Kokkos (pointmass/kokkos.hpp) against, in the same run: the
// library's own steps (ParticleSystem::step on one thread, pointmass::step(par_unseq, ...) on
// TBB's threads) and the read-modify-write bandwidth of the same six arrays on one and on two
// threads (the memory bound of a step). Kokkos rows for each host backend this Kokkos has:
// Serial always, OpenMP (2 threads) where it was built with it.
// scripts/benchmark-kokkos.sh runs it and writes docs/performance.md's Kokkos table.
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

namespace {

using namespace pointmass;

// 1/60 s, from outside every timed loop (set in main), so the compiler cannot fold it.
float float_duration = 0.0f;
double double_duration = 0.0;
template <class R>
R duration() {
  if constexpr (sizeof(R) == sizeof(float)) return float_duration;
  else return double_duration;
}

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

// Six arrays in one block, each offset by k x 448 bytes within its page (as the system's).
template <class R>
struct StaggeredArrays {
  explicit StaggeredArrays(std::size_t n) {
    const std::size_t span = (n * sizeof(R) + 4095) / 4096 * 4096 + 448;
    block = static_cast<std::byte*>(::operator new(6 * span, std::align_val_t{64}));
    for (std::size_t k = 0; k < 6; ++k) {
      array[k] = reinterpret_cast<R*>(block + k * span);
      std::fill(array[k], array[k] + n, R(1));
    }
  }
  ~StaggeredArrays() { ::operator delete(block, std::align_val_t{64}); }
  StaggeredArrays(const StaggeredArrays&) = delete;
  StaggeredArrays& operator=(const StaggeredArrays&) = delete;
  std::byte* block = nullptr;
  R* array[6] = {};
};

// Read-modify-write of six arrays: the memory bound of a step of six arrays.
template <class R>
void rmw(R* __restrict a0, R* __restrict a1, R* __restrict a2, R* __restrict a3,
         R* __restrict a4, R* __restrict a5, std::size_t n, R c) {
  for (std::size_t i = 0; i < n; ++i) {
    a0[i] += c, a1[i] += c, a2[i] += c, a3[i] += c, a4[i] += c, a5[i] += c;
  }
}

template <class R>
void BM_Bandwidth(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  StaggeredArrays<R> arrays(n);
  R** a = arrays.array;
  for (auto _ : state) {
    rmw(a[0], a[1], a[2], a[3], a[4], a[5], n, duration<R>());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class R>
void BM_BandwidthParallel(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  StaggeredArrays<R> arrays(n);
  R** a = arrays.array;
  constexpr std::size_t chunk = 16384;
  const std::size_t chunks = (n + chunk - 1) / chunk;
  for (auto _ : state) {
    const R c = duration<R>();
    std::for_each(std::execution::par_unseq, detail::CountingIterator(0),
                  detail::CountingIterator(chunks), [&](std::size_t k) {
                    const std::size_t begin = k * chunk;
                    const std::size_t end = std::min(begin + chunk, n);
                    rmw(a[0] + begin, a[1] + begin, a[2] + begin, a[3] + begin, a[4] + begin,
                        a[5] + begin, end - begin, c);
                  });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
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
  float_duration = 1.0f / (60.0f * static_cast<float>(argc > 0 ? 1 : 2));
  double_duration = 1.0 / (60.0 * (argc > 0 ? 1 : 2));
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
    std::vector<char*> arguments(argv, argv + argc);
    char smoke_filter[] = "--benchmark_filter=/100000/";
    if (std::getenv("POINTMASS_BENCHMARK_SMOKE") != nullptr) arguments.push_back(smoke_filter);
    int count = static_cast<int>(arguments.size());
    benchmark::Initialize(&count, arguments.data());
    if (benchmark::ReportUnrecognizedArguments(count, arguments.data())) {
      result = 1;
    } else {
      benchmark::RunSpecifiedBenchmarks();
      benchmark::Shutdown();
    }
  }
  Kokkos::finalize();
  return result;
}
