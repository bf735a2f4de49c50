// SPDX-License-Identifier: BSL-1.0
// A step view is handed back once: it moves and does not copy.
// expected-error: use of deleted function
// expected-error: call to deleted constructor of
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float> system;
  auto view = system.begin_step(0.5f);
  auto copy = view;
  system.finish_step(std::move(copy));
  return 0;
}
