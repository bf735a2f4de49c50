// SPDX-License-Identifier: BSL-1.0
// The cost of wide positions (precision.hpp) side by side with all-float, in the same run:
// ParticleSystem::step of the default sparks (per-second damping, p + v t, gravity) with
// positions stored as float (6 arrays, 24 bytes per particle), as double (36 bytes) and as a
// compensated float pair (9 arrays, 36 bytes), at 1,000, 100,000 and 10,000,000 particles;
// and the same for the artillery configuration (damping::Exact, position::Exact). Beside them,
// the bound: the sparks' arithmetic written by hand over plain arrays with each of the three
// storages (float positions; double positions; float positions with float error terms), so
// that what wider positions cost the hardware itself is measured in the same run.
// scripts/large-worlds.sh runs it and writes the ratios into docs/large-worlds.md.
// Counters: items_per_second = particle-steps per second.
#include <pointmass/particle_system.hpp>

#include <pointmass/gravity.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <random>
#include <type_traits>

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

// How the hand-written loop stores a position component.
enum class Storage { float_positions, double_positions, compensated_positions };

// The sparks' step by hand (per-second damping with d^t once per step, p + v0 t, gravity):
// v1 = v0 d^t + a t and the displacement v0 t in float, added to a position stored as float,
// as double, or as a float pair with TwoSum (error terms e).
template <Storage S, class P>
void hand_sparks(P* __restrict px, P* __restrict py, P* __restrict pz, float* __restrict ex,
                 float* __restrict ey, float* __restrict ez, float* __restrict vx,
                 float* __restrict vy, float* __restrict vz, std::size_t n, float ax, float ay,
                 float az, float t, float kept) {
  const auto add = [](P& p, float* e, std::size_t i, float d) {
    if constexpr (S == Storage::compensated_positions) {
      const float y = d + e[i];
      const float s = p + y;
      const float b = s - p;
      e[i] = (p - (s - b)) + (y - b);
      p = s;
    } else {
      static_cast<void>(e);
      static_cast<void>(i);
      p = p + static_cast<P>(d);
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    const float x = vx[i], y = vy[i], z = vz[i];
    vx[i] = x * kept + ax * t;
    vy[i] = y * kept + ay * t;
    vz[i] = z * kept + az * t;
    add(px[i], ex, i, x * t);
    add(py[i], ey, i, y * t);
    add(pz[i], ez, i, z * t);
  }
}

template <Storage S>
void BM_HandSparks(benchmark::State& state) {
  using P = std::conditional_t<S == Storage::double_positions, double, float>;
  const auto n = static_cast<std::size_t>(state.range(0));
  // The columns in one aligned block, each offset by k x 448 bytes within its page (as a
  // system's, so that no two columns' loads and stores share their addresses' low bits).
  const std::size_t float_span = (n * sizeof(float) + 4095) / 4096 * 4096 + 448;
  const std::size_t position_span = (n * sizeof(P) + 4095) / 4096 * 4096 + 448;
  const std::size_t errors = S == Storage::compensated_positions ? 3 : 0;
  const std::size_t bytes = 3 * position_span + (3 + errors) * float_span;
  auto* block = static_cast<std::byte*>(::operator new(bytes, std::align_val_t{64}));
  P* p[3];
  float* v[3];
  float* e[3] = {nullptr, nullptr, nullptr};
  std::mt19937 engine(1);
  std::uniform_real_distribution<float> value(-10.0f, 10.0f);
  for (std::size_t k = 0; k < 3; ++k) {
    p[k] = reinterpret_cast<P*>(block + k * position_span);
    v[k] = reinterpret_cast<float*>(block + 3 * position_span + k * float_span);
    if (errors != 0) {
      e[k] = reinterpret_cast<float*>(block + 3 * position_span + (3 + k) * float_span);
    }
    for (std::size_t i = 0; i < n; ++i) {
      p[k][i] = static_cast<P>((k == 0 ? 1e6f : 0.0f) + 10.0f * value(engine));
      v[k][i] = value(engine);
      if (errors != 0) e[k][i] = 0.0f;
    }
  }
  const float t = duration<float>();
  const float kept = real_pow(0.9f, t);
  const Vector3<float> g = gravity<float>();
  for (auto _ : state) {
    hand_sparks<S>(p[0], p[1], p[2], e[0], e[1], e[2], v[0], v[1], v[2], n, g.x, g.y, g.z, t,
                   kept);
    benchmark::ClobberMemory();
  }
  ::operator delete(block, std::align_val_t{64});
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
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
BENCHMARK_TEMPLATE(BM_HandSparks, Storage::float_positions)->Arg(1000)->Arg(100000)->Arg(10000000);
BENCHMARK_TEMPLATE(BM_HandSparks, Storage::double_positions)->Arg(1000)->Arg(100000)->Arg(10000000);
BENCHMARK_TEMPLATE(BM_HandSparks, Storage::compensated_positions)
    ->Arg(1000)
    ->Arg(100000)
    ->Arg(10000000);

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
  // The smoke test (large_worlds_step.cmake sets POINTMASS_BENCHMARK_SMOKE) skips the 10^7
  // sizes, which take most of a minute to set up in a debug build.
  return run_benchmarks(argc, argv, "--benchmark_filter=/(1000|100000)$");
}
