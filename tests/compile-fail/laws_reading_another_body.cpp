// SPDX-License-Identifier: BSL-1.0
// A law fused into the step sees only the particle it acts on: a spring to another body reads
// that body's state, so it goes through the accumulator (update_force, apply_links) before the
// step; given as a law, it gets one sentence.
// expected-error: every law must be a force of one particle's own state
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

using Sparks =
    pointmass::ParticleSystem<float, pointmass::damping::PerSecond, pointmass::position::Euler,
                              pointmass::features::ForceAccumulator>;

int main() {
  Sparks sparks(4);
  const pointmass::Particle<float> anchor;
  const pointmass::forces::Spring<pointmass::Particle<float>> rope(anchor, 20.0f, 1.0f);
  sparks.step(1.0f / 60, pointmass::forces::laws(rope));
}
