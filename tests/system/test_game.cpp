// SPDX-License-Identifier: BSL-1.0
// What a game needs of the batch: previous positions and interpolation, bursts and the
// renderer's copy-out; and that none of it costs a configuration that does not choose it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <pointmass/fixed_step.hpp>  // interpolate
#include <pointmass/gravity.hpp>
#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;
using pointmass::test::SpawnTag;

TEST_CASE("spawn_burst: count particles from a generator, reserving once") {
  using Painted =
      ParticleSystem<float, damping::None, position::Euler, features::Column<SpawnTag, int>>;
  Painted system;
  system.spawn({}, {}, -1);
  const std::size_t added = system.spawn_burst(1000, [](std::size_t k) {
    return std::tuple{Vector3<float>{float(k), 0, 0}, Vector3<float>{0, 1, 0}, int(k)};
  });
  CHECK(added == 1000);
  CHECK(system.size() == 1001);
  CHECK(system.capacity() == 1001);  // one reservation, to the count asked for
  for (std::size_t i = 1; i < system.size(); ++i) {
    CHECK(system.column<SpawnTag>(i) == int(i - 1));
    CHECK(system.position(i).x == float(i - 1));
  }
  // A generator of particles, into a system without columns.
  ParticleSystem<float> sparks;
  Particle<float> model;
  model.set_velocity({1, 2, 3});
  CHECK(sparks.spawn_burst(3, [&](std::size_t) { return model; }) == 3);
  CHECK(sparks.velocity(2) == Vector3<float>{1, 2, 3});
}

TEST_CASE_TEMPLATE("interpolation: alpha 0 is the previous position, 1 the current, bit for bit", R,
                   float, double) {
  // ConstantAcceleration: its last addition (a t^2 / 2) leaves positions off the grid of the previous ones.
  using Drawn = ParticleSystem<R, damping::PerSecond, position::ConstantAcceleration,
                               features::Interpolation>;
  std::mt19937 random(5);
  Drawn system;
  system.set_acceleration(gravity<R>());
  system.set_damping(R(0.9));
  for (int n = 0; n < 100; ++n) {
    system.spawn(test::random_vector<R>(random, R(1000)), test::random_vector<R>(random, R(50)));
  }
  system.spawn({-R(0), R(0), -R(0)}, {});  // signed zeros must come back as they are
  // Large steps that end near 0: previous + (current - previous) rounds away from current.
  for (const R start : {R(1000.3), R(-77.7), R(123456.7)}) {
    system.spawn({start, -start, start},
                 {-start * R(60) * R(0.999987), start * R(60) * R(0.99993), -start * R(59.99)});
  }
  for (int frame = 0; frame < 3; ++frame) {
    std::vector<Vector3<R>> before;
    for (std::size_t i = 0; i < system.size(); ++i) before.push_back(system.position(i));
    system.step(R(1) / R(60));
    std::vector<R> packed(system.size() * 3), interleaved(system.size() * 5, R(-7));
    for (const R alpha : {R(0), R(1)}) {
      system.copy_interpolated_positions(alpha, std::span<R>(packed));
      system.copy_interpolated_positions(alpha, std::span<R>(interleaved).subspan(1), 5);
      for (std::size_t i = 0; i < system.size(); ++i) {
        const Vector3<R> expected = alpha > R(0) ? system.position(i) : before[i];
        CHECK(same_bits(system.previous_position(i), before[i]));
        CHECK(same_bits(system.interpolated_position(i, alpha), expected));
        CHECK(same_bits(Vector3<R>{packed[3 * i], packed[3 * i + 1], packed[3 * i + 2]}, expected));
        CHECK(same_bits(
            Vector3<R>{interleaved[5 * i + 1], interleaved[5 * i + 2], interleaved[5 * i + 3]},
            expected));
        CHECK(interleaved[5 * i] == R(-7));  // the other attributes are left alone
        CHECK(interleaved[5 * i + 4] == R(-7));
      }
    }
    // Half way: between the two, at the midpoint up to rounding.
    for (std::size_t i = 0; i < system.size(); ++i) {
      const Vector3<R> half = system.interpolated_position(i, R(0.5));
      const Vector3<R> mid = (before[i] + system.position(i)) * R(0.5);
      CHECK(magnitude(half - mid) <=
            R(4) * std::numeric_limits<R>::epsilon() * (magnitude(mid) + R(1)));
    }
  }
  // A jump by set_position does not streak: both ends move.
  system.set_position(0, {R(1), R(2), R(3)});
  CHECK(system.interpolated_position(0, R(0.25)) == Vector3<R>{R(1), R(2), R(3)});
  // interpolate(), for a lone Particle's loop.
  const Vector3<R> a{-R(0), R(1), R(2)}, b{R(3), R(4), R(5)};
  CHECK(same_bits(interpolate(a, b, R(0)), a));
  CHECK(same_bits(interpolate(a, b, R(1)), b));
}

