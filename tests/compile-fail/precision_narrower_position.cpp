// SPDX-License-Identifier: BSL-1.0
// Positions stored narrower than the arithmetic (double velocities, float positions): one
// sentence names the combinations that work.
// expected-error: Precision<Real, Position>: the position must be a Real at least as wide as Real (Precision<float, double>) or Compensated<Real> of the same Real
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<pointmass::Precision<double, float>> particle;
  particle.integrate(1.0);
}
