// SPDX-License-Identifier: BSL-1.0
// A system and the equivalent scalar Particles, stepped side by side, agree bit for bit:
// each particle's step is integrate<D, P> on x, y and z apart, the same operations in the same
// order as Particle::integrate on a Vector3, so nothing may differ (not even by one ulp).
// Every damping and position policy pair, float and double; uniform and per-particle values.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <random>
#include <tuple>
#include <type_traits>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

namespace {

using namespace pointmass;
using pointmass::test::matches;
using pointmass::test::random_vector;
using pointmass::test::same_bits;

template <class R, class D, class P>
struct Config {
  using real = R;
  using damping_policy = D;
  using position_policy = P;
};

template <class R>
using AllPairs = std::tuple<
    Config<R, damping::None, position::Euler>,
    Config<R, damping::None, position::ConstantAcceleration>,
    Config<R, damping::None, position::SemiImplicit>, Config<R, damping::None, position::Exact>,
    Config<R, damping::PerFrame, position::Euler>,
    Config<R, damping::PerFrame, position::ConstantAcceleration>,
    Config<R, damping::PerFrame, position::SemiImplicit>,
    Config<R, damping::PerSecond, position::Euler>,
    Config<R, damping::PerSecond, position::ConstantAcceleration>,
    Config<R, damping::PerSecond, position::SemiImplicit>,
    Config<R, damping::AccelerateThenDamp, position::Euler>,
    Config<R, damping::AccelerateThenDamp, position::ConstantAcceleration>,
    Config<R, damping::AccelerateThenDamp, position::SemiImplicit>,
    Config<R, damping::Exact, position::Euler>,
    Config<R, damping::Exact, position::ConstantAcceleration>,
    Config<R, damping::Exact, position::SemiImplicit>, Config<R, damping::Exact, position::Exact>,
    Config<R, damping::None, position::VelocityVerlet>,
    Config<R, damping::PerFrame, position::VelocityVerlet>,
    Config<R, damping::PerSecond, position::VelocityVerlet>,
    Config<R, damping::Exact, position::VelocityVerlet>>;

template <class... A, class... B>
auto concatenate(std::tuple<A...>, std::tuple<B...>) -> std::tuple<A..., B...>;
using EveryPairFloatAndDouble =
    decltype(concatenate(std::declval<AllPairs<float>>(), std::declval<AllPairs<double>>()));

// Steps of varied length (seconds), including a long one that takes Exact past |kt| = 1/4.
template <class R>
constexpr std::array<R, 5> durations = {R(1) / R(60), R(1) / R(30), R(0.1), R(0.005), R(0.7)};

// 37 particles: two full vector blocks of 16 and a remainder of 5, so both loops run.
constexpr std::size_t count = 37;

}  // namespace

TEST_CASE_TEMPLATE_DEFINE("uniform damping and gravity: system == Particles, bit for bit", C,
                          uniform_equivalence) {
  using R = typename C::real;
  using D = typename C::damping_policy;
  using P = typename C::position_policy;
  using System = ParticleSystem<R, D, P>;
  std::mt19937 engine(42);
  const Vector3<R> acceleration{R(1.5), R(-9.807), R(0.25)};

  System system(count);
  system.set_acceleration(acceleration);
  if constexpr (System::stores_damping) system.set_damping(R(0.6));
  std::vector<Particle<R, D, P>> particles(count);
  for (auto& particle : particles) {
    particle.set_position(random_vector(engine, R(100)));
    particle.set_velocity(random_vector(engine, R(30)));
    particle.set_acceleration(acceleration);
    if constexpr (System::stores_damping) particle.set_damping(R(0.6));
    CHECK(system.spawn(particle.position(), particle.velocity()) != System::npos);
  }
  REQUIRE(matches(system, particles));
  const Vector3<R> start = system.position(1);
  for (int step = 0; step < 40; ++step) {
    const R t = durations<R>[static_cast<std::size_t>(step) % durations<R>.size()];
    system.step(t);
    for (auto& particle : particles) particle.integrate(t);
    REQUIRE(matches(system, particles));
  }
  // The particles moved: two systems that did nothing would match too.
  CHECK_FALSE(system.position(1) == start);
}
TEST_CASE_TEMPLATE_APPLY(uniform_equivalence, EveryPairFloatAndDouble);

