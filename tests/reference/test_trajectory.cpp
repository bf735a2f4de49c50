// SPDX-License-Identifier: BSL-1.0
// trajectory.hpp's queries on the exact pairs: state_at against Odeint and the closed form,
// and is integrate(T) on a copy; time_to_reach against a root of the closed form found apart
// (a dense scan for the first sign change, then bisection, in long double), "never" where the
// coordinate cannot reach the value; both as d -> 1 and d -> 0.
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <doctest/doctest.h>

#include <pointmass/trajectory.hpp>

#include "accuracy.hpp"
#include "reference_solution.hpp"

using namespace pointmass;
using namespace pointmass::accuracy;

namespace {

using Exact = Particle<double, damping::Exact, position::Exact>;
using Undamped = Particle<double, damping::None, position::Exact>;

template <class P>
P launched(const Scene& s) {
  P particle;
  particle.set_position(s.start_position);
  particle.set_velocity(s.start_velocity);
  particle.set_acceleration(s.gravity);
  if constexpr (P::stores_damping) particle.set_damping(s.damping);
  return particle;
}

double rate_of(double d) {
  return d == 1.0 ? 0.0 : d > 0 ? std::log(d) : -std::numeric_limits<double>::infinity();
}

double coordinate(const Vector3<double>& v, Axis axis) {
  return axis == Axis::x ? v.x : axis == Axis::y ? v.y : v.z;
}

/// The first t in [0, horizon] where the closed form's coordinate reaches value: scanned in
/// 20,000 intervals for a sign change (or an exact hit), then bisected; nothing if none.
std::optional<double> reference_time(const Scene& s, double rate, Axis axis, double value,
                                     double horizon) {
  const auto gap = [&](double t) {
    return coordinate(
               reference::analytic_ballistic(s.start_position, s.start_velocity, s.gravity, rate, t)
                   .position,
               axis) -
           value;
  };
  const double start = gap(0);
  if (start == 0) return 0.0;
  const int intervals = 20000;
  for (int n = 1; n <= intervals; ++n) {
    double lo = horizon * (n - 1) / intervals, hi = horizon * n / intervals;
    if ((gap(hi) > 0) == (start > 0) && gap(hi) != 0) continue;
    for (int k = 0; k < 200; ++k) {
      const double mid = lo + (hi - lo) / 2;
      if (!(mid > lo && mid < hi)) break;
      ((gap(mid) > 0) == (start > 0) && gap(mid) != 0 ? lo : hi) = mid;
    }
    return hi;
  }
  return std::nullopt;
}

struct Target {
  const char* shot;
  Axis axis;
  double value;
  bool reached;  // worked from the shot: the apex, the sign of the acceleration, ...
};

// The four shots from (0, 1.5, 0): pistol and artillery fall to the ground; the artillery's
// apex is about 1.5 + 30^2 / 40 = 24 m (less with drag), so 20 m and 23.5 m (after 1 s and
// before 2 s, where it is 21.5 m) are reached and 30 m never;
// the fireball accelerates upwards (never down to 0); the laser flies level along z.
const std::vector<Target> targets{
    {"pistol", Axis::y, 0.0, true},     {"pistol", Axis::z, 50.0, true},
    {"artillery", Axis::y, 0.0, true},  {"artillery", Axis::y, 20.0, true},
    {"artillery", Axis::y, 23.5, true}, {"artillery", Axis::y, 30.0, false},
    {"fireball", Axis::y, 0.0, false},  {"fireball", Axis::y, 5.0, true},
    {"laser", Axis::z, 200.0, true},    {"laser", Axis::y, 0.0, false},
};

Scene shot_named(const char* name) {
  for (const Scene& s : ballistic_scenes()) {
    if (s.name == name) return s;
  }
  throw std::logic_error("no shot named " + std::string(name));
}

}  // namespace

TEST_CASE("state_at matches Odeint at 1e-12 relative over the four shots, and is integrate(T)") {
  for (const Scene& s : ballistic_scenes()) {
    const Exact particle = launched<Exact>(s);
    for (const double time : {0.1, 1.0, 2.5, 5.0}) {
      INFO(s.name, " at t = ", time);
      const auto state = state_at(particle, time);
      // Odeint at a local tolerance of 1e-14, so that its own error stays below the 1e-12.
      const auto ref = reference::odeint_trajectory(model_of<damping::Exact>(s), s.start_position,
                                                    s.start_velocity, time, 1, 1e-14)[1];
      CHECK(magnitude(state.position - ref.position) <=
            1e-12 * std::max(1.0, magnitude(ref.position)));
      CHECK(magnitude(state.velocity - ref.velocity) <=
            1e-12 * std::max(1.0, magnitude(ref.velocity)));
      CHECK(position_at(particle, time) == state.position);
      CHECK(velocity_at(particle, time) == state.velocity);
      Exact stepped = particle;
      stepped.integrate(time);
      CHECK(stepped.position() == state.position);  // the same bits: one step of length T
      CHECK(stepped.velocity() == state.velocity);
    }
    CHECK(state_at(particle, 0.0).position == particle.position());
  }
}

