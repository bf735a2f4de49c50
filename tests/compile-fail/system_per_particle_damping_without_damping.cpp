// SPDX-License-Identifier: BSL-1.0
// Per-particle damping asked of a system whose damping policy has no damping value.
// expected-error: features::PerParticleDamping needs a damping policy with a damping value
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float, pointmass::damping::None, pointmass::position::Euler,
                            pointmass::features::PerParticleDamping>
      sparks;
  return static_cast<int>(sparks.size());
}
