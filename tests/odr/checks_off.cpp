// SPDX-License-Identifier: BSL-1.0
// The other translation unit of the mixed-settings program: hot-path checks off. The same
// calls as in checks_on.cpp must be accepted (a negative step runs backwards in time).
#define POINTMASS_DISABLE_CHECKS 1
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include <stdexcept>

#include "odr.hpp"

bool rejects_with_checks_off() {
  pointmass::Particle<float> particle;
  pointmass::ParticleSystem<float> system;
  system.spawn({}, {});
  try {
    particle.integrate(-1.0f);
    system.step(-1.0f);
  } catch (const std::invalid_argument&) {
    return true;
  }
  return false;
}
