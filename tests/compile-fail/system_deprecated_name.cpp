// SPDX-License-Identifier: BSL-1.0
// A name of 0.1 still compiles for one minor version, with a warning naming its replacement
// (an error under the project's -Werror).
// expected-error: pointmass 0.2: use column<Column::position_x>()
#include <pointmass/particle_system.hpp>

int main() {
  pointmass::ParticleSystem<float> system;
  return static_cast<int>(system.position_x().size());
}
