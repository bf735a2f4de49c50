// SPDX-License-Identifier: BSL-1.0
// Test support for the force generators: a body in a given state, and the force one
// update_force call adds to it.
#pragma once

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

namespace pointmass::test {

/// A particle at p with velocity v and mass `mass`.
template <class R>
Particle<R> body_at(Vector3<R> p, Vector3<R> v = {}, R mass = R(1)) {
  Particle<R> particle;
  particle.set_position(p);
  particle.set_velocity(v);
  particle.set_mass(mass);
  return particle;
}

/// The force one update_force call, with step dt, adds to a copy of `particle`.
template <class G, class R>
Vector3<R> force_on(const G& generator, Particle<R> particle, R dt = R(1) / R(60)) {
  forces::update_force(generator, particle, dt);
  return particle.force_accumulator();
}

}  // namespace pointmass::test
