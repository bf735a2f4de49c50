// SPDX-License-Identifier: BSL-1.0
// Double quantities given to a float particle.
// expected-error: of another Real than the particle's
#include <pointmass/units.hpp>

namespace si = boost::units::si;

int main() {
  pointmass::units::Particle<float> particle;
  particle.set_position(pointmass::Vector3<double>{0.0, 1.5, 0.0} * si::meters);
}
