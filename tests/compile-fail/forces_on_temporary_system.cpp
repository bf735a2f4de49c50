// SPDX-License-Identifier: BSL-1.0
// Forces added to a temporary system would be lost with it: apply takes a named system, or a
// temporary view or adapter (relative_to, SoaBodies); a temporary system gets one sentence.
// expected-error: these bodies are a temporary, so the forces added to them would be lost
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

using Sparks =
    pointmass::ParticleSystem<float, pointmass::damping::PerSecond, pointmass::position::Euler,
                              pointmass::features::ForceAccumulator>;

int main() {
  const pointmass::forces::Drag<float> drag(0.4f, 0.1f);
  pointmass::forces::apply(drag, Sparks(4), 1.0f / 60);
}
