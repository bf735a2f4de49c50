// SPDX-License-Identifier: BSL-1.0
// Shared by the ParticleSystem tests: a reproducible scene of particles, bit-for-bit
// comparison of a system against the equivalent scalar Particles, and a user column's tag.
#pragma once

#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <vector>

#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>
#include <pointmass/vector3.hpp>

#include "ulp.hpp"  // same_bits

namespace pointmass::test {

/// A random vector with components in [-scale, scale] (never -0).
template <class R>
Vector3<R> random_vector(std::mt19937& engine, R scale) {
  std::uniform_real_distribution<R> component(-scale, scale);
  return {component(engine), component(engine), component(engine)};
}

/// Index of the particle of `system` whose bits equal `particle`'s position, velocity; true
/// when every particle of `system` has exactly the state of the particle at the same index.
template <class System, class Particle>
bool matches(const System& system, const std::vector<Particle>& particles) {
  if (system.size() != particles.size()) return false;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!same_bits(system.position(i), particles[i].position())) return false;
    if (!same_bits(system.velocity(i), particles[i].velocity())) return false;
  }
  return true;
}

/// The tag of a user column (features::Column<SpawnTag, T>) that holds each particle's spawn
/// number, by which a test follows the particle through removals.
struct SpawnTag {};

}  // namespace pointmass::test
