// SPDX-License-Identifier: BSL-1.0
// Cyclone's own job, side by side: every particle with its own damping (0.99 per
// second), mass and acceleration (gravity), stepped at 1/60 s, against
//   * the engine's particle (tests/support/reference_engine.*: its 72-byte float / 144-byte
//     double layout with padded vectors, its integrate out of line in its own translation
//     unit, one pow per particle and step) — the baseline every ratio is taken against;
//   * a vector of `Particle<R>` (the default policies: per-second damping, p + v t), at a
//     fixed step and with a step length that changes every step;
//   * a vector of `Particle<R, damping::AccelerateThenDamp, position::Euler>` (the engine's
//     equations, the same results bit for bit: tests/reference/test_engine_replay.cpp);
//   * a hand-written loop over a plain struct doing the default Particle's arithmetic at a
//     fixed step (its retention d^t kept per particle, as a hand-tuned game loop would);
//   * `ParticleSystem` configurations (BM_System, below);
//   * the power function alone at the changing step lengths (BM_PowAlone).
// scripts/benchmark-engine.sh runs it with interleaved repetitions and writes the table of
// medians and ratios into docs/results/engine.md. Counters: items_per_second = particle-steps/s.
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "reference_engine.hpp"
#include "support/bench_refresh.hpp"
#include "support/bench_support.hpp"

namespace {

using namespace pointmass;
using namespace pointmass_benchmarks;

// A length that changes every step: t and t (1 + 2^-10) in turn.
template <class R>
R varying_duration(std::int64_t step) {
  return step % 2 == 0 ? duration<R>() : duration<R>() * (R(1) + R(1) / R(1024));
}

template <class R>
constexpr R damping_value = R(0.99);

/// Initial state of particle i, the same for every loop.
template <class R>
struct Start {
  Vector3<R> position;
  Vector3<R> velocity;
  R mass;
};
template <class R>
std::vector<Start<R>> starts(std::size_t count) {
  std::mt19937 engine(1);
  std::uniform_real_distribution<R> position(R(-100), R(100));
  std::uniform_real_distribution<R> velocity(R(-10), R(10));
  std::uniform_real_distribution<R> mass(R(0.5), R(2));
  std::vector<Start<R>> result(count);
  for (auto& s : result) {
    s.position = {position(engine), position(engine), position(engine)};
    s.velocity = {velocity(engine), velocity(engine), velocity(engine)};
    s.mass = mass(engine);
  }
  return result;
}
template <class R>
constexpr Vector3<R> gravity_vector{R(0), R(-9.81f), R(0)};

/// `count` particles of type P set up from starts<R>: a Vector3<R> is passed through
/// `vector` (Cyclone's particle takes its own vector type).
template <class P, class R, class ToVector>
std::vector<P> particles_from_starts(std::size_t count, ToVector vector) {
  std::vector<P> particles(count);
  const auto s = starts<R>(count);
  for (std::size_t i = 0; i < count; ++i) {
    particles[i].set_position(vector(s[i].position));
    particles[i].set_velocity(vector(s[i].velocity));
    particles[i].set_mass(s[i].mass);
    particles[i].set_damping(damping_value<R>);
    particles[i].set_acceleration(vector(gravity_vector<R>));
  }
  return particles;
}

// Every timed loop below puts its particles (or their velocities) back to where they started
// every 4,096 steps, outside the timing (support/bench_refresh.hpp): at 1,024 particles the
// fastest loops would otherwise take the x and z velocities into the subnormal range within a
// second of running, and time that.

/// The timed loop of a vector of particles, each stepped by its `integrate`: at a fixed step,
/// or (Varying) at a length that changes every step.
template <class R, bool Varying, class P>
void integrate_loop(benchmark::State& state, std::vector<P>& particles) {
  const std::vector<P> start = particles;
  std::int64_t steps = 0;  // counted by refresh_now_and_then
  for (auto _ : state) {
    const R t = Varying ? varying_duration<R>(steps) : duration<R>();
    for (auto& p : particles) p.integrate(t);
    benchmark::DoNotOptimize(particles.data());
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] { particles = start; });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(particles.size()));
}

// --- Cyclone's loop: the baseline ------------------------------------------------

template <class R, bool Varying>
void BM_Engine(benchmark::State& state) {
  auto particles = particles_from_starts<reference_engine::Particle<R>, R>(
      static_cast<std::size_t>(state.range(0)),
      [](const Vector3<R>& v) { return reference_engine::Vector3<R>(v.x, v.y, v.z); });
  integrate_loop<R, Varying>(state, particles);
}

// --- vectors of Particle ------------------------------------------------------------------------

