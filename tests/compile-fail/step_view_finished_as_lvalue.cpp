// SPDX-License-Identifier: BSL-1.0
// finish_step takes the view over (std::move(view)): a named view handed as it is does not
// bind, so a view cannot be finished and then still used by mistake.
// expected-error: cannot bind rvalue reference of type
// expected-error: no matching member function for call to 'finish_step'
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float> system;
  auto view = system.begin_step(0.5f);
  system.finish_step(view);
  return 0;
}
