// SPDX-License-Identifier: BSL-1.0
// The SI particle (units.hpp): same results as the plain particle, bit for bit; quantities
// with the right units at the boundary; the step's equations type-checked on quantities; the
// same contract errors; no extra storage.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <pointmass/extras/scenes.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/units.hpp>

#include <boost/units/systems/si/prefixes.hpp>

#include "tolerance.hpp"

namespace pm = pointmass;
namespace si = boost::units::si;
using pm::Vector3;

namespace {

template <class R>
Vector3<R> numbers(const Vector3<R>& v) {
  return v;
}
template <class Unit, class R>
Vector3<R> numbers(const Vector3<boost::units::quantity<Unit, R>>& v) {
  return {v.x.value(), v.y.value(), v.z.value()};
}

/// Runs every shot for `steps` frames of `frame` seconds, with a force added every frame,
/// on both particles, and requires identical numbers after every frame.
template <class R, class D, class P>
void check_same_trajectories(R frame, int steps) {
  for (const auto& shot : pm::scenes::ballistic_shots<R>) {
    CAPTURE(shot.name);
    pm::Particle<R, D, P> plain;
    pm::units::Particle<R, D, P> with_units;
    pm::scenes::launch(plain, shot);
    pm::scenes::launch(with_units, shot);
    const Vector3<R> push{R(0.5), R(-2), R(1.25)};  // newtons
    for (int step = 0; step < steps; ++step) {
      plain.add_force(push);
      with_units.add_force(push * si::newtons);
      plain.integrate(frame);
      with_units.integrate(frame * si::seconds);
      REQUIRE(numbers(with_units.position()) == plain.position());
      REQUIRE(numbers(with_units.velocity()) == plain.velocity());
    }
    CHECK(numbers(with_units.acceleration()) == plain.acceleration());
    CHECK(with_units.mass().value() == plain.mass());
    CHECK(with_units.damping() == plain.damping());
  }
}

TEST_CASE_TEMPLATE("scenes::launch starts a particle with wide positions, plain and SI", S,
                   pm::Precision<float, double>, pm::Precision<float, pm::Compensated<float>>) {
  const auto& shot = pm::scenes::ballistic_shots<float>[1];
  pm::Particle<S> plain;
  pm::units::Particle<S> with_units;
  pm::scenes::launch(plain, shot);
  pm::scenes::launch(with_units, shot);
  const auto& origin = pm::scenes::ballistic_origin<float>;
  const Vector3<double> start{double(origin.x), double(origin.y), double(origin.z)};
  CHECK(plain.position() == start);
  CHECK(numbers(with_units.position()) == start);
  CHECK(plain.velocity() == shot.velocity);
  CHECK(numbers(with_units.velocity()) == shot.velocity);
  CHECK(plain.mass() == shot.mass);
}

template <class R, class D>
void check_all_positions(R frame, int steps) {
  check_same_trajectories<R, D, pm::position::Euler>(frame, steps);
  check_same_trajectories<R, D, pm::position::ConstantAcceleration>(frame, steps);
  check_same_trajectories<R, D, pm::position::SemiImplicit>(frame, steps);
  if constexpr (pm::PositionPolicyFor<pm::position::Exact, D>) {
    check_same_trajectories<R, D, pm::position::Exact>(frame, steps);
  }
  if constexpr (pm::PositionPolicyFor<pm::position::VelocityVerlet, D>) {
    check_same_trajectories<R, D, pm::position::VelocityVerlet>(frame, steps);
  }
}

}  // namespace

TEST_CASE_TEMPLATE("every policy combination gives the plain particle's numbers bit for bit", R,
                   float, double) {
  // 150 frames at 30 fps: 5 s, the shots' duration.
  const R frame = R(1) / R(30);
  SUBCASE("None") { check_all_positions<R, pm::damping::None>(frame, 150); }
  SUBCASE("PerFrame") { check_all_positions<R, pm::damping::PerFrame>(frame, 150); }
  SUBCASE("PerSecond") { check_all_positions<R, pm::damping::PerSecond>(frame, 150); }
  SUBCASE("AccelerateThenDamp") {
    check_all_positions<R, pm::damping::AccelerateThenDamp>(frame, 150);
  }
  SUBCASE("Exact") { check_all_positions<R, pm::damping::Exact>(frame, 150); }
}