template <class R, class D, class P, bool Varying>
void BM_Particles(benchmark::State& state) {
  auto particles = particles_from_starts<Particle<R, D, P>, R>(
      static_cast<std::size_t>(state.range(0)), [](const Vector3<R>& v) { return v; });
  integrate_loop<R, Varying>(state, particles);
}

// The Particle a fixed-step scene can choose: damping::PerFrame, given the fraction kept per
// step (d^t of the per-second d, computed once), keeps no damping state for other lengths and
// no cache, so it holds exactly the lean struct's fields (BM_HandStruct, below) and does its
// arithmetic, v = v d^t + a t. Another step length would need its owner to set d^t again.
template <class R>
void BM_PerFrameParticles(benchmark::State& state) {
  auto particles = particles_from_starts<Particle<R, damping::PerFrame>, R>(
      static_cast<std::size_t>(state.range(0)), [](const Vector3<R>& v) { return v; });
  for (auto& p : particles) p.set_damping(real_pow(damping_value<R>, duration<R>()));
  integrate_loop<R, false>(state, particles);
}

// --- the hand-written loop: the default Particle's arithmetic over a plain struct ---------------

// Its fields in the Particle's order (position, inverse mass, velocity, ...): no two of the
// vectors a step writes are adjacent, so g++ does not vectorise the stores of a position and
// the next velocity's first component together, which takes shuffles (particle.hpp, at its
// fields). In the textbook's order this loop would be the slower one in cache.
template <class R>
struct HandParticle {
  Vector3<R> position;
  R inverse_mass;
  Vector3<R> velocity;
  Vector3<R> acceleration;
  Vector3<R> force;
  R kept;  // d^t for the fixed step, computed once
};

/// A hand-written particle's step once its d^t is `p.kept`: a = acceleration + force * inverse
/// mass, p += v t, v = v d^t + a t (the caller skips immovable particles and clears the force).
template <class Hand, class R>
void hand_advance(Hand& p, R t) {
  const Vector3<R> a = p.acceleration + p.force * p.inverse_mass;
  p.position = p.position + p.velocity * t;
  p.velocity = p.velocity * p.kept + a * t;
}

template <class R>
void BM_HandStruct(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  std::vector<HandParticle<R>> particles(count);
  const auto s = starts<R>(count);
  const R t = duration<R>();
  for (std::size_t i = 0; i < count; ++i) {
    particles[i] = {s[i].position,
                    R(1) / s[i].mass,
                    s[i].velocity,
                    gravity_vector<R>,
                    {},
                    real_pow(damping_value<R>, t)};
  }
  const std::vector<HandParticle<R>> start = particles;
  std::int64_t steps = 0;
  for (auto _ : state) {
    for (auto& p : particles) {
      if (p.inverse_mass > R(0)) hand_advance(p, t);
      p.force = {};
    }
    benchmark::DoNotOptimize(particles.data());
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] { particles = start; });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}

// The same data as the default Particle<R> and the same arithmetic: what "a hand-written struct
// loop of the same arithmetic" means in docs/results/engine.md. It holds what a Particle must to
// take any damping and any step length (d and ln d as hi + lo, the last step's length and d^t)
// and does, per particle, the Particle's step: compare the length with the kept one (computing
// d^t with the library's exponential when it differs), then a = acceleration + force * inverse
// mass, p += v t, v = v d^t + a t, force = 0. BM_HandStruct (above) is the leaner struct a
// game would write for one fixed step (d^t kept, 56 bytes in float): the price of the bytes.
template <class R>
struct HandSameData {  // in the Particle's order (as HandParticle, above)
  Vector3<R> position;
  R inverse_mass;
  Vector3<R> velocity;
  Vector3<R> acceleration;
  Vector3<R> force;
  R damping;
  detail::SplitLog<R> log_damping;
  R kept_duration;
  R kept;
};
static_assert(sizeof(HandSameData<float>) == sizeof(Particle<float>));
static_assert(sizeof(HandParticle<float>) == sizeof(Particle<float, damping::PerFrame>));
static_assert(sizeof(HandParticle<double>) == sizeof(Particle<double, damping::PerFrame>));
static_assert(sizeof(HandSameData<double>) == sizeof(Particle<double>));

