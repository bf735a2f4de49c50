// SPDX-License-Identifier: BSL-1.0
// A duration in metres.
// expected-error: integrate: wrong dimension
#include <pointmass/units.hpp>

namespace si = boost::units::si;

int main() {
  pointmass::units::Particle<double> particle;
  particle.integrate(0.033 * si::meters);
}
