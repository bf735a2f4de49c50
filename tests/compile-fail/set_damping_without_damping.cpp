// SPDX-License-Identifier: BSL-1.0
// damping::None stores no damping value: set_damping says so, and names the policies that do.
// expected-error: set_damping: this damping policy has no damping value to set
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<float, pointmass::damping::None> particle;
  particle.set_damping(0.99f);
}
