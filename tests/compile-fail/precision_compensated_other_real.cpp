// SPDX-License-Identifier: BSL-1.0
// A compensated position of another Real than the arithmetic's (float velocities, a pair of
// doubles for the position) in a system: the same sentence.
// expected-error: Precision<Real, Position>: the position must be a Real at least as wide as Real (Precision<float, double>) or Compensated<Real> of the same Real
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<pointmass::Precision<float, pointmass::Compensated<double>>> system;
  system.step(1.0f);
}
