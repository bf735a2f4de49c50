// SPDX-License-Identifier: BSL-1.0
// The step's traversal. While the arrays take more than alternation_floor_bytes and at most
// alternation_limit_bytes, successive steps walk the particles forwards and backwards in
// turn (backwards: the part past the last whole chunk first, then whole chunks of
// backward_chunk from the last to the first); otherwise every step walks forwards. Either
// way every particle takes exactly its own step once: the system matches the equivalent
// Particles bit for bit after every step, for sizes around the vector block and the chunk
// (step_range_backward directly), and on both sides of both bounds (step).
#include <doctest/doctest.h>

#include <cstddef>
#include <random>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

namespace {

using namespace pointmass;
using pointmass::test::matches;
using pointmass::test::random_vector;
using pointmass::test::same_bits;

enum class Walk { by_step_alternating, by_step_forwards, backward_only };

// Steps a system of `count` particles and the equivalent Particles `steps` times, by `step`
// or by step_range_backward alone; checks after each step that they match and, with `step`,
// that the walk's direction alternates (or not). With forces, every particle has its own mass
// and a new force of its own every step; with lifetimes, its own lifetime, so that particles
// expire over the steps: each particle's state, age and lifetime must stay its own.
template <class R, class D, class P, class... Features>
void step_side_by_side(std::size_t count, int steps, Walk walk) {
  using System = ParticleSystem<R, D, P, Features...>;
  CAPTURE(count);
  std::mt19937 engine(static_cast<unsigned>(count));
  const Vector3<R> gravity{R(0), R(-9.807), R(0)};
  System system(count);
  if constexpr (!System::template has<pointmass::features::PerParticleAcceleration>)
    system.set_acceleration(gravity);
  if constexpr (System::stores_damping &&
                !System::template has<pointmass::features::PerParticleDamping>) {
    system.set_damping(R(0.6));
  }
  std::vector<Particle<R, D, P>> particles(count);
  std::uniform_real_distribution<R> damping(R(0.1), R(1));
  std::uniform_real_distribution<R> mass(R(0.5), R(4));
  // Lifetimes from 0.01 s (the first step expires some) to beyond the run (some survive it).
  std::uniform_real_distribution<R> lifetime(R(0.01), R(steps) / R(50));
  std::size_t rejected = 0;
  for (auto& particle : particles) {
    particle.set_position(random_vector(engine, R(100)));
    particle.set_velocity(random_vector(engine, R(30)));
    if constexpr (System::template has<pointmass::features::PerParticleAcceleration>) {
      particle.set_acceleration(random_vector(engine, R(20)));
    } else {
      particle.set_acceleration(gravity);
    }
    if constexpr (System::template has<pointmass::features::PerParticleDamping>) {
      particle.set_damping(damping(engine));
    } else if constexpr (System::stores_damping) {
      particle.set_damping(R(0.6));
    }
    if constexpr (System::template has<pointmass::features::ForceAccumulator>)
      particle.set_mass(mass(engine));
    rejected += system.spawn(particle) == System::npos ? 1 : 0;
  }
  REQUIRE(rejected == 0);
  REQUIRE(matches(system, particles));
  // The lifetimes of particles[k] and of the system's particle k (until a step expires some).
  std::vector<R> lifetimes(count, real_infinity<R>);
  if constexpr (System::template has<pointmass::features::Lifetime>) {
    for (std::size_t i = 0; i < count; ++i) {
      lifetimes[i] = lifetime(engine);
      system.set_lifetime(i, lifetimes[i]);
    }
  }
  R age = R(0);  // every particle's: they were spawned together
  for (int step = 0; step < steps; ++step) {
    CAPTURE(step);
    const R t = R(1) / R(60 + step);
    if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
      for (std::size_t i = 0; i < system.size(); ++i) {
        const Vector3<R> force = random_vector(engine, R(5));
        system.add_force(i, force);
        particles[i].add_force(force);
      }
    }
    if (walk == Walk::backward_only) {
      auto view = system.begin_step(t);
      pointmass::detail::SystemAccess::Kernel<System>::step_range_backward(
          view.arrays(), 0, view.size(), view.parameters());
      system.finish_step(std::move(view));
    } else {
      CHECK(pointmass::detail::SystemAccess::next_step_backward(system) ==
            (walk == Walk::by_step_alternating && step % 2 == 1));
      system.step(t);
    }
    for (auto& particle : particles) particle.integrate(t);
    if constexpr (System::template has<pointmass::features::Lifetime>) {
      // Expiry reorders the survivors: find each of the system's particles by its position's
      // bits among the Particles, and check it is one that should survive, in full.
      age += t;
      std::vector<Particle<R, D, P>> survivors;
      std::vector<R> survivors_lifetimes;
      std::vector<bool> taken(particles.size(), false);
      for (std::size_t i = 0; i < system.size(); ++i) {
        CAPTURE(i);
        std::size_t k = 0;
        while (k < particles.size() && !same_bits(system.position(i), particles[k].position())) {
          ++k;
        }
        REQUIRE(k < particles.size());
        REQUIRE_FALSE(taken[k]);
        taken[k] = true;
        CHECK(same_bits(system.lifetime(i), lifetimes[k]));
        CHECK(same_bits(system.age(i), age));
        CHECK(age < lifetimes[k]);
        survivors.push_back(particles[k]);
        survivors_lifetimes.push_back(lifetimes[k]);
      }
      std::size_t expected_survivors = 0;
      for (const R l : lifetimes) expected_survivors += age < l ? 1 : 0;
      REQUIRE(system.size() == expected_survivors);
      particles = std::move(survivors);
      lifetimes = std::move(survivors_lifetimes);
    }
    REQUIRE(matches(system, particles));
  }
  if constexpr (System::template has<pointmass::features::Lifetime>) {
    CHECK(system.size() > 0);      // some lived through the run,
    CHECK(system.size() < count);  // and some expired in it
  }
}

}  // namespace

