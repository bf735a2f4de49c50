// SPDX-License-Identifier: BSL-1.0
// The cost of wide positions (precision.hpp) side by side with all-float, in the same run:
// ParticleSystem::step of the default sparks (per-second damping, p + v t, gravity) with
// positions stored as float (6 arrays, 24 bytes per particle), as double (36 bytes) and as a
// compensated float pair (9 arrays, 36 bytes), at 1,000, 100,000 and 10,000,000 particles;
// and the same for the artillery configuration (damping::Exact, position::Exact). Beside them,
// the bound: the sparks' arithmetic written by hand over plain arrays with each of the three
// storages (float positions; double positions; float positions with float error terms),
// walking forwards, and walking as the system of that storage does (BM_HandSparksLikeSystem:
// forwards and backwards in turn, within the system's size bounds), and
// the least any loop over each storage does (BM_Traffic: every byte loaded, one addition,
// stored back), so that what wider positions cost the hardware itself is measured in the
// same run.
// scripts/large-worlds.sh runs it and writes the ratios into docs/results/large-worlds.md.
// Counters: items_per_second = particle-steps per second.
#include <pointmass/particle_system.hpp>

#include <pointmass/gravity.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <random>
#include <type_traits>
#include <vector>

#include "support/bench_refresh.hpp"
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
  const SavedVelocities<System> start(system);
  std::int64_t steps = 0;
  for (auto _ : state) {
    system.step(duration<float>());
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] { start.restore(system); });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
  state.counters["bytes_per_particle"] = static_cast<double>(System::storage_bytes_per_particle);
}

// The systems of the sparks (per-second damping, p + v t) for each position storage.
using FloatSparks = ParticleSystem<float>;
using DoubleSparks = ParticleSystem<Precision<float, double>>;
using CompensatedSparks = ParticleSystem<Precision<float, Compensated<float>>>;

// How the hand-written loop stores a position component.
enum class Storage { float_positions, double_positions, compensated_positions };