// A step of the length the last one took reuses its uniform damping factors; set_damping,
// a copy and a swap must take them along or forget them, so that every step still gives what
// Particles with the same damping give, bit for bit.
TEST_CASE_TEMPLATE("kept damping factors follow set_damping, copies and swaps", C,
                   Config<float, damping::PerSecond, position::Euler>,
                   Config<double, damping::Exact, position::Exact>,
                   Config<float, damping::AccelerateThenDamp, position::Euler>) {
  using R = typename C::real;
  using D = typename C::damping_policy;
  using P = typename C::position_policy;
  using System = ParticleSystem<R, D, P>;
  std::mt19937 engine(7);
  const Vector3<R> acceleration{R(0), R(-9.807), R(0)};
  const R t = R(1) / R(60);
  // Two systems with their Particles, damped differently.
  const auto make = [&](R damping, System& system, std::vector<Particle<R, D, P>>& particles) {
    system.set_acceleration(acceleration);
    system.set_damping(damping);
    particles.resize(count);
    for (auto& particle : particles) {
      particle.set_position(random_vector(engine, R(100)));
      particle.set_velocity(random_vector(engine, R(30)));
      particle.set_acceleration(acceleration);
      particle.set_damping(damping);
      REQUIRE(system.spawn(particle.position(), particle.velocity()) != System::npos);
    }
  };
  System a(count), b(count);
  std::vector<Particle<R, D, P>> pa, pb;
  make(R(0.6), a, pa);
  make(R(0.05), b, pb);
  const auto step = [&](System& system, std::vector<Particle<R, D, P>>& particles) {
    system.step(t);
    for (auto& particle : particles) particle.integrate(t);
    return matches(system, particles);
  };
  REQUIRE(step(a, pa));
  REQUIRE(step(b, pb));
  a.set_damping(R(0.95));  // the same length, a new damping
  for (auto& particle : pa) particle.set_damping(R(0.95));
  CHECK(step(a, pa));
  swap(a, b);  // each takes the other's damping and kept factors along
  std::swap(pa, pb);
  CHECK(step(a, pa));
  CHECK(step(b, pb));
  System c = a;  // a copy: the same damping, the same kept factors
  std::vector<Particle<R, D, P>> pc = pa;
  CHECK(step(c, pc));
  c.set_damping(R(0.3));
  for (auto& particle : pc) particle.set_damping(R(0.3));
  CHECK(step(c, pc));
  CHECK(step(a, pa));  // the original keeps its own
}

namespace {

/// n particles with their own damping, acceleration, mass and forces, in a system
/// and as Particles, stepped side by side for `steps` steps: the same bits after each step.
/// Particle i is immovable (inverse mass 0) when immovable(i) says so; the first immovable
/// and the first movable particle are checked to have stayed and moved.
template <class C, class Immovable>
void check_per_particle_equivalence(std::size_t n, int steps, Immovable immovable) {
  using R = typename C::real;
  using D = typename C::damping_policy;
  using P = typename C::position_policy;
  constexpr bool damped = !std::is_empty_v<typename D::template State<R>>;
  using System = std::conditional_t<
      damped,
      ParticleSystem<R, D, P, features::PerParticleDamping, features::PerParticleAcceleration,
                     features::ForceAccumulator>,
      ParticleSystem<R, D, P, features::PerParticleAcceleration, features::ForceAccumulator>>;
  std::mt19937 engine(7);
  std::uniform_real_distribution<R> damping(R(0), R(1));
  std::uniform_real_distribution<R> mass(R(0.25), R(4));

  System system(n);
  std::vector<Particle<R, D, P>> particles(n);
  std::size_t still = n;   // the first immovable particle
  std::size_t moving = n;  // the first movable one
  for (std::size_t i = 0; i < n; ++i) {
    auto& particle = particles[i];
    particle.set_position(random_vector(engine, R(100)));
    particle.set_velocity(random_vector(engine, R(30)));
    particle.set_acceleration(random_vector(engine, R(20)));
    if constexpr (damped) particle.set_damping(i % 9 == 0 ? R(1) : damping(engine));
    if (immovable(i)) {
      still = std::min(still, i);
      particle.set_inverse_mass(R(0));  // immovable
    } else {
      moving = std::min(moving, i);
      particle.set_mass(mass(engine));
    }
    particle.add_force(random_vector(engine, R(5)));  // carried into the system by spawn
    REQUIRE(system.spawn(particle) == i);
  }
  REQUIRE(matches(system, particles));
  REQUIRE(still < n);
  REQUIRE(moving < n);
  const Vector3<R> immovable_start = system.position(still);
  const Vector3<R> movable_start = system.position(moving);
  for (int step = 0; step < steps; ++step) {
    const R t = durations<R>[static_cast<std::size_t>(step) % durations<R>.size()];
    system.step(t);
    for (auto& particle : particles) particle.integrate(t);
    REQUIRE(matches(system, particles));
    for (std::size_t i = 0; i < n; ++i) {
      REQUIRE(system.force_accumulator(i) == Vector3<R>{});  // cleared by the step
      const Vector3<R> force = random_vector(engine, R(5));
      system.add_force(i, force);
      particles[i].add_force(force);
    }
  }
  CHECK(same_bits(system.position(still), immovable_start));  // inverse mass 0: never moved
  CHECK_FALSE(system.position(moving) == movable_start);
}

}  // namespace

