// SPDX-License-Identifier: BSL-1.0
// A force given as an acceleration (gravity must be m/s^2, not N).
// expected-error: set_acceleration: wrong dimension
#include <pointmass/units.hpp>

namespace si = boost::units::si;

int main() {
  pointmass::units::Particle<double> particle;
  particle.set_acceleration(pointmass::Vector3<double>{0.0, -9.807, 0.0} * si::newtons);
}
