// SPDX-License-Identifier: BSL-1.0
// A plain number where a mass in kilograms belongs.
// expected-error: set_mass: wrong dimension
#include <pointmass/units.hpp>

int main() {
  pointmass::units::Particle<double> particle;
  particle.set_mass(2.0);
}
