// SPDX-License-Identifier: BSL-1.0
// A force added to a temporary particle would be lost with it: update_force takes a named
// particle, or a temporary view or adapter (relative_to, SoaBodies), whose forces land in the
// storage it refers to; a temporary particle gets one sentence.
// expected-error: this body is a temporary, so the force added to it would be lost
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

int main() {
  pointmass::forces::Drag<float> drag(0.4f, 0.1f);
  pointmass::forces::update_force(drag, pointmass::Particle<float>{}, 1.0f / 60);
}
