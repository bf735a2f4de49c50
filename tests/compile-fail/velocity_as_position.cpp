// SPDX-License-Identifier: BSL-1.0
// A velocity given where a position belongs.
// expected-error: set_position: wrong dimension
#include <pointmass/units.hpp>

namespace si = boost::units::si;

int main() {
  pointmass::units::Particle<double> particle;
  particle.set_position(pointmass::Vector3<double>{0.0, 30.0, 40.0} * si::meters_per_second);
}
