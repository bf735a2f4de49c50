// SPDX-License-Identifier: BSL-1.0
// Force generators compute in the arithmetic's type: a system with positions stored wider
// (precision.hpp) reaches them through forces::relative_to(system, origin), and apply on the
// system itself says so in one sentence (docs/large-worlds.md: forces on wide positions).
// expected-error: pass forces::relative_to(bodies, origin)
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

int main() {
  using Sparks =
      pointmass::ParticleSystem<pointmass::Precision<float, double>, pointmass::damping::PerSecond,
                                pointmass::position::Euler, pointmass::features::ForceAccumulator>;
  Sparks sparks;
  sparks.spawn({1e6, 0.0, 0.0}, {1.0f, 0.0f, 0.0f});
  const pointmass::forces::Drag<float> drag(0.1f, 0.01f);
  pointmass::forces::apply(drag, sparks, 1.0f / 60);
}
