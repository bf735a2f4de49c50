// SPDX-License-Identifier: BSL-1.0
// A particle with its position stored wider than its arithmetic (precision.hpp) reaches a
// generator through forces::relative_to(particle, origin); update_force on the particle itself
// says so in one sentence (docs/large-worlds.md: forces on wide positions).
// expected-error: pass forces::relative_to(particle, origin)
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<pointmass::Precision<float, pointmass::Compensated<float>>> shell;
  shell.set_position({1e6, 0.0, 0.0});
  pointmass::forces::AnchoredSpring<float> spring({0.0f, 0.0f, 0.0f}, 10.0f, 1.0f);
  pointmass::forces::update_force(spring, shell, 1.0f / 60);
}
