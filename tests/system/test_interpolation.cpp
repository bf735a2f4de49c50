// SPDX-License-Identifier: BSL-1.0
// Interpolation (system/interpolation.hpp): previous positions, alpha 0 and 1 bit for bit, alpha
// as the fraction of the way, every copy-out, a jump that does not streak, and `interpolate`.
#include <doctest/doctest.h>

#include <cstddef>
#include <limits>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include <pointmass/fixed_step.hpp>  // interpolate
#include <pointmass/gravity.hpp>
#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;

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
