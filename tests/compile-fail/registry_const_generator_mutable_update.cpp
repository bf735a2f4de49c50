// SPDX-License-Identifier: BSL-1.0
// A const generator is accepted when its update_force can run on a const object; one whose
// update_force member is not const is refused with one sentence saying what to change.
// expected-error: its update_force member is not: pass a non-const generator
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

struct Counter {
  int calls = 0;
  void update_force(pointmass::Particle<double>&, double) { ++calls; }
};

int main() {
  pointmass::Particle<double> particle;
  pointmass::forces::ForceRegistry<pointmass::Particle<double>> registry;
  const Counter counter;
  registry.add(particle, counter);
}
