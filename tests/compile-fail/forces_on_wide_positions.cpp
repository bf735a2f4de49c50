// SPDX-License-Identifier: BSL-1.0
// Force generators act on bodies whose positions are in the arithmetic's type: a system with
// positions stored wider (precision.hpp) is not `forces::Bodies`, and apply says so
// (docs/large-worlds.md: forces on wide positions).
// expected-error: does not satisfy return-type-requirement
// expected-error: does not satisfy 'Bodies'
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

int main() {
  using Sparks = pointmass::ParticleSystem<pointmass::Precision<float, double>,
                                           pointmass::damping::PerSecond,
                                           pointmass::position::Euler,
                                           pointmass::features::ForceAccumulator>;
  Sparks sparks;
  sparks.spawn({1e6, 0.0, 0.0}, {1.0f, 0.0f, 0.0f});
  const pointmass::forces::Drag<float> drag(0.1f, 0.01f);
  pointmass::forces::apply(drag, sparks, 1.0f / 60);
}
