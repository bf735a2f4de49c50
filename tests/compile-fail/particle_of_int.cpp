// SPDX-License-Identifier: BSL-1.0
// A Real that is not float, double or long double (nor a Precision of one): the first
// argument must satisfy PrecisionChoice (a Real, or Precision<R, Position>).
// expected-error: PrecisionChoice
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<int> particle;
  particle.integrate(1);
}
