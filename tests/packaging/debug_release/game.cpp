// SPDX-License-Identifier: BSL-1.0
#ifdef NDEBUG
#error "the game must be built without NDEBUG"
#endif
#include <cmath>
#include <cstdio>

#include "engine.hpp"

int main() {
  static_assert(POINTMASS_CHECKS == 1, "the game checks");
  pointmass::ParticleSystem<float> particles;
  particles.set_acceleration({0.0f, -10.0f, 0.0f});
  particles.spawn({0.0f, 100.0f, 0.0f}, {2.0f, 0.0f, 0.0f});
  for (int frame = 0; frame < 60; ++frame) engine_update(particles, 1.0f / 60.0f);
  // 60 steps of the default policies: it moved right and fell, and is still finite.
  const auto p = particles.position(0);
  const bool flew = p.x > 1.9f && p.x < 2.0f && p.y < 95.5f && p.y > 94.0f && p.z == 0.0f;
  std::printf("after one second: (%g, %g, %g)\n", static_cast<double>(p.x),
              static_cast<double>(p.y), static_cast<double>(p.z));
  if (flew) std::printf("debug_release: ok\n");
  return flew ? 0 : 1;
}
