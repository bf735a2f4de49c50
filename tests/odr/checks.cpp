// SPDX-License-Identifier: BSL-1.0
// The released library of the mixed-checks program: hot-path checks off (as with NDEBUG).
#define POINTMASS_DISABLE_CHECKS 1
#include "odr.hpp"

void released_step(pointmass::ParticleSystem<float>& system, float duration) {
  system.step(duration);
}
