// SPDX-License-Identifier: BSL-1.0
// Particle: its state, defaults, storage, infinite mass, zero duration, forces and the kept
// damping factors.
#include <doctest/doctest.h>

#include <limits>

#include <pointmass/pointmass.hpp>

#include "counting_damping.hpp"
#include "tolerance.hpp"

using namespace pointmass;

// A policy that needs no state costs no storage.
static_assert(sizeof(Particle<float, damping::None>) < sizeof(Particle<float, damping::PerSecond>));
static_assert(sizeof(Particle<float, damping::None>) == 13 * sizeof(float));
// Per-second damping keeps d and ln d (as hi + lo: no logarithm a step), and the last step's
// length and factor (no exponential while the length repeats).
static_assert(sizeof(Particle<float, damping::PerSecond>) == (13 + 3 + 2) * sizeof(float));
static_assert(sizeof(Particle<double, damping::PerFrame, position::ConstantAcceleration>) ==
              14 * sizeof(double));
static_assert(sizeof(Particle<float, damping::AccelerateThenDamp>) == (13 + 1 + 2) * sizeof(float));
static_assert(sizeof(Particle<float, damping::Exact>) == (13 + 3 + 4) * sizeof(float));
static_assert(Particle<float>::caches_factors && Particle<double, damping::Exact>::caches_factors);
static_assert(!Particle<float, damping::PerFrame>::caches_factors &&
              !Particle<float, damping::None>::caches_factors);
static_assert(!Particle<float, damping::None>::stores_damping);
static_assert(Particle<float>::stores_damping);
// The defaults.
static_assert(std::is_same_v<Particle<float>::damping_policy, damping::PerSecond>);
static_assert(std::is_same_v<Particle<float>::position_policy, position::Euler>);
static_assert(std::is_trivially_copyable_v<Particle<float>>);
// The concepts accept the library's policies.
static_assert(DampingPolicy<damping::None> && DampingPolicy<damping::PerFrame> &&
              DampingPolicy<damping::PerSecond> && DampingPolicy<damping::AccelerateThenDamp> &&
              DampingPolicy<damping::Exact>);
static_assert(PositionPolicyFor<position::Exact, damping::Exact>);
static_assert(PositionPolicyFor<position::Exact, damping::None>);
// The exact position needs the exact damping's factors: with eq. 3.6 it is not exact.
static_assert(!PositionPolicyFor<position::Exact, damping::PerSecond>);

TEST_CASE_TEMPLATE("a default particle is at rest at the origin, mass 1, undamped", R, float,
                   double) {
  const Particle<R> p;
  CHECK(p.position() == Vector3<R>{});
  CHECK(p.velocity() == Vector3<R>{});
  CHECK(p.acceleration() == Vector3<R>{});
  CHECK(p.force_accumulator() == Vector3<R>{});
  CHECK(p.mass() == R(1));
  CHECK(p.inverse_mass() == R(1));
  CHECK(p.damping() == R(1));
  CHECK(p.has_finite_mass());

  // Undamped and at rest, it stays where it is.
  Particle<R> q;
  q.integrate(R(1));
  CHECK(q.position() == Vector3<R>{});
  CHECK(q.velocity() == Vector3<R>{});
}

TEST_CASE_TEMPLATE("mass and inverse mass", R, float, double) {
  Particle<R> p;
  p.set_mass(R(4));
  CHECK(p.inverse_mass() == R(0.25));
  CHECK(p.mass() == R(4));
  p.set_inverse_mass(R(0.5));
  CHECK(p.mass() == R(2));
  p.set_inverse_mass(R(0));
  CHECK_FALSE(p.has_finite_mass());
  CHECK(p.mass() == std::numeric_limits<R>::infinity());
  p.set_mass(std::numeric_limits<R>::infinity());  // infinite mass is allowed: immovable
  CHECK(p.inverse_mass() == R(0));
  CHECK_FALSE(p.has_finite_mass());
}