TEST_CASE_TEMPLATE_DEFINE(
    "per-particle damping, acceleration, mass and forces: system == Particles, bit for bit", C,
    per_particle_equivalence) {
  // Every sixth particle immovable: each block of 16 has one, so every step takes the loop
  // that selects between moving a particle and keeping it.
  check_per_particle_equivalence<C>(count, 40, [](std::size_t i) { return i % 6 == 0; });
}
TEST_CASE_TEMPLATE_APPLY(per_particle_equivalence, EveryPairFloatAndDouble);

TEST_CASE_TEMPLATE_DEFINE(
    "chunks of movable particles step without the select: system == Particles, bit for bit", C,
    movable_chunks_equivalence) {
  // 3,000 particles: the walk alternates (forwards: chunks of 1,024 particles, of which the
  // first holds immovable particles 17 and 40, past its first block, and the next two none;
  // backwards: chunks of 256), and particle 2,995 is immovable in the remainder after the
  // last whole block. The chunks with no immovable particle take the loop without the select.
  check_per_particle_equivalence<C>(3000, 6,
                                    [](std::size_t i) { return i == 17 || i == 40 || i == 2995; });
}
TEST_CASE_TEMPLATE_APPLY(movable_chunks_equivalence, EveryPairFloatAndDouble);

TEST_CASE_TEMPLATE(
    "an inverse mass of NaN or -0 written through its column keeps the particle "
    "in place among movable ones",
    R, float, double) {
  // The column is the user's to write; a step moves only particles whose inverse mass is
  // > 0, whatever chunk they are in. 2,048 particles: two whole chunks.
  using System = ParticleSystem<R, damping::PerSecond, position::Euler,
                                features::PerParticleAcceleration, features::ForceAccumulator>;
  std::mt19937 engine(11);
  System system(2048);
  for (std::size_t i = 0; i < 2048; ++i) {
    system.spawn(random_vector(engine, R(100)), random_vector(engine, R(30)));
    system.set_acceleration(i, random_vector(engine, R(20)));
  }
  const auto inverse_mass = system.template column<Column::inverse_mass>();
  inverse_mass[100] = std::numeric_limits<R>::quiet_NaN();
  inverse_mass[1500] = -R(0);
  const System before = system;
  for (int step = 0; step < 3; ++step) system.step(R(1) / R(60));
  for (const std::size_t i : {std::size_t{100}, std::size_t{1500}}) {
    CHECK(same_bits(system.position(i), before.position(i)));
    CHECK(same_bits(system.velocity(i), before.velocity(i)));
  }
  CHECK_FALSE(system.position(101) == before.position(101));
  CHECK_FALSE(system.position(1501) == before.position(1501));
}

