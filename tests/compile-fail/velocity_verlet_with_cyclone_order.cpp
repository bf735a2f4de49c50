// SPDX-License-Identifier: BSL-1.0
// position::VelocityVerlet damps by the step's retention between its drifts: Cyclone's order of
// acceleration and damping (AccelerateThenDamp) is not a Verlet step. One sentence says so.
// expected-error: position::VelocityVerlet works with damping::None, PerSecond, PerFrame and Exact
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<float, pointmass::damping::AccelerateThenDamp,
                      pointmass::position::VelocityVerlet>
      particle;
  particle.integrate(0.1f);
}
