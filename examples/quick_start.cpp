// SPDX-License-Identifier: BSL-1.0
#include <pointmass/pointmass.hpp>

#include <cstdio>

int main() {
  pointmass::Particle<float> shot;                   // per-second damping, p + v t
  shot.set_position({0.0f, 1.5f, 0.0f});             // m
  shot.set_velocity({0.0f, 30.0f, 40.0f});           // m/s
  shot.set_acceleration(pointmass::gravity(20.0f));  // (0, -20, 0) m/s^2
  shot.set_mass(200.0f);                             // kg
  shot.set_damping(0.99f);                           // 99% of the velocity kept per second
  for (int frame = 0; frame < 60; ++frame) shot.integrate(1.0f / 60);

  const auto p = shot.position();
  std::printf("after 1 s: x %.3f y %.3f z %.3f m\n", double(p.x), double(p.y), double(p.z));
}