TEST_CASE_TEMPLATE("values come back as the SI quantities they were given", R, float, double) {
  pm::units::Particle<R> particle;
  particle.set_position(Vector3<R>{R(1), R(2), R(3)} * si::meters);
  particle.set_velocity(Vector3<R>{R(4), R(5), R(6)} * si::meters_per_second);
  particle.set_acceleration(Vector3<R>{R(0), R(-9.807), R(0)} * si::meters_per_second_squared);
  particle.set_mass(R(4) * si::kilograms);
  particle.add_force(Vector3<R>{R(8), R(0), R(0)} * si::newtons);

  static_assert(std::is_same_v<decltype(particle.position()), Vector3<pm::units::length<R>>>);
  static_assert(std::is_same_v<decltype(particle.velocity()), Vector3<pm::units::velocity<R>>>);
  static_assert(
      std::is_same_v<decltype(particle.acceleration()), Vector3<pm::units::acceleration<R>>>);
  static_assert(
      std::is_same_v<decltype(particle.force_accumulator()), Vector3<pm::units::force<R>>>);
  static_assert(std::is_same_v<decltype(particle.mass()), pm::units::mass<R>>);
  static_assert(std::is_same_v<decltype(particle.inverse_mass()), pm::units::inverse_mass<R>>);
  static_assert(std::is_same_v<decltype(particle.damping()), R>);

  CHECK(particle.position().y == R(2) * si::meters);
  CHECK(particle.velocity().z == R(6) * si::meters_per_second);
  CHECK(particle.acceleration().y == R(-9.807) * si::meters_per_second_squared);
  CHECK(particle.force_accumulator().x == R(8) * si::newtons);
  CHECK(particle.mass() == R(4) * si::kilograms);
  CHECK(particle.inverse_mass() == R(0.25) / si::kilograms);

  // 1/kg is what the set says inverse mass is, and f * (1/m) is an acceleration.
  particle.set_inverse_mass(R(0.5) / si::kilograms);
  CHECK(particle.mass() == R(2) * si::kilograms);
}

TEST_CASE_TEMPLATE("a duration converts to seconds for the damping's exponent", R, float, double) {
  static_assert(std::is_same_v<pm::scalar_t<pm::units::time<R>>, R>);
  static_assert(std::is_same_v<pm::scalar_t<pm::units::length<R>>, R>);
  CHECK(pm::in_seconds(R(0.25) * si::seconds) == R(0.25));
  CHECK(pm::in_seconds(R(1) / R(60) * si::seconds) == R(1) / R(60));
}

TEST_CASE_TEMPLATE("the step's equations run on quantities and give the closed form", R, float,
                   double) {
  // advance() itself, instantiated on Vector3s of length, velocity and acceleration and a
  // time quantity: without damping, ConstantAcceleration is p + v t + a t^2 / 2 exactly in real
  // arithmetic; the rounding of a handful of operations is all that may differ.
  Vector3<pm::units::length<R>> p = Vector3<R>{R(0), R(1.5), R(0)} * si::meters;
  Vector3<pm::units::velocity<R>> v = Vector3<R>{R(0), R(30), R(40)} * si::meters_per_second;
  const Vector3<pm::units::acceleration<R>> a =
      Vector3<R>{R(0), R(-20), R(0)} * si::meters_per_second_squared;
  const pm::units::time<R> t = R(0.5) * si::seconds;
  pm::integrate<pm::damping::None, pm::position::ConstantAcceleration>(
      p, v, a, t, pm::damping::None::Factors{});
  // By hand: y = 1.5 + 30 * 0.5 - 20 * 0.125 = 14, z = 40 * 0.5 = 20; vy = 30 - 10 = 20.
  POINTMASS_CHECK_CLOSE(numbers(p), (Vector3<R>{R(0), R(14), R(20)}), R(8));
  POINTMASS_CHECK_CLOSE(numbers(v), (Vector3<R>{R(0), R(20), R(40)}), R(8));
}

