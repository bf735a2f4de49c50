// SPDX-License-Identifier: BSL-1.0
// damping::None stores no damping value: a system's set_damping says so, as a Particle's does.
// expected-error: damping::None damps nothing
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float, pointmass::damping::None> sparks;
  sparks.set_damping(0.5f);
}
