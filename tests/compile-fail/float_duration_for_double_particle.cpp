// SPDX-License-Identifier: BSL-1.0
// A float duration given to a double particle (Boost.Units alone would widen it silently).
// expected-error: integrate: the argument's quantities are of another Real
#include <pointmass/units.hpp>

namespace si = boost::units::si;

int main() {
  pointmass::units::Particle<double> particle;
  particle.integrate(0.033f * si::seconds);
}
