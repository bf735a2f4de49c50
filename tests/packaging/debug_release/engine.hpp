// SPDX-License-Identifier: BSL-1.0
#pragma once
#include <pointmass/particle_system.hpp>

// Built with NDEBUG.
void engine_update(pointmass::ParticleSystem<float>& particles, float duration);
