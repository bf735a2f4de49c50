// SPDX-License-Identifier: BSL-1.0
// One translation unit of the mixed-settings program: hot-path checks on.
#define POINTMASS_ENABLE_CHECKS 1
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include <stdexcept>

#include "odr.hpp"

bool rejects_with_checks_on() {
  pointmass::Particle<float> particle;
  pointmass::ParticleSystem<float> system;
  system.spawn({}, {});
  bool rejected = false;
  try {
    particle.integrate(-1.0f);
  } catch (const std::invalid_argument&) {
    rejected = true;
  }
  try {
    system.step(-1.0f);
    rejected = false;
  } catch (const std::invalid_argument&) {
  }
  return rejected;
}
