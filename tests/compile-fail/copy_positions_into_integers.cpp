// SPDX-License-Identifier: BSL-1.0
// Positions copied into a buffer of integers: an int cannot hold every position, and
// converting a float beyond its range is undefined behaviour, so copy_positions takes
// floating-point buffers only (and vectors whose members are floating-point numbers).
// expected-error: floating_point
#include <pointmass/particle_system.hpp>

#include <span>
#include <vector>

int main() {
  pointmass::ParticleSystem<float> system;
  system.spawn({1e20f, 0, 0}, {});
  std::vector<int> pixels(3);
  system.copy_positions(std::span<int>(pixels));
}
