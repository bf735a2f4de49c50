// SPDX-License-Identifier: BSL-1.0
// An acceleration added as a force.
// expected-error: add_force: wrong dimension
#include <pointmass/units.hpp>

namespace si = boost::units::si;

int main() {
  pointmass::units::Particle<float> particle;
  particle.add_force(pointmass::Vector3<float>{0.0f, -9.807f, 0.0f} *
                     si::meters_per_second_squared);
}
