// SPDX-License-Identifier: BSL-1.0
// pointmass::gravity is a Vector3 of plain numbers; a particle of SI quantities wants
// pointmass::units::gravity, which the sentence names.
// expected-error: set_acceleration: plain numbers have no unit; give metres per second squared, as in pointmass::units::gravity<double>()
#include <pointmass/units.hpp>

int main() {
  pointmass::units::Particle<double> particle;
  particle.set_acceleration(pointmass::gravity(9.807));
}
