// SPDX-License-Identifier: BSL-1.0
// damping::Exact with position::Exact: the closed form of constant acceleration with linear
// per-second damping, so no truncation error at any frame time, one 5 s step included.
#include <cmath>
#include <limits>
#include <vector>

#include <doctest/doctest.h>

#include "accuracy.hpp"
#include "reference_solution.hpp"
#include "tolerance.hpp"

using namespace pointmass;
using namespace pointmass::accuracy;

namespace {

/// The frame times of the test: the standard four and a single step over the whole shot.
const std::vector<double> exact_frame_times{1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240, 5.0};

/// The damping values whose limits matter: none, almost none, strong, near total, total.
const std::vector<double> damping_values{1.0, 1.0 - 1e-7, 0.5, 1e-6, 0.0};

template <class R>
struct Run {
  std::vector<reference::Sample> samples;
  bool all_finite = true;
};

/// A shot with damping d, stepped by the exact pair in R; the inputs as R holds them.
template <class R>
Run<R> run_exact(Scene s, double h) {
  Run<R> run;
  auto particle = make_particle<R, damping::Exact, position::Exact>(s, h);
  const R frame = static_cast<R>(h);
  run.samples.push_back({widen(particle.position()), widen(particle.velocity())});
  for (long n = 0; n < steps_for(s, h); ++n) {
    particle.integrate(frame);
    run.all_finite =
        run.all_finite && is_finite(particle.position()) && is_finite(particle.velocity());
    run.samples.push_back({widen(particle.position()), widen(particle.velocity())});
  }
  return run;
}

/// The scene's values as R rounds them (so the reference solves the problem R was given).
template <class R>
Scene as_stored(Scene s) {
  s.start_position = widen(cast<R>(s.start_position));
  s.start_velocity = widen(cast<R>(s.start_velocity));
  s.gravity = widen(cast<R>(s.gravity));
  s.damping = static_cast<double>(static_cast<R>(s.damping));
  return s;
}

/// Relative tolerance for R: 1e-12 for double; for float, the rounding of
/// about 8 operations a step over N steps, N 8 eps (and at least 8 eps for one step), since
/// each exact step only rounds. For long double the same N 8 eps of its own, plus the
/// reference's rounding to double (its samples are doubles): 2 double epsilons.
template <class R>
double tolerance(long steps) {
  if constexpr (std::is_same_v<R, double>) return 1e-12;
  const double rounding =
      8.0 * static_cast<double>(std::numeric_limits<R>::epsilon()) * static_cast<double>(steps);
  if constexpr (std::is_same_v<R, long double>)
    return rounding + 2 * std::numeric_limits<double>::epsilon();
  return rounding;
}

}  // namespace

TEST_CASE_TEMPLATE("the exact pair matches the closed form at every frame time and damping", R,
                   float, double, long double) {
  for (Scene shot : ballistic_scenes()) {
    for (const double d : damping_values) {
      shot.damping = d;
      const Scene s = as_stored<R>(shot);
      const double k =
          s.damping == 1.0
              ? 0.0
              : (s.damping > 0 ? std::log(s.damping) : -std::numeric_limits<double>::infinity());
      for (const double h : exact_frame_times) {
        INFO(shot.name, ", damping ", d, ", frame time ", h);
        const Run<R> run = run_exact<R>(s, h);
        REQUIRE(run.all_finite);
        const long steps = steps_for(s, h);
        const double tol = tolerance<R>(steps);
        for (long n = 0; n <= steps; ++n) {
          const double t = static_cast<double>(n) * static_cast<double>(static_cast<R>(h));
          const auto exact =
              reference::analytic_ballistic(s.start_position, s.start_velocity, s.gravity, k, t);
          const auto& x = run.samples[static_cast<std::size_t>(n)];
          INFO("step ", n, ": position ", x.position, ", exact ", exact.position);
          const double scale =
              std::max({1.0, magnitude(exact.position), magnitude(s.start_position)});
          CHECK(magnitude(x.position - exact.position) <= tol * scale);
          const double speed = std::max({1.0, magnitude(exact.velocity),
                                         magnitude(s.start_velocity), magnitude(s.gravity) * t});
          CHECK(magnitude(x.velocity - exact.velocity) <= tol * speed);
        }
      }
    }
  }
}

TEST_CASE("the exact pair matches Odeint's solution at 1e-12 relative, one 5 s step included") {
  for (Scene s : ballistic_scenes()) {
    for (const double d : {1.0, 1.0 - 1e-7, 0.5, 1e-6}) {
      s.damping = d;
      for (const double h : exact_frame_times) {
        const long steps = steps_for(s, h);
        // Odeint at a local tolerance of 1e-14, so that its own accumulated error stays below
        // the 1e-12 the check allows.
        const auto ref = reference::odeint_trajectory(model_of<damping::Exact>(s), s.start_position,
                                                      s.start_velocity, h, steps, 1e-14);
        const auto run = run_exact<double>(s, h);
        for (long n = 0; n <= steps; ++n) {
          const auto& x = run.samples[static_cast<std::size_t>(n)];
          const auto& y = ref[static_cast<std::size_t>(n)];
          INFO(s.name, ", damping ", d, ", frame time ", h, ", step ", n);
          CHECK(magnitude(x.position - y.position) <= 1e-12 * std::max(1.0, magnitude(y.position)));
        }
      }
    }
  }
}

TEST_CASE_TEMPLATE("total damping (d = 0) stops the particle where it is, without NaN", R, float,
                   double) {
  Particle<R, damping::Exact, position::Exact> p;
  p.set_position({R(1), R(2), R(3)});
  p.set_velocity({R(10), R(-5), R(7)});
  p.set_acceleration({R(0), R(-9.807), R(0)});
  p.set_damping(R(0));
  for (const R t : {R(1) / R(60), R(5)}) {
    p.integrate(t);
    CHECK(p.position() == Vector3<R>{R(1), R(2), R(3)});
    CHECK(p.velocity() == Vector3<R>{});
  }
}

TEST_CASE_TEMPLATE("no damping (d = 1) is the kinematic form exactly", R, float, double) {
  Particle<R, damping::Exact, position::Exact> exact;
  Particle<R, damping::None, position::ConstantAcceleration> kinematic;
  exact.set_damping(R(1));
  exact.set_velocity({R(3), R(20), R(4)});
  kinematic.set_velocity({R(3), R(20), R(4)});
  exact.set_acceleration({R(0), R(-9.807), R(0)});
  kinematic.set_acceleration({R(0), R(-9.807), R(0)});
  for (int n = 0; n < 300; ++n) {
    exact.integrate(R(1) / R(60));
    kinematic.integrate(R(1) / R(60));
  }
  const R eps = std::numeric_limits<R>::epsilon();
  CHECK(magnitude(exact.position() - kinematic.position()) <=
        300 * 8 * eps * magnitude(kinematic.position()));
  CHECK(exact.velocity() == kinematic.velocity());
}