TEST_CASE_TEMPLATE(
    "interpolation: alpha is the fraction of the way from the previous position "
    "to the current one",
    R, float, double) {
  // Every number here is exact in binary, so the expected positions are exact: a step of
  // 0.25 s at (4, -8, 2) m/s moves (1, -2, 0.5) m, and a quarter and three quarters of that
  // are exact too. (Alpha 0, 0.5 and 1 cannot tell the two ends apart: a formula with the
  // ends swapped gives the same points there.)
  using Drawn = ParticleSystem<R, damping::None, position::Euler, features::Interpolation>;
  Drawn system;
  system.spawn({R(0), R(8), R(-4)}, {R(4), R(-8), R(2)});
  system.spawn({R(1), R(1), R(1)}, {});  // at rest: every alpha gives where it is
  system.step(R(0.25));
  REQUIRE(system.previous_position(0) == Vector3<R>{R(0), R(8), R(-4)});
  REQUIRE(system.position(0) == Vector3<R>{R(1), R(6), R(-3.5)});
  const Vector3<R> quarter{R(0.25), R(7.5), R(-3.875)};
  const Vector3<R> three_quarters{R(0.75), R(6.5), R(-3.625)};
  const Vector3<R> rest{R(1), R(1), R(1)};
  for (const auto& point : {std::pair{R(0.25), quarter}, std::pair{R(0.75), three_quarters}}) {
    const R alpha = point.first;
    const Vector3<R> expected = point.second;
    CAPTURE(alpha);
    CHECK(system.interpolated_position(0, alpha) == expected);
    CHECK(system.interpolated_position(1, alpha) == rest);
    std::vector<R> packed(6), strided(7, R(-7));
    system.copy_interpolated_positions(alpha, std::span<R>(packed));
    CHECK(Vector3<R>{packed[0], packed[1], packed[2]} == expected);
    CHECK(Vector3<R>{packed[3], packed[4], packed[5]} == rest);
    system.copy_interpolated_positions(alpha, std::span<R>(strided), 4);
    CHECK(Vector3<R>{strided[0], strided[1], strided[2]} == expected);
    CHECK(strided[3] == R(-7));
    CHECK(Vector3<R>{strided[4], strided[5], strided[6]} == rest);
    std::vector<Vector3<R>> vectors(2);
    system.copy_interpolated_positions(alpha, std::span<Vector3<R>>(vectors));
    CHECK(vectors[0] == expected);
    CHECK(vectors[1] == rest);
    // The free interpolate, for a lone Particle's loop.
    CHECK(interpolate(Vector3<R>{R(0), R(8), R(-4)}, Vector3<R>{R(1), R(6), R(-3.5)}, alpha) ==
          expected);
  }
}

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

TEST_CASE("a feature not chosen costs nothing: the configurations' bytes and arrays as before") {
  // The figures of the configurations before these features existed (examples/variants.cmake
  // checks the same): 6 numbers per particle, +2 Lifetime, +4 ForceAccumulator, +3
  // PerParticleAcceleration.
  static_assert(ParticleSystem<float>::storage_bytes_per_particle == 24);
  static_assert(pointmass::detail::SystemAccess::Layout<ParticleSystem<float>>::array_count == 6);
  static_assert(ParticleSystem<double, damping::None>::storage_bytes_per_particle == 48);
  static_assert(ParticleSystem<float, damping::None, position::Euler,
                               features::Lifetime>::storage_bytes_per_particle == 32);
  // The raw arrays gain pointers for the new columns (nullptr, never walked), nothing for
  // absent user columns; the system object gains nothing for absent handles.
  using Lean = ParticleSystem<float>;
  static_assert(sizeof(Lean::StepView::Arrays) == 26 * sizeof(float*) + sizeof(std::size_t));
  // The object beside its arrays: block pointer and capacity, two flags, d and ln d (hi, lo),
  // the acceleration: 48 bytes on a 64-bit target, as before (measured on the commit before);
  // and the last step's length and its factor d^t, kept for the next step of that length: 8.
  // (a static_assert under `if constexpr` outside a template is checked on every target)
  static_assert(sizeof(void*) != 8 || sizeof(Lean) - sizeof(Lean::StepView::Arrays) == 56);
  // Each feature adds exactly its own columns.
  static_assert(ParticleSystem<float, damping::None, position::Euler,
                               features::Interpolation>::storage_bytes_per_particle == 36);
  static_assert(ParticleSystem<double, damping::None, position::Euler,
                               features::Handles>::storage_bytes_per_particle == 52);
}