TEST_CASE_TEMPLATE("an infinite-mass particle does not move, whatever acts on it", R, float,
                   double) {
  Particle<R, damping::PerSecond, position::ConstantAcceleration> wall;
  wall.set_position({R(1), R(2), R(3)});
  wall.set_velocity({R(5), R(0), R(0)});
  wall.set_acceleration(gravity(earth_gravity<R>));
  wall.set_inverse_mass(R(0));
  wall.add_force({R(1e6), R(1e6), R(1e6)});
  wall.integrate(R(0.5));
  CHECK(wall.position() == Vector3<R>{R(1), R(2), R(3)});
  CHECK(wall.velocity() == Vector3<R>{R(5), R(0), R(0)});
  CHECK(wall.force_accumulator() == Vector3<R>{});  // the force does not wait for later

  // Made immovable after a step that kept its length's factors: the next step of that length
  // (the kept factors' way) does not move it either.
  Particle<R, damping::PerSecond, position::ConstantAcceleration> ball;
  ball.set_velocity({R(5), R(0), R(0)});
  ball.set_acceleration(gravity(earth_gravity<R>));
  ball.set_damping(R(0.5));
  ball.integrate(R(0.5));
  REQUIRE(ball.position() != Vector3<R>{});
  ball.set_inverse_mass(R(0));
  const Vector3<R> position = ball.position();
  const Vector3<R> velocity = ball.velocity();
  ball.add_force({R(1e6), R(1e6), R(1e6)});
  ball.integrate(R(0.5));
  CHECK(ball.position() == position);
  CHECK(ball.velocity() == velocity);
  CHECK(ball.force_accumulator() == Vector3<R>{});
}

TEST_CASE_TEMPLATE("a zero duration changes nothing", R, float, double) {
  Particle<R, damping::PerFrame> p;  // per-frame damping would damp even a zero step
  p.set_position({R(1), R(2), R(3)});
  p.set_velocity({R(4), R(5), R(6)});
  p.set_acceleration({R(0), R(-10), R(0)});
  p.set_damping(R(0.5));
  p.add_force({R(1), R(0), R(0)});
  p.integrate(R(0));
  CHECK(p.position() == Vector3<R>{R(1), R(2), R(3)});
  CHECK(p.velocity() == Vector3<R>{R(4), R(5), R(6)});
  CHECK(p.force_accumulator() == Vector3<R>{R(1), R(0), R(0)});  // kept for the next step
}

// The step tests a zero duration and a zero inverse mass on their bits (detail::is_zero): a
// zero of either sign is zero, on a new step length and on the kept one, for the engine's
// equations (their own order around the power function) and for the default policies.
template <class P>
void check_negative_zeros() {
  using R = typename P::real;
  P p;
  p.set_position({R(1), R(2), R(3)});
  p.set_velocity({R(4), R(5), R(6)});
  p.set_acceleration({R(0), R(-10), R(0)});
  p.set_damping(R(0.5));
  for (int step = 0; step < 2; ++step) {  // a new length first, then the kept one
    CAPTURE(step);
    const Vector3<R> position = p.position();
    const Vector3<R> velocity = p.velocity();
    p.add_force({R(1), R(0), R(0)});
    p.integrate(-R(0));  // changes nothing: the force waits for the next step
    CHECK(p.position() == position);
    CHECK(p.velocity() == velocity);
    CHECK(p.force_accumulator() == Vector3<R>{R(1), R(0), R(0)});
    p.integrate(R(1) / R(60));
    CHECK(p.position() != position);
    CHECK(p.force_accumulator() == Vector3<R>{});
  }
  p.set_inverse_mass(-R(0));  // accepted as zero: immovable
  CHECK_FALSE(p.has_finite_mass());
  for (const R t : {R(1) / R(60), R(1) / R(30)}) {  // the kept length, then a new one
    CAPTURE(t);
    const Vector3<R> position = p.position();
    const Vector3<R> velocity = p.velocity();
    p.add_force({R(1e6), R(1e6), R(1e6)});
    p.integrate(t);
    CHECK(p.position() == position);
    CHECK(p.velocity() == velocity);
    CHECK(p.force_accumulator() == Vector3<R>{});
  }
}

TEST_CASE_TEMPLATE(
    "a duration or inverse mass of -0 is zero, on a new step length and the kept "
    "one",
    R, float, double) {
  check_negative_zeros<Particle<R, damping::AccelerateThenDamp, position::Euler>>();
  check_negative_zeros<Particle<R>>();
  check_negative_zeros<Particle<R, damping::PerFrame, position::ConstantAcceleration>>();
}

TEST_CASE_TEMPLATE("forces accumulate for one step and act through the inverse mass", R, float,
                   double) {
  Particle<R, damping::None, position::SemiImplicit> p;
  p.set_mass(R(2));
  p.add_force({R(2), R(0), R(0)});
  p.add_force({R(0), R(4), R(0)});
  CHECK(p.force_accumulator() == Vector3<R>{R(2), R(4), R(0)});
  p.integrate(R(1));
  CHECK(p.velocity() == Vector3<R>{R(1), R(2), R(0)});  // f / m t
  p.integrate(R(1));                                    // no force now: constant velocity
  CHECK(p.velocity() == Vector3<R>{R(1), R(2), R(0)});
  p.add_force({R(2), R(0), R(0)});
  p.clear_accumulator();
  CHECK(p.force_accumulator() == Vector3<R>{});
}