template <class R>
void BM_HandSameData(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  std::vector<HandSameData<R>> particles(count);
  const auto s = starts<R>(count);
  for (std::size_t i = 0; i < count; ++i) {
    particles[i] = {s[i].position,
                    R(1) / s[i].mass,
                    s[i].velocity,
                    gravity_vector<R>,
                    {},
                    damping_value<R>,
                    detail::split_log(damping_value<R>),
                    R(-1),
                    R(1)};
  }
  const R t = duration<R>();
  const std::vector<HandSameData<R>> start = particles;
  std::int64_t steps = 0;
  for (auto _ : state) {
    for (auto& p : particles) {
      if (p.inverse_mass > R(0)) {
        if (!real_equal(p.kept_duration, t)) {
          p.kept = detail::pow_unit_scalar(p.log_damping, t);
          p.kept_duration = t;
        }
        hand_advance(p, t);
      }
      p.force = {};
    }
    benchmark::DoNotOptimize(particles.data());
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] { particles = start; });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}

// --- memory bounds: read-modify-write over the same bytes -------------------------------------

// Every byte of `Bytes` per particle read and written once a step (a step of a vector of
// particles rewrites every cache line it reads): the bound of a vector of such particles.
template <class R, std::size_t Bytes>
void BM_BandwidthBytes(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  std::vector<R> data(count * Bytes / sizeof(R), R(1));
  const R c = duration<R>();
  for (auto _ : state) {
    R* __restrict d = data.data();
    for (std::size_t i = 0; i < data.size(); ++i) d[i] += c;
    benchmark::DoNotOptimize(data.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}

// --- the power function alone -------------------------------------------------------------------

// What a step length that changes every step costs both loops of the engine's equations (its
// particles and Particle<R, AccelerateThenDamp, Euler>) before anything else: the C library's
// pow of each particle's damping (real_pow, as both call it), one per particle and step,
// stored, at the same alternating lengths. Their rates over this one say how much of each
// loop's time the rest of its step takes.
template <class R>
void BM_PowAlone(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  std::vector<R> damping(count, damping_value<R>);
  std::vector<R> kept(count);
  std::int64_t step = 0;
  for (auto _ : state) {
    const R t = varying_duration<R>(step++);
    for (std::size_t i = 0; i < count; ++i) kept[i] = real_pow(damping[i], t);
    benchmark::DoNotOptimize(kept.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}

// --- ParticleSystem rows --------------------------------------------------------------------------
// BM_System<Config>: the place for the batch's rows. Config::System is a ParticleSystem type;
// the engine's job needs per-particle damping, acceleration, mass and forces (FullFeatured);
// Lean is the system at its cheapest for the same motion (uniform damping and gravity).
// scripts/benchmark-engine.sh reads the rows by these names.

template <class R>
struct FullFeatured {
  using System =
      ParticleSystem<R, damping::PerSecond, position::Euler, features::PerParticleDamping,
                     features::PerParticleAcceleration, features::ForceAccumulator>;
};
template <class R>
struct Lean {
  using System = ParticleSystem<R>;
};
// The full-featured system's other arrays with one damping for all: what per-particle damping
// costs is FullFeatured against this.
template <class R>
struct UniformDampingFeatured {
  using System = ParticleSystem<R, damping::PerSecond, position::Euler,
                                features::PerParticleAcceleration, features::ForceAccumulator>;
};

// The full-featured system's memory traffic at a fixed step with trivial arithmetic: every
// array it reads (14: position, velocity, acceleration, inverse mass, force, and each
// particle's d^t kept for the step length) read, the 9 it writes (position, velocity, force)
// written, in its own block: the bound of its step.
template <class R>
void BM_BandwidthFullFeatured(benchmark::State& state) {
  using System = typename FullFeatured<R>::System;
  const auto count = static_cast<std::size_t>(state.range(0));
  System system(count);
  for (std::size_t i = 0; i < count; ++i) system.spawn({}, {});
  const auto& a = pointmass::detail::SystemAccess::arrays(system);
  const R c = duration<R>();
  for (auto _ : state) {
    R* __restrict px = a.position_x;
    R* __restrict py = a.position_y;
    R* __restrict pz = a.position_z;
    R* __restrict vx = a.velocity_x;
    R* __restrict vy = a.velocity_y;
    R* __restrict vz = a.velocity_z;
    R* __restrict fx = a.force_x;
    R* __restrict fy = a.force_y;
    R* __restrict fz = a.force_z;
    const R* __restrict ax = a.acceleration_x;
    const R* __restrict ay = a.acceleration_y;
    const R* __restrict az = a.acceleration_z;
    const R* __restrict im = a.inverse_mass;
    const R* __restrict kept = a.damping_retention;
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = 0; i < count; ++i) {
      const R k = (ax[i] + ay[i]) + (az[i] + im[i]) + kept[i] + ((fx[i] + fy[i]) + fz[i]);
      px[i] += c * k;
      py[i] += c * k;
      pz[i] += c * k;
      vx[i] += k;
      vy[i] += k;
      vz[i] += k;
      fx[i] = R(0);
      fy[i] = R(0);
      fz[i] = R(0);
    }
    benchmark::DoNotOptimize(a.position_x);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}

template <class Config>
void BM_System(benchmark::State& state) {
  using System = typename Config::System;
  using R = typename System::real;
  const auto count = static_cast<std::size_t>(state.range(0));
  System system(count);
  const auto s = starts<R>(count);
  for (std::size_t i = 0; i < count; ++i) system.spawn(s[i].position, s[i].velocity);
  if constexpr (System::template has<pointmass::features::PerParticleDamping>) {
    for (std::size_t i = 0; i < count; ++i) system.set_damping(i, damping_value<R>);
  } else {
    system.set_damping(damping_value<R>);
  }
  if constexpr (System::template has<pointmass::features::PerParticleAcceleration>) {
    for (std::size_t i = 0; i < count; ++i) system.set_acceleration(i, gravity_vector<R>);
  } else {
    system.set_acceleration(gravity_vector<R>);
  }
  if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
    for (std::size_t i = 0; i < count; ++i) system.set_mass(i, s[i].mass);
  }
  const R t = duration<R>();
  const SavedVelocities<System> start(system);
  std::int64_t steps = 0;
  for (auto _ : state) {
    system.step(t);
    benchmark::DoNotOptimize(system.template column<pointmass::Column::position_x>().data());
    benchmark::ClobberMemory();
    refresh_now_and_then(state, steps, [&] { start.restore(system); });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(count));
}

void sizes(benchmark::internal::Benchmark* b) {
  for (const long n : {1024L, 100000L, 1000000L}) b->Arg(n);
}

#define POINTMASS_ENGINE_BENCHMARKS(R)                                                           \
  BENCHMARK(BM_Engine<R, false>)->Apply(sizes);                                                  \
  BENCHMARK(BM_Engine<R, true>)->Apply(sizes);                                                   \
  BENCHMARK(BM_Particles<R, damping::PerSecond, position::Euler, false>)->Apply(sizes);          \
  BENCHMARK(BM_Particles<R, damping::PerSecond, position::Euler, true>)->Apply(sizes);           \
  BENCHMARK(BM_Particles<R, damping::AccelerateThenDamp, position::Euler, false>)->Apply(sizes); \
  BENCHMARK(BM_Particles<R, damping::AccelerateThenDamp, position::Euler, true>)->Apply(sizes);  \
  BENCHMARK(BM_PerFrameParticles<R>)->Apply(sizes);                                              \
  BENCHMARK(BM_HandStruct<R>)->Apply(sizes);                                                     \
  BENCHMARK(BM_HandSameData<R>)->Apply(sizes);                                                   \
  BENCHMARK(BM_System<FullFeatured<R>>)->Apply(sizes);                                           \
  BENCHMARK(BM_System<UniformDampingFeatured<R>>)->Apply(sizes);                                 \
  BENCHMARK(BM_System<Lean<R>>)->Apply(sizes);                                                   \
  BENCHMARK(BM_BandwidthFullFeatured<R>)->Arg(1000000);                                          \
  BENCHMARK(BM_BandwidthBytes<R, sizeof(Particle<R>)>)->Arg(100000)->Arg(1000000);               \
  BENCHMARK(BM_BandwidthBytes<R, sizeof(HandParticle<R>)>)->Arg(100000)->Arg(1000000);           \
  BENCHMARK(BM_PowAlone<R>)->Apply(sizes)

POINTMASS_ENGINE_BENCHMARKS(float);
POINTMASS_ENGINE_BENCHMARKS(double);

/// The loops must move the particles, or their times mean nothing.
template <class R>
bool step_moves_particles() {
  Particle<R> particle;
  particle.set_velocity({R(1), R(0), R(0)});
  particle.integrate(duration<R>());
  reference_engine::Particle<R> theirs;
  theirs.set_velocity({R(1), R(0), R(0)});
  theirs.integrate(duration<R>());
  return particle.position().x > R(0) && theirs.position().x > R(0);
}

}  // namespace

int main(int argc, char** argv) {
  set_duration(argc);
  if (!step_moves_particles<float>() || !step_moves_particles<double>()) {
    std::fputs("engine_step: a step did not move the particles; the timings would be void\n",
               stderr);
    return 1;
  }
  // The smoke test (benchmarks/CMakeLists.txt sets POINTMASS_BENCHMARK_SMOKE) runs the 1,024
  // sizes only: setting up the 10^6 ones takes most of a minute in a debug build.
  return run_benchmarks(argc, argv, "--benchmark_filter=/1024$");
}
