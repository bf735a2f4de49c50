// SPDX-License-Identifier: BSL-1.0
// ForceRegistry::add keeps a pointer: a temporary generator would dangle at once. The owning
// form (add_owned, emplace) is the way to hand the registry a generator to keep.
// expected-error: use add_owned
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<double> particle;
  pointmass::forces::ForceRegistry<pointmass::Particle<double>> registry;
  registry.add(particle, pointmass::forces::Drag<double>(0.1, 0.0));
}