TEST_CASE("a fixed-step loop computes the damping factors once, and again only when needed") {
  using pointmass::test::CountingPerSecond;
  using Counted = Particle<float, CountingPerSecond>;
  static_assert(Counted::caches_factors);
  Counted particle;
  particle.set_velocity({1.0f, 2.0f, 3.0f});
  particle.set_damping(0.5f);
  CountingPerSecond::factor_calls = 0;
  for (int i = 0; i < 10; ++i) particle.integrate(1.0f / 60);
  CHECK(CountingPerSecond::factor_calls == 1);  // ten steps of one length: one power
  particle.integrate(1.0f / 30);
  CHECK(CountingPerSecond::factor_calls == 2);  // a new length
  particle.integrate(1.0f / 60);
  CHECK(CountingPerSecond::factor_calls == 3);  // the old length again: one entry is kept
  particle.set_damping(0.9f);
  particle.integrate(1.0f / 60);
  CHECK(CountingPerSecond::factor_calls == 4);  // a new damping, the same length
  Counted copy = particle;
  copy.integrate(1.0f / 60);
  CHECK(CountingPerSecond::factor_calls == 4);  // a copy carries the kept factors
  particle.integrate(0.0f);
  CHECK(CountingPerSecond::factor_calls == 4);  // a zero step computes none
}

TEST_CASE_TEMPLATE(
    "a repeated step length reuses the damping factors, a new length or damping does not", D,
    damping::PerSecond, damping::AccelerateThenDamp, damping::Exact) {
  using R = float;
  using Counting = pointmass::test::CountingFactors<D>;
  static_assert(DampingPolicy<Counting>);
  static_assert(Particle<R, D>::caches_factors && Particle<R, Counting>::caches_factors);
  Particle<R, D> particle;
  Particle<R, Counting> counted;  // the same steps, counting the factors it computes
  const Vector3<R> a{R(0), R(-9.8f), R(1)};
  Vector3<R> v{R(1), R(2), R(3)};
  particle.set_velocity(v);
  particle.set_acceleration(a);
  counted.set_velocity(v);
  counted.set_acceleration(a);
  Counting::factor_calls = 0;
  // Each step against the policy's own factors computed afresh: equal bit for bit; `calls`
  // is how many factors the counted particle has computed after the step.
  const auto step = [&](R t, R d, int calls) {
    CAPTURE(t);
    CAPTURE(d);
    v = D::velocity(v, a, t, D::factors(typename D::template State<R>(d), t));
    particle.integrate(t);
    counted.integrate(t);
    CHECK(particle.velocity() == v);
    CHECK(counted.velocity() == v);
    CHECK(Counting::factor_calls == calls);
  };
  particle.set_damping(R(0.5));
  counted.set_damping(R(0.5));
  step(R(1) / R(60), R(0.5), 1);
  step(R(1) / R(60), R(0.5), 1);  // the same length: reused
  step(R(1) / R(30), R(0.5), 2);  // a new length
  step(R(1) / R(60), R(0.5), 3);  // the old length again: only the last one is kept
  particle.set_damping(R(0.05));
  counted.set_damping(R(0.05));
  step(R(1) / R(60), R(0.05), 4);  // a new damping, the same length
  step(R(1) / R(60), R(0.05), 4);
  const Particle<R, D> copy = particle;  // a copy carries the kept factors with it
  const Particle<R, Counting> counted_copy = counted;
  particle.set_damping(R(0.9));
  counted.set_damping(R(0.9));
  step(R(1) / R(60), R(0.9), 5);
  const Vector3<R> copy_velocity =
      D::velocity(copy.velocity(), a, R(1) / R(60),
                  D::factors(typename D::template State<R>(R(0.05)), R(1) / R(60)));
  Particle<R, D> other = copy;
  other.integrate(R(1) / R(60));
  CHECK(other.velocity() == copy_velocity);
  Particle<R, Counting> counted_other = counted_copy;
  counted_other.integrate(R(1) / R(60));
  CHECK(counted_other.velocity() == copy_velocity);
  CHECK(Counting::factor_calls == 5);  // the copy's kept factors, not the original's new ones
}
