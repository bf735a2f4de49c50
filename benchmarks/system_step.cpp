// SPDX-License-Identifier: BSL-1.0
// ParticleSystem::step against, in the same run: a hand-written loop of the same maths over
// plain staggered arrays (the speed of light for this step; once forwards every step, once
// with the system's alternating traversal), a read-modify-write bandwidth
// loop over as many bytes, and a loop of scalar Particles (one object per particle).
// scripts/benchmark-system.sh runs it and turns the medians into docs/results/system.md.
// Counters: items_per_second = particle-steps per second.
#include <pointmass/parallel.hpp>

#include <pointmass/denormals.hpp>
#include <pointmass/gravity.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <execution>
#include <limits>
#include <new>
#include <optional>
#include <random>
#include <span>
#include <type_traits>
#include <vector>

#include "support/bench_parallel.hpp"
#include "support/bench_refresh.hpp"

namespace {

using namespace pointmass;
using namespace pointmass_benchmarks;

template <class R>
Vector3<R> random_vector(std::mt19937& engine, R scale) {
  std::uniform_real_distribution<R> component(-scale, scale);
  return {component(engine), component(engine), component(engine)};
}

template <class System>
System make_system(std::size_t count) {
  System system(count);
  std::mt19937 engine(1);
  for (std::size_t i = 0; i < count; ++i) {
    system.spawn(random_vector(engine, typename System::real(100)),
                 random_vector(engine, typename System::real(10)));
  }
  if constexpr (!System::template has<pointmass::features::PerParticleAcceleration>) {
    system.set_acceleration(gravity<typename System::real>());
  }
  if constexpr (System::stores_damping &&
                !System::template has<pointmass::features::PerParticleDamping>) {
    system.set_damping(typename System::real(0.9));
  }
  if constexpr (System::template has<pointmass::features::PerParticleDamping>) {
    for (std::size_t i = 0; i < count; ++i) system.set_damping(i, typename System::real(0.9));
  }
  return system;
}

template <class System>
void BM_System(benchmark::State& state) {
  auto system = make_system<System>(static_cast<std::size_t>(state.range(0)));
  const SavedVelocities<System> start(system);
  const auto t = duration<typename System::real>();
  std::int64_t steps = 0;
  for (auto _ : state) {
    system.step(t);
    benchmark::ClobberMemory();
    refresh_now_and_then<typename System::damping_policy>(state, steps,
                                                          [&] { start.restore(system); });
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Particles at rest (docs/results/subnormal.md): the sparks of BM_System once
// damping has taken their x and z velocities into the subnormal range, where they stay (the
// damped value rounds back to itself). The velocities are put there at once rather than by
// the 51,000 steps of 1/60 s that damping 0.9 per second takes from 10 m/s in float (in
// double, 400,000), and are not refreshed. Flush: every step under FlushDenormals, which
// makes them zero at the first step.
template <class R, bool Flush>
void BM_Subnormal(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  auto system = make_system<ParticleSystem<R>>(count);
  const R tiny = std::numeric_limits<R>::min() / R(64);
  for (std::size_t i = 0; i < count; ++i) {
    const Vector3<R> v = system.velocity(i);
    system.set_velocity(i, {v.x < R(0) ? -tiny : tiny, v.y, v.z < R(0) ? -tiny : tiny});
  }
  const auto t = duration<R>();
  std::optional<FlushDenormals> flush;
  if constexpr (Flush) flush.emplace();
  for (auto _ : state) {
    system.step(t);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class System>
void BM_SystemParallel(benchmark::State& state) {
  auto system = make_system<System>(static_cast<std::size_t>(state.range(0)));
  const SavedVelocities<System> start(system);
  const auto t = duration<typename System::real>();
  std::int64_t steps = 0;
  for (auto _ : state) {
    pointmass::step(std::execution::par_unseq, system, t);
    benchmark::ClobberMemory();
    refresh_now_and_then<typename System::damping_policy>(state, steps,
                                                          [&] { start.restore(system); });
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The same maths as ParticleSystem<R> (per-second damping, d^t once per step, p + v0 t),
// written by hand.
template <class R>
void hand_step(R* __restrict px, R* __restrict py, R* __restrict pz, R* __restrict vx,
               R* __restrict vy, R* __restrict vz, std::size_t n, R ax, R ay, R az, R t, R kept) {
  for (std::size_t i = 0; i < n; ++i) {
    const R x = vx[i], y = vy[i], z = vz[i];
    vx[i] = x * kept + ax * t;
    vy[i] = y * kept + ay * t;
    vz[i] = z * kept + az * t;
    px[i] = px[i] + x * t;
    py[i] = py[i] + y * t;
    pz[i] = pz[i] + z * t;
  }
}

// The traversal ParticleSystem::step uses within its alternation bounds, by hand: every
// other step walks the arrays backwards in whole chunks, each chunk forwards.
template <class R>
void hand_step_backward(R* const* a, std::size_t n, R ax, R ay, R az, R t, R kept) {
  constexpr std::size_t chunk =
      pointmass::detail::SystemAccess::Kernel<ParticleSystem<R>>::backward_chunk;
  std::size_t end = n - n % chunk;
  hand_step(a[0] + end, a[1] + end, a[2] + end, a[3] + end, a[4] + end, a[5] + end, n - end, ax, ay,
            az, t, kept);
  while (end != 0) {
    end -= chunk;
    hand_step(a[0] + end, a[1] + end, a[2] + end, a[3] + end, a[4] + end, a[5] + end, chunk, ax, ay,
              az, t, kept);
  }
}

// How the hand-written loop walks its arrays from one step to the next: always forwards;
// forwards and backwards in turn as the system does (within its size bounds); or in turn at
// every size (what the bounds avoid).
enum class Walk { forwards, like_the_system, always_alternating };

template <class R, Walk walk>
void hand_loop(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  StaggeredArrays<R> arrays(n);
  const R t = duration<R>();
  const Vector3<R> g = gravity<R>();
  R** a = arrays.array;
  const bool alternating =
      walk == Walk::always_alternating ||
      (walk == Walk::like_the_system &&
       pointmass::detail::SystemAccess::Kernel<ParticleSystem<R>>::alternates(n));
  const std::vector<R> start_x(a[3], a[3] + n), start_y(a[4], a[4] + n),
      start_z(a[5], a[5] + n);  // the velocities, to put back
  std::int64_t steps = 0;
  for (auto _ : state) {
    const R kept = real_pow(R(0.9), t);
    if (alternating && steps % 2 == 1) {
      hand_step_backward(a, n, g.x, g.y, g.z, t, kept);
    } else {
      hand_step(a[0], a[1], a[2], a[3], a[4], a[5], n, g.x, g.y, g.z, t, kept);
    }
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] {
      std::copy(start_x.begin(), start_x.end(), a[3]);
      std::copy(start_y.begin(), start_y.end(), a[4]);
      std::copy(start_z.begin(), start_z.end(), a[5]);
    });
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class R>
void BM_HandStaggered(benchmark::State& state) {
  hand_loop<R, Walk::forwards>(state);
}
template <class R>
void BM_HandAlternating(benchmark::State& state) {
  hand_loop<R, Walk::like_the_system>(state);
}
template <class R>
void BM_HandAlwaysAlternating(benchmark::State& state) {
  hand_loop<R, Walk::always_alternating>(state);
}

// Read-modify-write of the same six arrays: the memory bound of a step.
template <class R>
void BM_Bandwidth(benchmark::State& state) {
  StaggeredArrays<R> arrays(static_cast<std::size_t>(state.range(0)));
  bandwidth(state, arrays);
  state.SetBytesProcessed(state.iterations() * state.range(0) * 12 *
                          static_cast<std::int64_t>(sizeof(R)));
}

template <class R>
void BM_BandwidthParallel(benchmark::State& state) {
  StaggeredArrays<R> arrays(static_cast<std::size_t>(state.range(0)));
  bandwidth_parallel(state, arrays);
}

// One Particle object per particle, each integrated on its own.
template <class R>
void BM_Particles(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<Particle<R>> particles(n);
  std::mt19937 engine(1);
  for (auto& particle : particles) {
    particle.set_position(random_vector(engine, R(100)));
    particle.set_velocity(random_vector(engine, R(10)));
    particle.set_acceleration(gravity<R>());
    particle.set_damping(R(0.9));
  }
  const R t = duration<R>();
  for (auto _ : state) {
    for (auto& particle : particles) particle.integrate(t);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class R>
using Sparks = ParticleSystem<R>;
template <class R>
using Undamped = ParticleSystem<R, damping::None>;
template <class R>
using PerFrame = ParticleSystem<R, damping::PerFrame>;
template <class R>
using WithLifetime = ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime>;
template <class R>
using WithForces =
    ParticleSystem<R, damping::PerSecond, position::Euler, features::ForceAccumulator>;
// Force-driven particles, the step alone (the forces' apply is the same for both).
template <class R>
using ForcesSemiImplicit =
    ParticleSystem<R, damping::PerSecond, position::SemiImplicit, features::ForceAccumulator>;
template <class R>
using ForcesVelocityVerlet =
    ParticleSystem<R, damping::PerSecond, position::VelocityVerlet, features::ForceAccumulator>;
template <class R>
using WithAcceleration =
    ParticleSystem<R, damping::PerSecond, position::Euler, features::PerParticleAcceleration>;
template <class R>
using WithDamping =
    ParticleSystem<R, damping::PerSecond, position::Euler, features::PerParticleDamping>;

void sizes(benchmark::internal::Benchmark* b) { b->Arg(1000)->Arg(100000)->Arg(10000000); }
void middle(benchmark::internal::Benchmark* b) { b->Arg(100000); }
void large(benchmark::internal::Benchmark* b) { b->Arg(10000000); }
// Double sizes across both alternation bounds (32 KiB = 682 particles, 8 MiB = 174,762).
void around_limit(benchmark::internal::Benchmark* b) {
  b->Arg(1000)->Arg(100000)->Arg(300000)->Arg(1000000)->Arg(3000000);
}

#define POINTMASS_BENCH_BOTH(function, args)        \
  BENCHMARK_TEMPLATE(function, float)->Apply(args); \
  BENCHMARK_TEMPLATE(function, double)->Apply(args)

POINTMASS_BENCH_BOTH(BM_HandStaggered, sizes);
POINTMASS_BENCH_BOTH(BM_HandAlternating, sizes);
// Why the bounds: forwards against alternating at every size, double.
BENCHMARK_TEMPLATE(BM_HandStaggered, double)->Arg(300000)->Arg(1000000)->Arg(3000000);
BENCHMARK_TEMPLATE(BM_HandAlwaysAlternating, double)->Apply(around_limit);
// And why not below 32 KiB: float, 1,000 particles (23 KiB).
BENCHMARK_TEMPLATE(BM_HandAlwaysAlternating, float)->Arg(1000);
POINTMASS_BENCH_BOTH(BM_Bandwidth, sizes);
BENCHMARK_TEMPLATE(BM_System, Sparks<float>)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_System, Sparks<double>)->Apply(sizes);
// Particles at rest: subnormal x and z velocities, without and with FlushDenormals.
void at_rest(benchmark::internal::Benchmark* b) { b->Arg(1000)->Arg(100000); }
BENCHMARK_TEMPLATE(BM_Subnormal, float, false)->Apply(at_rest);
BENCHMARK_TEMPLATE(BM_Subnormal, float, true)->Apply(at_rest);
BENCHMARK_TEMPLATE(BM_Subnormal, double, false)->Apply(at_rest);
BENCHMARK_TEMPLATE(BM_Subnormal, double, true)->Apply(at_rest);
POINTMASS_BENCH_BOTH(BM_Particles, middle);
BENCHMARK_TEMPLATE(BM_SystemParallel, Sparks<float>)->Apply(large)->UseRealTime();
BENCHMARK_TEMPLATE(BM_SystemParallel, Sparks<double>)->Apply(large)->UseRealTime();
BENCHMARK_TEMPLATE(BM_BandwidthParallel, float)->Apply(large)->UseRealTime();
BENCHMARK_TEMPLATE(BM_BandwidthParallel, double)->Apply(large)->UseRealTime();
// What each compile-time choice costs, at 100,000 particles.
BENCHMARK_TEMPLATE(BM_System, Undamped<float>)->Apply(middle);
BENCHMARK_TEMPLATE(BM_System, PerFrame<float>)->Apply(middle);
BENCHMARK_TEMPLATE(BM_System, WithLifetime<float>)->Apply(middle);
BENCHMARK_TEMPLATE(BM_System, WithForces<float>)->Apply(middle);
BENCHMARK_TEMPLATE(BM_System, WithAcceleration<float>)->Apply(middle);
BENCHMARK_TEMPLATE(BM_System, WithDamping<float>)->Apply(middle);
// Second order under forces against SemiImplicit, side by side.
void forces_sizes(benchmark::internal::Benchmark* b) { b->Arg(1000)->Arg(100000); }
BENCHMARK_TEMPLATE(BM_System, ForcesSemiImplicit<float>)->Apply(forces_sizes);
BENCHMARK_TEMPLATE(BM_System, ForcesVelocityVerlet<float>)->Apply(forces_sizes);

// The renderer's hand-off (docs/results/hand-off.md): copying the positions out, after a step,
// against the step itself, in the same run. Items: particles copied (or stepped).
template <class R>
using Interpolated =
    ParticleSystem<R, damping::PerSecond, position::Euler, features::Interpolation>;
struct GameColourTag {};
template <class R>
using GameSparks = ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime,
                                  features::Interpolation, features::Handles,
                                  features::Column<GameColourTag, std::uint32_t>>;
struct Vertex {  // a renderer's vertex: position, then a colour (interleaved)
  float x, y, z;
  std::uint32_t colour;
};
struct Vec3 {
  float x, y, z;
};

template <class R, int Layout>
void BM_CopyOut(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  auto system = make_system<Interpolated<R>>(n);
  system.step(duration<R>());
  std::vector<float> packed(3 * n), strided(6 * n);
  std::vector<Vec3> vectors(n);
  for (auto _ : state) {
    if constexpr (Layout == 0) {  // x, y, z packed: float[3 n]
      system.copy_positions(std::span<float>(packed));
      benchmark::DoNotOptimize(packed.data());
    } else if constexpr (Layout == 1) {  // into a vector of {x, y, z} structs
      system.copy_positions(std::span<Vec3>(vectors));
      benchmark::DoNotOptimize(vectors.data());
    } else if constexpr (Layout == 2) {  // interleaved with three other floats: stride 6
      system.copy_positions(std::span<float>(strided), 6);
      benchmark::DoNotOptimize(strided.data());
    } else {  // interpolated at alpha 0.5, packed
      system.copy_interpolated_positions(R(0.5), std::span<float>(packed));
      benchmark::DoNotOptimize(packed.data());
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
template <class R>
void BM_CopyPacked(benchmark::State& state) {
  BM_CopyOut<R, 0>(state);
}
template <class R>
void BM_CopyVec3(benchmark::State& state) {
  BM_CopyOut<R, 1>(state);
}
template <class R>
void BM_CopyStrided(benchmark::State& state) {
  BM_CopyOut<R, 2>(state);
}
template <class R>
void BM_CopyInterpolated(benchmark::State& state) {
  BM_CopyOut<R, 3>(state);
}

// A renderer's hand-off from wide positions (precision.hpp): copy_positions(out, camera)
// near the particles, which are spread over a kilometre 1e6 m out, into {x, y, z} floats;
// each offset rounded once (round_via_odd), the cost beside copy_positions' from float.
template <class S>
void BM_Relative(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  ParticleSystem<S> system(n);
  std::mt19937 engine(5);
  std::uniform_real_distribution<double> spread(-500, 500);
  for (std::size_t i = 0; i < n; ++i) {
    system.spawn(Vector3<double>{1e6 + spread(engine), spread(engine), 1e6 + spread(engine)}, {});
  }
  const Vector3<double> camera{1e6 + 0.3, 1.7, 1e6 - 2.1};
  std::vector<Vector3<float>> offsets(n);
  for (auto _ : state) {
    system.copy_positions(std::span(offsets), camera);
    benchmark::DoNotOptimize(offsets.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void handoff(benchmark::internal::Benchmark* b) { b->Arg(100000)->Arg(1000000); }
BENCHMARK_TEMPLATE(BM_System, Sparks<float>)->Arg(1000000);
BENCHMARK_TEMPLATE(BM_System, Interpolated<float>)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_System, GameSparks<float>)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_CopyPacked, float)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_CopyVec3, float)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_CopyStrided, float)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_CopyInterpolated, float)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_Relative, Precision<float, double>)->Apply(handoff);
BENCHMARK_TEMPLATE(BM_Relative, Precision<float, Compensated<float>>)->Apply(handoff);

template <class R>
bool step_moves_particles() {
  auto system = make_system<Sparks<R>>(32);
  const Vector3<R> before = system.position(31);
  system.step(duration<R>());
  return duration<R>() > R(0) && !(system.position(31) == before);
}

}  // namespace

int main(int argc, char** argv) {
  set_duration(argc);
  if (!step_moves_particles<float>() || !step_moves_particles<double>()) {
    std::fputs("system_step: a step did not move the particles; the timings would be void\n",
               stderr);
    return 1;
  }
  // The smoke test (benchmarks/CMakeLists.txt sets POINTMASS_BENCHMARK_SMOKE) skips the 10^7
  // sizes, which take minutes to set up in a debug build.
  return run_benchmarks(argc, argv, "--benchmark_filter=/(1000|100000)$");
}
