// SPDX-License-Identifier: BSL-1.0
#ifndef NDEBUG
#error "the engine must be built with NDEBUG"
#endif
#include "engine.hpp"

void engine_update(pointmass::ParticleSystem<float>& particles, float duration) {
  particles.step(duration);
}