TEST_CASE_TEMPLATE("the step kernel over one index is the step", R, float, double) {
  using System = ParticleSystem<R, damping::PerSecond, position::ConstantAcceleration,
                                features::PerParticleAcceleration, features::Lifetime>;
  std::mt19937 engine(3);
  System stepped(40);
  for (int i = 0; i < 40; ++i) {
    const std::size_t index =
        stepped.spawn(random_vector(engine, R(10)), random_vector(engine, R(10)));
    stepped.set_acceleration(index, random_vector(engine, R(10)));
    stepped.set_lifetime(index, R(0.05) * R(i + 1));
  }
  stepped.set_damping(R(0.5));
  System by_index = stepped;
  for (int step = 0; step < 10; ++step) {
    stepped.step(R(0.1));
    // What another engine's loop would do: the kernel for each i, then expiry on the host.
    auto view = by_index.begin_step(R(0.1));
    REQUIRE(view.size() == by_index.size());
    for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);
    by_index.finish_step(std::move(view));
    REQUIRE(stepped.size() == by_index.size());
    for (std::size_t i = 0; i < stepped.size(); ++i) {
      REQUIRE(same_bits(stepped.position(i), by_index.position(i)));
      REQUIRE(same_bits(stepped.velocity(i), by_index.velocity(i)));
      REQUIRE(same_bits(stepped.age(i), by_index.age(i)));
    }
  }
  CHECK(stepped.size() < 40);  // some expired, so the comparison covered expiry
}

TEST_CASE_TEMPLATE(
    "per-particle d^t kept across steps of one length: set_damping, spawn, kill, a new length, "
    "a copy and a loop of one's own all stay the Particles' bit for bit",
    S, ParticleSystem<float, damping::PerSecond, position::Euler, features::PerParticleDamping>,
    ParticleSystem<double, damping::PerSecond, position::ConstantAcceleration,
                   features::PerParticleDamping, features::ForceAccumulator>,
    ParticleSystem<float, damping::AccelerateThenDamp, position::Euler,
                   features::PerParticleDamping, features::PerParticleAcceleration>) {
  using R = typename S::real;
  using Body = typename S::particle_type;
  static_assert(S::template stores<Column::damping_retention>);
  std::mt19937 engine(11);
  std::uniform_real_distribution<R> damping(R(0.05), R(1));
  S system(8);
  std::vector<Body> particles;
  const auto add = [&] {
    Body particle;
    particle.set_position(random_vector(engine, R(50)));
    particle.set_velocity(random_vector(engine, R(20)));
    particle.set_damping(damping(engine));
    if constexpr (S::template has<pointmass::features::PerParticleAcceleration>)
      particle.set_acceleration({R(0), R(-9.81), R(0)});
    REQUIRE(system.spawn(particle) == particles.size());
    particles.push_back(particle);
  };
  const auto step_both = [&](R t) {
    system.step(t);
    for (auto& particle : particles) particle.integrate(t);
    REQUIRE(matches(system, particles));
  };
  // The kept column holds each particle's d^t for the last length, as the policy gives it.
  const auto holds_factors_for = [&](R t) {
    for (std::size_t i = 0; i < system.size(); ++i) {
      const typename S::damping_policy::template State<R> state(system.damping(i));
      if (!same_bits(system.template column<Column::damping_retention>()[i],
                     S::damping_policy::factors(state, t).kept)) {
        return false;
      }
    }
    return true;
  };
  for (int n = 0; n < 40; ++n) add();
  const R fixed = R(1) / R(60);
  for (int k = 0; k < 3; ++k) step_both(fixed);
  CHECK(holds_factors_for(fixed));
  // A new damping between steps of the same length.
  for (std::size_t i = 0; i < system.size(); i += 3) {
    const R d = damping(engine);
    system.set_damping(i, d);
    particles[i].set_damping(d);
  }
  CHECK(holds_factors_for(fixed));
  step_both(fixed);
  // Spawned and killed between steps of the same length.
  for (int n = 0; n < 5; ++n) add();
  system.kill(2);
  particles[2] = particles.back();
  particles.pop_back();
  step_both(fixed);
  // Another length, then back.
  step_both(R(1) / R(30));
  CHECK(holds_factors_for(R(1) / R(30)));
  step_both(fixed);
  // A copy keeps going as the original.
  S copy = system;
  copy.step(fixed);
  system.step(fixed);
  for (auto& particle : particles) particle.integrate(fixed);
  REQUIRE(matches(copy, particles));
  REQUIRE(matches(system, particles));
  // A loop of one's own with another length (the device route), then finish_step: the next
  // step of the old length must not trust the column.
  const R other = R(1) / R(45);
  auto view = system.begin_step(other);
  REQUIRE(view.size() == system.size());
  for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);
  system.finish_step(std::move(view));
  for (auto& particle : particles) particle.integrate(other);
  REQUIRE(matches(system, particles));
  step_both(fixed);
  step_both(fixed);
}
