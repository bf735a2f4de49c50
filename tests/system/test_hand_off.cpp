// SPDX-License-Identifier: BSL-1.0
// Positions handed to a renderer (system/hand_off.hpp): copy_positions packed, strided and into
// vectors with x, y, z members.
#include <doctest/doctest.h>

#include <cstddef>
#include <span>
#include <vector>

#include <pointmass/particle_system.hpp>

using namespace pointmass;

TEST_CASE("copy_positions: packed, strided and into vectors with x, y, z") {
  ParticleSystem<double> system;
  for (int n = 0; n < 10; ++n) system.spawn({double(n), n + 0.5, -n - 0.25}, {});
  struct Vertex {
    float x, y, z;
  };
  std::vector<Vertex> vertices(10);
  system.copy_positions(std::span<Vertex>(vertices));
  std::vector<float> strided(9 * 6 + 3, -1.0f);
  system.copy_positions(std::span<float>(strided), 6);
  for (std::size_t i = 0; i < 10; ++i) {
    const Vector3<float> expected{float(i), float(i) + 0.5f, -float(i) - 0.25f};
    CHECK(Vector3<float>{vertices[i].x, vertices[i].y, vertices[i].z} == expected);
    CHECK(Vector3<float>{strided[6 * i], strided[6 * i + 1], strided[6 * i + 2]} == expected);
    if (i < 9) CHECK(strided[6 * i + 3] == -1.0f);
  }
}