TEST_CASE("time_to_reach: the first time, against the closed form's root, never when it cannot") {
  for (const Target& target : targets) {
    const Scene s = shot_named(target.shot);
    INFO(target.shot, " axis ", int(target.axis), " value ", target.value);
    const auto ref = reference_time(s, rate_of(s.damping), target.axis, target.value, 60.0);
    REQUIRE(ref.has_value() == target.reached);  // the reference agrees with the reasoning
    const auto hit = time_to_reach(launched<Exact>(s), target.axis, target.value);
    REQUIRE(hit.has_value() == target.reached);
    if (!hit) continue;
    CHECK(std::abs(*hit - *ref) <= 1e-12 * *ref);
    // Of the two adjacent times around the crossing, the one nearer the value: a neighbour on
    // the other side of the value is no nearer.
    const auto miss = [&](double t) {
      return coordinate(position_at(launched<Exact>(s), t), target.axis) - target.value;
    };
    for (const double neighbour : {std::nextafter(*hit, 0.0), std::nextafter(*hit, 1e300)}) {
      if ((miss(neighbour) < 0) != (miss(*hit) < 0)) {
        CHECK(std::abs(miss(*hit)) <= std::abs(miss(neighbour)));
      }
    }
    // Odeint's position at that time is at the value, to 1e-12 of the distance flown.
    const auto at = reference::odeint_trajectory(model_of<damping::Exact>(s), s.start_position,
                                                 s.start_velocity, *hit, 1, 1e-14)[1];
    CHECK(std::abs(coordinate(at.position, target.axis) - target.value) <=
          1e-12 * std::max(1.0, magnitude(at.position)));
    // The undamped pair, against the quadratic's smaller non-negative root.
    Scene undamped = s;
    undamped.damping = 1.0;
    const auto free_ref = reference_time(undamped, 0.0, target.axis, target.value, 60.0);
    const auto free_hit = time_to_reach(launched<Undamped>(undamped), target.axis, target.value);
    REQUIRE(free_hit.has_value() == free_ref.has_value());
    if (free_hit) CHECK(std::abs(*free_hit - *free_ref) <= 1e-12 * *free_ref);
  }
  // The apex below h: never, for any damping, with or without.
  Scene artillery = shot_named("artillery");
  for (const double d : {1.0, 0.99, 0.5, 1e-6, 0.0}) {
    artillery.damping = d;
    CHECK_FALSE(time_to_reach(launched<Exact>(artillery), Axis::y, 24.5).has_value());
  }
  CHECK_FALSE(time_to_reach(launched<Undamped>(artillery), Axis::y, 24.5).has_value());
  CHECK(time_to_reach(launched<Undamped>(artillery), Axis::y, 1.5) == 0.0);  // there now
}

TEST_CASE("queries stay exact as d -> 1 and d -> 0") {
  Scene artillery = shot_named("artillery");
  for (const double d : {1.0, 1.0 - 1e-15, 1.0 - 1e-9, 0.9, 1e-9, 1e-300, 0.0}) {
    artillery.damping = d;
    const double rate = rate_of(d);
    const Exact particle = launched<Exact>(artillery);
    INFO("damping ", d);
    for (const double time : {1e-9, 0.5, 3.0, 40.0}) {
      const auto state = state_at(particle, time);
      const auto ref = reference::analytic_ballistic(
          artillery.start_position, artillery.start_velocity, artillery.gravity, rate, time);
      CHECK(magnitude(state.position - ref.position) <=
            1e-12 * std::max(1.0, magnitude(ref.position)));
      CHECK(magnitude(state.velocity - ref.velocity) <=
            1e-12 * std::max(1.0, magnitude(ref.velocity)));
    }
    // The apex, by a dense scan of the closed form: a height just below it is reached (on
    // the way up: the turning point must be where the velocity passes 0, at every drag).
    double apex = artillery.start_position.y;
    for (int n = 0; n <= 200000; ++n) {
      const double t = 10.0 * n / 200000;
      apex = std::max(
          apex, reference::analytic_ballistic(artillery.start_position, artillery.start_velocity,
                                              artillery.gravity, rate, t)
                    .position.y);
    }
    const double near_apex = apex - 0.05 * (apex - artillery.start_position.y);
    // The ground, 10 m (reached on the way up when the drag allows), and just below the apex.
    for (const double value : {0.0, 10.0, near_apex}) {
      const auto hit = time_to_reach(particle, Axis::y, value);
      const auto ref = reference_time(artillery, rate, Axis::y, value, 60.0);
      INFO("value ", value);
      if (d == 0.0) {  // d = 0 stops it where it is (and there the apex is the start)
        if (value == artillery.start_position.y) {
          CHECK(hit == 0.0);
        } else {
          CHECK_FALSE(hit.has_value());
        }
        continue;
      }
      REQUIRE(hit.has_value() == ref.has_value());
      if (hit) CHECK(std::abs(*hit - *ref) <= 1e-12 * *ref);
    }
  }
}
