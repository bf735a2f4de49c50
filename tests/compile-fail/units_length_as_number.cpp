// SPDX-License-Identifier: BSL-1.0
// A length is not a number: `.value()` gives its number of metres (docs/units.md). The error
// is Boost.Units' own (a quantity has no conversion to its value type); this pins that it
// stays an error, in each compiler's wording.
// expected-error: cannot convert 'pointmass::units::length
// expected-error: cannot convert ‘pointmass::units::length
// expected-error: cannot convert 'boost::units::quantity
// expected-error: cannot convert ‘boost::units::quantity
// expected-error: no viable conversion from
#include <pointmass/units.hpp>

int main() {
  pointmass::units::Particle<double> particle;
  const double y = particle.position().y;
  return y > 0.0 ? 1 : 0;
}