// The sparks' step by hand (per-second damping with d^t once per step, p + v0 t, gravity):
// v1 = v0 d^t + a t and the displacement v0 t in float, added to a position stored as float,
// as double, or as a float pair with Fast2Sum (error terms e), as precision.hpp does.
template <Storage S, class P>
void hand_sparks(P* __restrict px, P* __restrict py, P* __restrict pz, float* __restrict ex,
                 float* __restrict ey, float* __restrict ez, float* __restrict vx,
                 float* __restrict vy, float* __restrict vz, std::size_t n, float ax, float ay,
                 float az, float t, float kept) {
  const auto add = [](P& p, float* e, std::size_t i, float d) {
    if constexpr (S == Storage::compensated_positions) {
      const float y = d + e[i];
      const float s = p + y;
      e[i] = y - (s - p);
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

/// The arrays a hand-written loop steps: positions of the storage's type, float velocities and
/// (compensated only) float error terms, in one aligned block, each column offset by k x 448
/// bytes within its page (as a system's, so that no two columns' loads and stores share their
/// addresses' low bits), filled as make_system fills a system.
template <Storage S>
struct HandArrays {
  using P = std::conditional_t<S == Storage::double_positions, double, float>;
  static constexpr std::size_t errors = S == Storage::compensated_positions ? 3 : 0;

  explicit HandArrays(std::size_t count) : n(count) {
    const std::size_t float_span = (n * sizeof(float) + 4095) / 4096 * 4096 + 448;
    const std::size_t position_span = (n * sizeof(P) + 4095) / 4096 * 4096 + 448;
    block = static_cast<std::byte*>(
        ::operator new (3 * position_span + (3 + errors) * float_span, std::align_val_t{64}));
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
  }
  HandArrays(const HandArrays&) = delete;
  HandArrays& operator=(const HandArrays&) = delete;
  ~HandArrays() { ::operator delete (block, std::align_val_t{64}); }

  std::size_t n;
  std::byte* block;
  P* p[3];
  float* v[3];
  float* e[3] = {nullptr, nullptr, nullptr};
};

// The system of each storage, whose walk a hand-written loop may follow.
template <Storage S>
using SparksOf = std::conditional_t<
    S == Storage::float_positions, FloatSparks,
    std::conditional_t<S == Storage::double_positions, DoubleSparks, CompensatedSparks>>;

// How a hand-written loop walks its arrays from one step to the next: always forwards, or as
// the storage's system does (forwards and backwards in turn within its size bounds, each
// backward walk in whole chunks from the end, each chunk forwards: detail/system_kernel.hpp).
enum class Walk { forwards, like_the_system };

template <Storage S, Walk W>
void hand_sparks_loop(benchmark::State& state) {
  HandArrays<S> a(static_cast<std::size_t>(state.range(0)));
  const float t = duration<float>();
  const float kept = real_pow(0.9f, t);
  const Vector3<float> g = gravity<float>();
  const std::vector<float> start_x(a.v[0], a.v[0] + a.n), start_y(a.v[1], a.v[1] + a.n),
      start_z(a.v[2], a.v[2] + a.n);  // the velocities, to put back
  const bool alternating = W == Walk::like_the_system &&
                           pointmass::detail::SystemAccess::Kernel<SparksOf<S>>::alternates(a.n);
  // The particles [begin, begin + count).
  const auto step = [&](std::size_t begin, std::size_t count) {
    const auto at = [begin](auto* column) { return column ? column + begin : column; };
    hand_sparks<S>(at(a.p[0]), at(a.p[1]), at(a.p[2]), at(a.e[0]), at(a.e[1]), at(a.e[2]),
                   at(a.v[0]), at(a.v[1]), at(a.v[2]), count, g.x, g.y, g.z, t, kept);
  };
  std::int64_t steps = 0;
  for (auto _ : state) {
    if (alternating && steps % 2 == 1) {
      constexpr std::size_t chunk =
          pointmass::detail::SystemAccess::Kernel<SparksOf<S>>::backward_chunk;
      std::size_t end = a.n - a.n % chunk;
      step(end, a.n - end);
      while (end != 0) {
        end -= chunk;
        step(end, chunk);
      }
    } else {
      step(0, a.n);
    }
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] {
      std::copy(start_x.begin(), start_x.end(), a.v[0]);
      std::copy(start_y.begin(), start_y.end(), a.v[1]);
      std::copy(start_z.begin(), start_z.end(), a.v[2]);
    });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(a.n));
}
template <Storage S>
void BM_HandSparks(benchmark::State& state) {
  hand_sparks_loop<S, Walk::forwards>(state);
}
template <Storage S>
void BM_HandSparksLikeSystem(benchmark::State& state) {
  hand_sparks_loop<S, Walk::like_the_system>(state);
}

// The least a step can do with the storage, in two forms over the same columns (every
// element the sparks' step changes: velocities, positions, and the pair's error terms):
//   Touch::add    loads each element, adds a constant and stores it back (BM_Traffic): what
//                 the bytes alone cost. Also a floor: a step loads every element it changes
//                 (the new value depends on the old one), computes with it at least once and
//                 stores it, so no step of a storage takes fewer instructions per element.
//   Touch::store  stores the constant, with nothing loaded (BM_Stores): the floor the bytes
//                 set in the L1 cache, since no step of a storage takes less time than storing
//                 its bytes.
enum class Touch { add, store };

template <Storage S, Touch T, class P>
void touch_columns(P* __restrict px, P* __restrict py, P* __restrict pz, float* __restrict ex,
                   float* __restrict ey, float* __restrict ez, float* __restrict vx,
                   float* __restrict vy, float* __restrict vz, std::size_t n, float c) {
  const auto touch = [c](auto& x) {
    using X = std::remove_reference_t<decltype(x)>;
    if constexpr (T == Touch::add) x += static_cast<X>(c);
    else x = static_cast<X>(c);
  };
  for (std::size_t i = 0; i < n; ++i) {
    touch(vx[i]);
    touch(vy[i]);
    touch(vz[i]);
    touch(px[i]);
    touch(py[i]);
    touch(pz[i]);
    if constexpr (S == Storage::compensated_positions) {
      touch(ex[i]);
      touch(ey[i]);
      touch(ez[i]);
    }
  }
}

template <Storage S, Touch T>
void touch_loop(benchmark::State& state) {
  HandArrays<S> a(static_cast<std::size_t>(state.range(0)));
  // Alternating signs keep the values where they started.
  float c = duration<float>();
  for (auto _ : state) {
    touch_columns<S, T>(a.p[0], a.p[1], a.p[2], a.e[0], a.e[1], a.e[2], a.v[0], a.v[1], a.v[2], a.n,
                        c);
    c = -c;
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(a.n));
}
template <Storage S>
void BM_Traffic(benchmark::State& state) {
  touch_loop<S, Touch::add>(state);
}
template <Storage S>
void BM_Stores(benchmark::State& state) {
  touch_loop<S, Touch::store>(state);
}

using FloatShots = ParticleSystem<float, damping::Exact, position::Exact>;
using DoubleShots = ParticleSystem<Precision<float, double>, damping::Exact, position::Exact>;
using CompensatedShots =
    ParticleSystem<Precision<float, Compensated<float>>, damping::Exact, position::Exact>;

// Each benchmark at the three sizes: 1,000 (in cache), 100,000 and 10,000,000.
#define POINTMASS_LARGE_WORLDS_BENCHMARK(...) \
  BENCHMARK_TEMPLATE(__VA_ARGS__)->Arg(1000)->Arg(100000)->Arg(10000000)

// REGISTER(benchmark, each of the sparks' systems) and REGISTER(benchmark, each storage).
#define POINTMASS_EACH_SPARKS(REGISTER, benchmark) \
  REGISTER(benchmark, FloatSparks);                \
  REGISTER(benchmark, DoubleSparks);               \
  REGISTER(benchmark, CompensatedSparks)
#define POINTMASS_EACH_STORAGE(REGISTER, benchmark) \
  REGISTER(benchmark, Storage::float_positions);    \
  REGISTER(benchmark, Storage::double_positions);   \
  REGISTER(benchmark, Storage::compensated_positions)

POINTMASS_EACH_SPARKS(POINTMASS_LARGE_WORLDS_BENCHMARK, BM_Step);
POINTMASS_LARGE_WORLDS_BENCHMARK(BM_Step, FloatShots);
POINTMASS_LARGE_WORLDS_BENCHMARK(BM_Step, DoubleShots);
POINTMASS_LARGE_WORLDS_BENCHMARK(BM_Step, CompensatedShots);
POINTMASS_EACH_STORAGE(POINTMASS_LARGE_WORLDS_BENCHMARK, BM_HandSparks);
POINTMASS_EACH_STORAGE(POINTMASS_LARGE_WORLDS_BENCHMARK, BM_HandSparksLikeSystem);
POINTMASS_EACH_STORAGE(POINTMASS_LARGE_WORLDS_BENCHMARK, BM_Traffic);
// In the L1 data cache of any current processor (500 particles: 12 KB of float, 18 KB wide):
// the sparks' step, the stores alone and the bytes alone (loaded, added to, stored back), for
// the floors that the bytes set there.
#define POINTMASS_IN_L1_BENCHMARK(...) BENCHMARK_TEMPLATE(__VA_ARGS__)->Arg(500)
POINTMASS_EACH_SPARKS(POINTMASS_IN_L1_BENCHMARK, BM_Step);
POINTMASS_EACH_STORAGE(POINTMASS_IN_L1_BENCHMARK, BM_Stores);
POINTMASS_EACH_STORAGE(POINTMASS_IN_L1_BENCHMARK, BM_Traffic);

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
  // The smoke test (benchmarks/CMakeLists.txt sets POINTMASS_BENCHMARK_SMOKE) skips the 10^7
  // sizes, which take most of a minute to set up in a debug build.
  return run_benchmarks(argc, argv, "--benchmark_filter=/(1000|100000)$");
}
