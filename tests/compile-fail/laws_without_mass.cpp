// SPDX-License-Identifier: BSL-1.0
// A law's force needs each particle's mass: a system without features::ForceAccumulator has
// none, and a step with laws says so in one sentence.
// expected-error: laws need each particle's mass; add features::ForceAccumulator
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float> sparks(4);
  const pointmass::forces::Drag<float> drag(0.4f, 0.1f);
  sparks.step(1.0f / 60, pointmass::forces::laws(drag));
}
