// SPDX-License-Identifier: BSL-1.0
// The references themselves: Odeint's dopri5 at tolerance 1e-12 agrees with the closed forms,
// so either can judge the library.
#include <cmath>
#include <numbers>

#include <doctest/doctest.h>

#include "accuracy.hpp"
#include "reference_solution.hpp"
#include "tolerance.hpp"

using namespace pointmass;
using namespace pointmass::accuracy;

TEST_CASE("Odeint agrees with the closed form on every ballistic shot, damped and undamped") {
  for (Scene s : ballistic_scenes()) {
    for (const double rate : {std::log(s.damping), 0.0}) {
      const reference::Model model{s.gravity, 0, 0, rate};
      const double h = 1.0 / 30;
      const long steps = steps_for(s, h);
      const auto numeric =
          reference::odeint_trajectory(model, s.start_position, s.start_velocity, h, steps);
      REQUIRE(numeric.size() == static_cast<std::size_t>(steps) + 1);
      for (long n = 0; n <= steps; ++n) {
        const auto exact = reference::analytic_ballistic(
            s.start_position, s.start_velocity, s.gravity, rate, static_cast<double>(n) * h);
        const auto& y = numeric[static_cast<std::size_t>(n)];
        INFO(s.name, " rate ", rate, " step ", n);
        // dopri5's local tolerance 1e-12, accumulated over the run: 1e-11 of the scale.
        CHECK(magnitude(y.position - exact.position) <=
              1e-11 * std::max(1.0, magnitude(exact.position)));
        CHECK(magnitude(y.velocity - exact.velocity) <=
              1e-11 * std::max(1.0, magnitude(exact.velocity)));
      }
    }
  }
}

TEST_CASE("Odeint agrees with x cos(omega t) on the undamped spring") {
  const Scene s = spring(false, 10);
  const double h = 1.0 / 60, omega = s.angular_frequency();
  const long steps = steps_for(s, h);
  const auto numeric = reference::odeint_trajectory(model_of<damping::None>(s), s.start_position,
                                                    s.start_velocity, h, steps);
  for (long n = 0; n <= steps; ++n) {
    const double t = static_cast<double>(n) * h;
    const auto& y = numeric[static_cast<std::size_t>(n)];
    CHECK(std::abs(y.position.x - std::cos(omega * t)) <= 1e-10);
    CHECK(std::abs(y.velocity.x + omega * std::sin(omega * t)) <= 1e-10 * omega);
  }
}

TEST_CASE("Odeint samples every frame even when the end time is not a multiple of the step") {
  // 1/30 s does not divide 0.1 s exactly in binary; integrate_n_steps still gives 4 samples.
  const reference::Model model{{0, -9.807, 0}, 0, 0, 0};
  const auto samples = reference::odeint_trajectory(model, {}, {}, 1.0 / 30, 3);
  REQUIRE(samples.size() == 4);
  CHECK(std::abs(samples.back().position.y + 9.807 * 0.1 * 0.1 / 2) <= 1e-13);
}