TEST_CASE_TEMPLATE("bad values are rejected with the argument and its value in SI numbers", R,
                   float, double) {
  pm::units::Particle<R> particle;
  particle.set_mass(R(2) * si::kilograms);
  std::string message;
  try {
    particle.set_mass(R(-1) * si::kilograms);
  } catch (const std::invalid_argument& error) {
    message = error.what();
  }
  CHECK(message.find("set_mass") != std::string::npos);
  CHECK(message.find("'mass' = -1") != std::string::npos);
  CHECK(particle.mass() == R(2) * si::kilograms);  // unchanged

  CHECK_THROWS_AS(particle.set_inverse_mass(R(-1) / si::kilograms), std::invalid_argument);
  CHECK_THROWS_AS(particle.set_damping(R(1.5)), std::invalid_argument);
  CHECK_THROWS_AS(particle.set_velocity(Vector3<R>{R(0), std::numeric_limits<R>::infinity(), R(0)} *
                                        si::meters_per_second),
                  std::invalid_argument);
#if POINTMASS_CHECKS
  CHECK_THROWS_AS(particle.integrate(R(-0.1) * si::seconds), std::invalid_argument);
#endif
}

TEST_CASE_TEMPLATE("the SI particle costs no storage and stays trivially copyable", R, float,
                   double) {
  using pm::damping::Exact;
  using pm::damping::None;
  using pm::damping::PerSecond;
  static_assert(sizeof(pm::units::Particle<R>) == sizeof(pm::Particle<R>));
  static_assert(sizeof(pm::units::Particle<R, None>) == sizeof(pm::Particle<R, None>));
  static_assert(sizeof(pm::units::Particle<R, Exact, pm::position::Exact>) ==
                sizeof(pm::Particle<R, Exact, pm::position::Exact>));
  static_assert(std::is_trivially_copyable_v<pm::units::Particle<R, PerSecond>>);
  static_assert(std::is_trivially_copyable_v<pm::units::Particle<R, None>>);
  // A particle without a damping value says so (stores_damping), with or without units; its
  // set_damping fails to compile with a sentence (tests/compile-fail/set_damping_without_damping).
  static_assert(!pm::units::Particle<R, None>::stores_damping);
  static_assert(pm::units::Particle<R, PerSecond>::stores_damping);
  static_assert(requires(pm::units::Particle<R, PerSecond> p) { p.set_damping(R(1)); });
  CHECK(sizeof(pm::units::Particle<R, None>) < sizeof(pm::units::Particle<R, PerSecond>));
}

TEST_CASE_TEMPLATE("a quantity in another unit of the same dimension is converted to SI", R, float,
                   double) {
  // 16 ms, 2 km, 500 g, 3.6 km per second...: each is what SI would have been given.
  pm::units::Particle<R> milli;
  pm::units::Particle<R> plain;
  const auto ms = R(16) * si::milli * si::seconds;
  const auto seconds = R(16) * R(0.001) * si::seconds;
  milli.set_position(Vector3<R>{R(1), R(2), R(3)} * (si::kilo * si::meters));
  plain.set_position(Vector3<R>{R(1000), R(2000), R(3000)} * si::meters);
  CHECK(milli.position().x.value() == R(1000));
  CHECK(milli.position().z.value() == R(3000));
  milli.set_velocity(Vector3<R>{R(0), R(0.01), R(0)} * (si::kilo * si::meters_per_second));
  plain.set_velocity(Vector3<R>{R(0), R(10), R(0)} * si::meters_per_second);
  milli.set_mass(R(500) * si::milli * si::kilograms);
  plain.set_mass(R(0.5) * si::kilograms);
  milli.add_force(Vector3<R>{R(1), R(0), R(0)} * (si::kilo * si::newtons));
  plain.add_force(Vector3<R>{R(1000), R(0), R(0)} * si::newtons);
  milli.integrate(ms);
  plain.integrate(seconds);
  const auto numbers = [](const auto& v) {
    return Vector3<R>{v.x.value(), v.y.value(), v.z.value()};
  };
  CHECK(pm::test::close(numbers(milli.position()), numbers(plain.position()), R(8)));
  CHECK(pm::test::close(numbers(milli.velocity()), numbers(plain.velocity()), R(8)));
  CHECK(milli.velocity().x.value() > R(0));  // the force acted, in kilonewtons on 500 g
}
