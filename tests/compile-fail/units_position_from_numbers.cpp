// SPDX-License-Identifier: BSL-1.0
// Plain numbers given to a particle of SI quantities: no unit. One sentence says how to give one.
// expected-error: set_position: plain numbers have no unit; give metres, as in pointmass::Vector3<double>{0, 1.5, 0} * si::meters
#include <pointmass/units.hpp>

int main() {
  pointmass::units::Particle<double> particle;
  particle.set_position({0.0, 1.5, 0.0});
}