TEST_CASE_TEMPLATE("backward walk: every particle takes its own step, once", R, float, double) {
  using System = ParticleSystem<R>;
  static_assert(pointmass::detail::SystemAccess::Kernel<System>::backward_chunk %
                    pointmass::detail::SystemAccess::Kernel<System>::vector_block ==
                0);
  constexpr std::size_t chunk = pointmass::detail::SystemAccess::Kernel<System>::backward_chunk;
  for (const std::size_t count : {std::size_t{1}, std::size_t{15}, std::size_t{16}, chunk - 1,
                                  chunk, chunk + 1, 3 * chunk + 17, std::size_t{1000}}) {
    step_side_by_side<R, damping::PerSecond, position::Euler>(count, 3, Walk::backward_only);
  }
}

TEST_CASE_TEMPLATE("alternating walk with per-particle values, forces and lifetimes", R, float,
                   double) {
  using Featured = ParticleSystem<R, damping::Exact, position::Exact, features::PerParticleDamping,
                                  features::PerParticleAcceleration, features::ForceAccumulator,
                                  features::Lifetime>;
  constexpr std::size_t count =
      2 * pointmass::detail::SystemAccess::Kernel<Featured>::alternation_floor_bytes /
          Featured::storage_bytes_per_particle +
      pointmass::detail::SystemAccess::Kernel<Featured>::backward_chunk / 2;
  REQUIRE(pointmass::detail::SystemAccess::Kernel<Featured>::alternates(count));
  step_side_by_side<R, damping::Exact, position::Exact, features::PerParticleDamping,
                    features::PerParticleAcceleration, features::ForceAccumulator,
                    features::Lifetime>(count, 4, Walk::by_step_alternating);
  step_side_by_side<R, damping::PerFrame, position::SemiImplicit,
                    features::PerParticleAcceleration>(531, 3, Walk::backward_only);
}

TEST_CASE_TEMPLATE("the walk alternates between its size bounds and walks forwards outside them", R,
                   float, double) {
  using System = ParticleSystem<R>;
  constexpr std::size_t bytes = System::storage_bytes_per_particle;
  constexpr std::size_t smallest =
      pointmass::detail::SystemAccess::Kernel<System>::alternation_floor_bytes / bytes + 1;
  constexpr std::size_t largest =
      pointmass::detail::SystemAccess::Kernel<System>::alternation_limit_bytes / bytes;
  CHECK_FALSE(pointmass::detail::SystemAccess::Kernel<System>::alternates(smallest - 1));
  CHECK(pointmass::detail::SystemAccess::Kernel<System>::alternates(smallest));
  CHECK(pointmass::detail::SystemAccess::Kernel<System>::alternates(largest));
  CHECK_FALSE(pointmass::detail::SystemAccess::Kernel<System>::alternates(largest + 1));
  using PerSecondEuler = void (*)(std::size_t, int, Walk);
  const PerSecondEuler check = step_side_by_side<R, damping::PerSecond, position::Euler>;
  check(smallest - 1, 3, Walk::by_step_forwards);
  check(smallest, 3, Walk::by_step_alternating);
  check(largest, 3, Walk::by_step_alternating);
  check(largest + 1, 3, Walk::by_step_forwards);
}

TEST_CASE_TEMPLATE("a copy starts forwards, a move or swap takes the direction along", R, float,
                   double) {
  using System = ParticleSystem<R>;
  constexpr std::size_t count =
      2 * pointmass::detail::SystemAccess::Kernel<System>::alternation_floor_bytes /
      System::storage_bytes_per_particle;
  REQUIRE(pointmass::detail::SystemAccess::Kernel<System>::alternates(count));
  System system(count);
  std::mt19937 engine(3);
  for (std::size_t i = 0; i < count; ++i) {
    system.spawn(random_vector(engine, R(10)), random_vector(engine, R(1)));
  }
  system.step(R(1) / R(60));
  REQUIRE(pointmass::detail::SystemAccess::next_step_backward(system));

  const System copy(system);
  CHECK_FALSE(pointmass::detail::SystemAccess::next_step_backward(copy));

  System other;
  other.swap(system);
  CHECK(pointmass::detail::SystemAccess::next_step_backward(other));
  CHECK_FALSE(pointmass::detail::SystemAccess::next_step_backward(system));

  const System moved(std::move(other));
  CHECK(pointmass::detail::SystemAccess::next_step_backward(moved));
  CHECK_FALSE(pointmass::detail::SystemAccess::next_step_backward(
      other));  // NOLINT(bugprone-use-after-move): reset by the move
}
