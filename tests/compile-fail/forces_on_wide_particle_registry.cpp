// SPDX-License-Identifier: BSL-1.0
// A registry of particles with positions stored wider than their arithmetic (precision.hpp)
// meets the same sentence as update_force on such a particle: a generator reaches them through
// forces::relative_to(particle, origin) (docs/large-worlds.md: forces on wide positions).
// expected-error: pass forces::relative_to(particle, origin)
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

int main() {
  using Shell = pointmass::Particle<pointmass::Precision<float, double>>;
  pointmass::forces::ForceRegistry<Shell, pointmass::forces::Drag<float>> registry;
  Shell shell;
  registry.emplace<pointmass::forces::Drag<float>>(shell, 0.1f, 0.01f);
  registry.update_forces(1.0f / 60);
}
