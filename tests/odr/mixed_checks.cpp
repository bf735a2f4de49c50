// SPDX-License-Identifier: BSL-1.0
// A program with the checks on hands a ParticleSystem to a unit built with them off: both name
// one type, so the program links, and the step the other unit takes is this unit's to read.
#define POINTMASS_ENABLE_CHECKS 1
#include <cmath>
#include <cstdio>

#include "odr.hpp"

int main() {
  pointmass::ParticleSystem<float> system;
  system.set_acceleration({0.0f, -10.0f, 0.0f});
  system.spawn({1.0f, 2.0f, 3.0f}, {4.0f, 0.0f, 0.0f});
  released_step(system, 0.5f);
  const auto v = system.velocity(0);
  const auto p = system.position(0);
  std::printf("after the released step: p = (%g, %g, %g), v = (%g, %g, %g)\n",
              static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z),
              static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
  // Euler (the default position policy) moves by the old velocity; damping d per second
  // multiplies the new one by d^0.5.
  const double kept = std::pow(static_cast<double>(system.damping()), 0.5);
  const auto near = [](float x, double expected) {
    return std::abs(static_cast<double>(x) - expected) <= 1e-6 * (1.0 + std::abs(expected));
  };
  const bool moved = near(p.x, 3.0) && near(p.y, 2.0) && near(p.z, 3.0);
  const bool accelerated = near(v.x, 4.0 * kept) && near(v.y, -5.0 * kept) && near(v.z, 0.0);
  if (moved && accelerated) std::printf("odr: ok\n");
  return moved && accelerated ? 0 : 1;
}
