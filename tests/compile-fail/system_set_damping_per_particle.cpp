// SPDX-License-Identifier: BSL-1.0
// With per-particle damping there is no damping for all: set_damping(d) says so, in a sentence.
// expected-error: with features::PerParticleDamping, set_damping(i, d)
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float, pointmass::damping::PerSecond, pointmass::position::Euler,
                            pointmass::features::PerParticleDamping>
      sparks;
  sparks.set_damping(0.5f);
}
