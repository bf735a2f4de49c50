// SPDX-License-Identifier: BSL-1.0
// Every policy's equation, one step, against values worked out by hand and against an
// independent long double oracle, for every damping x position combination, float and
// double. Tolerances are in units of the type's epsilon.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <pointmass/pointmass.hpp>

#include "combinations.hpp"
#include "tolerance.hpp"

using namespace pointmass;
using test::close;

namespace {

template <class R>
Vector3<R> vec(const long double (&v)[3]) {
  return {R(v[0]), R(v[1]), R(v[2])};
}

}  // namespace

TEST_CASE_TEMPLATE_DEFINE("one step matches the policy's equations", C, one_step_id) {
  using R = typename C::real;
  using D = typename C::damping;
  using P = typename C::position;
  // Resulting acceleration a = acceleration + force * inverse mass = (0,-10,0) + (2,0,-4)/4.
  typename C::particle particle;
  particle.set_position({R(10), R(20), R(30)});
  particle.set_velocity({R(1), R(2), R(3)});
  particle.set_acceleration({R(0), R(-10), R(0)});
  particle.set_mass(R(4));
  if constexpr (C::particle::stores_damping) particle.set_damping(R(0.5));
  particle.add_force({R(2), R(0), R(-4)});

  const R t = R(0.5);
  particle.integrate(t);

  const test::OracleState start{{10, 20, 30}, {1, 2, 3}};
  const long double a[3] = {0.5L, -10, -1};
  const long double d = C::particle::stores_damping ? 0.5L : 1.0L;
  const auto expected = test::oracle_step<D, P>(start, a, d, static_cast<long double>(t));

  INFO("position ", particle.position(), " velocity ", particle.velocity());
  CHECK(close(particle.position(), vec<R>(expected.p), R(16)));
  CHECK(close(particle.velocity(), vec<R>(expected.v), R(16)));
  CHECK(particle.force_accumulator() == Vector3<R>{});               // cleared by the step
  CHECK(particle.acceleration() == Vector3<R>{R(0), R(-10), R(0)});  // left alone
}
TEST_CASE_TEMPLATE_APPLY(one_step_id, test::AllCombinations);

TEST_CASE_TEMPLATE_DEFINE("many steps match a loop of the exact discrete equations", C,
                          many_steps_id) {
  using R = typename C::real;
  using D = typename C::damping;
  using P = typename C::position;
  typename C::particle particle;
  particle.set_position({R(0), R(1.5), R(0)});
  particle.set_velocity({R(0), R(30), R(40)});
  particle.set_acceleration({R(0), R(-20), R(0)});
  if constexpr (C::particle::stores_damping) particle.set_damping(R(0.99L));  // as the oracle's d
  const long double d = C::particle::stores_damping ? 0.99L : 1.0L;

  test::OracleState state{{0, 1.5L, 0}, {0, 30, 40}};
  const R t = R(1) / R(60);
  constexpr int steps = 300;
  for (int i = 0; i < steps; ++i) {
    // A force that changes every step (mass 1): exercises the accumulator each time.
    const R push = R(i % 7) - R(3);
    particle.add_force({push, R(0), R(0)});
    particle.integrate(t);
    const long double a[3] = {static_cast<long double>(push), -20, 0};
    state = test::oracle_step<D, P>(state, a, d, static_cast<long double>(t));
  }
  // Rounding grows at most linearly with the steps: a few ulps a step, relative to the
  // largest coordinate (the trajectory reaches about 200 m).
  const R ulps = R(4 * steps);
  INFO("position ", particle.position(), " velocity ", particle.velocity());
  CHECK(close(particle.position(), vec<R>(state.p), ulps, R(200)));
  CHECK(close(particle.velocity(), vec<R>(state.v), ulps, R(50)));
}
TEST_CASE_TEMPLATE_APPLY(many_steps_id, test::AllCombinations);

// The phi series' length follows the significand, not the size of the type: a 64-bit
// x87 long double and a 113-bit quad one have the same size but need 21 and 31 terms.
static_assert(detail::phi_terms_for(std::numeric_limits<float>::digits) == 11);
static_assert(detail::phi_terms_for(std::numeric_limits<double>::digits) == 18);
static_assert(detail::phi_terms_for(64) == 21 && detail::phi_terms_for(113) == 31);
static_assert(detail::phi_terms<long double> ==
              detail::phi_terms_for(std::numeric_limits<long double>::digits));

namespace {

/// phi_offset(x) = sum_{n>=0} x^n / (n + offset)!, summed in long double from its smallest
/// term, 40 terms (for |x| <= 1 the omitted rest is below 1 / 41!).
long double phi_oracle(long double x, int offset) {
  long double term = 1;
  for (int n = 2; n <= offset; ++n) term /= n;  // 1 / offset!
  long double terms[40];
  for (int n = 0; n < 40; ++n) {
    terms[n] = term;
    term = term * x / static_cast<long double>(n + offset + 1);
  }
  long double sum = 0;
  for (int n = 39; n >= 0; --n) sum += terms[n];
  return sum;
}

}  // namespace

TEST_CASE_TEMPLATE("the phi series reach their type's precision on |x| < 1", R, float, double,
                   long double) {
  // Within 4 ulps of R, long double included.
  for (int i = -100; i <= 100; ++i) {
    const R x = R(i) / R(101);
    INFO("x = ", static_cast<double>(x));
    const long double wide = static_cast<long double>(x);
    CHECK(close(detail::phi_series<1>(x), static_cast<R>(phi_oracle(wide, 1)), R(4)));
    CHECK(close(detail::phi_series<2>(x), static_cast<R>(phi_oracle(wide, 2)), R(4)));
  }
}

TEST_CASE_TEMPLATE("damping::Exact's phi2 is within 4 ulps on each side of the series' edge", R,
                   float, double) {
  // phi2(x) = (e^x - 1 - x) / x^2 at x = t ln d, from random d in (e^-7, 1) and t chosen for
  // |x| in [0, 1.5] (the series below |x| = 1, (phi1 - 1) / x above) and in [1.5, 12]. The
  // oracle: x in long double, phi2 by its series for |x| <= 1 and by expm1l beyond, where
  // the cancellation costs long double less than 2 of its ulps (11 bits finer than double's).
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int outside = 0;
  for (int i = 0; i < 40000; ++i) {
    const double reach = i % 2 == 0 ? 1.5 * unit(random) : 1.5 + 10.5 * unit(random);
    const R d = static_cast<R>(std::exp(-7 * unit(random)));
    const R t = static_cast<R>(reach / -std::log(static_cast<double>(d)));
    if (!(d > R(0) && d < R(1) && t > R(0))) continue;
    const damping::LogDamping<R> state(d);
    const R phi2 = damping::Exact::factors(state, t).phi2;
    const long double x = std::log(static_cast<long double>(d)) * static_cast<long double>(t);
    const long double oracle = x >= -1.0L ? phi_oracle(x, 2) : (std::expm1(x) - x) / (x * x);
    if (!close(phi2, static_cast<R>(oracle), R(4), R(0))) {
      if (outside == 0)
        MESSAGE("x = ", static_cast<double>(x), ": phi2 ", phi2, ", oracle ",
                static_cast<double>(oracle));
      ++outside;
    }
  }
  CHECK(outside == 0);
}

TEST_CASE_TEMPLATE("values worked out by hand", R, float, double) {
  // v0 = (1, 2, 3), a = (0, -10, 0), p0 = (10, 20, 30), d = 0.5, t = 0.5;
  // d^t = sqrt(0.5) = 0.70710678118654752.
  const R root_half = R(0.70710678118654752L);

  SUBCASE("eq. 3.6 with p + v t (the defaults)") {
    Particle<R> p;
    p.set_position({R(10), R(20), R(30)});
    p.set_velocity({R(1), R(2), R(3)});
    p.set_acceleration({R(0), R(-10), R(0)});
    p.set_damping(R(0.5));
    p.integrate(R(0.5));
    CHECK(close(p.position(), Vector3<R>{R(10.5), R(21), R(31.5)}, R(2)));
    CHECK(close(p.velocity(), Vector3<R>{root_half, R(2) * root_half - R(5), R(3) * root_half},
                R(4)));
  }
  SUBCASE("eq. 3.5 with p + v t + a t^2 / 2") {
    Particle<R, damping::PerFrame, position::ConstantAcceleration> p;
    p.set_position({R(10), R(20), R(30)});
    p.set_velocity({R(1), R(2), R(3)});
    p.set_acceleration({R(0), R(-10), R(0)});
    p.set_damping(R(0.5));
    p.integrate(R(0.5));
    CHECK(close(p.position(), Vector3<R>{R(10.5), R(19.75), R(31.5)}, R(2)));
    CHECK(close(p.velocity(), Vector3<R>{R(0.5), R(-4), R(1.5)}, R(2)));
  }
  SUBCASE("the listing's form with p + v' t") {
    Particle<R, damping::AccelerateThenDamp, position::SemiImplicit> p;
    p.set_position({R(10), R(20), R(30)});
    p.set_velocity({R(1), R(2), R(3)});
    p.set_acceleration({R(0), R(-10), R(0)});
    p.set_damping(R(0.5));
    p.integrate(R(0.5));
    // (v0 + a t) d^t = (1, -3, 3) sqrt(0.5)
    const Vector3<R> v1{root_half, R(-3) * root_half, R(3) * root_half};
    CHECK(close(p.velocity(), v1, R(4)));
    CHECK(close(p.position(), Vector3<R>{R(10), R(20), R(30)} + v1 * R(0.5), R(4)));
  }
  SUBCASE("the exact pair") {
    // (d^t - 1) / ln d = 0.42255559429217389, ((d^t - 1) / ln d - t) / ln d = 0.11172866005927369
    Particle<R, damping::Exact, position::Exact> p;
    p.set_position({R(10), R(20), R(30)});
    p.set_velocity({R(1), R(2), R(3)});
    p.set_acceleration({R(0), R(-10), R(0)});
    p.set_damping(R(0.5));
    p.integrate(R(0.5));
    CHECK(close(p.velocity(),
                Vector3<R>{root_half, R(2) * root_half - R(4.2255559429217389L), R(3) * root_half},
                R(8)));
    CHECK(
        close(p.position(),
              Vector3<R>{R(10.422555594292173894L), R(19.727824587991611L), R(31.267666782876521L)},
              R(8)));
  }
}

TEST_CASE_TEMPLATE("constant-acceleration flight matches p0 + v0 t + a t^2 / 2", R, float, double) {
  // ConstantAcceleration without damping is exact for constant acceleration; so is the exact pair.
  const Vector3<R> p0{R(0), R(1.5), R(0)};
  const Vector3<R> v0{R(3), R(30), R(40)};
  const Vector3<R> a = gravity(earth_gravity<R>);
  constexpr int steps = 240;
  const R t = R(1) / R(60);

  Particle<R, damping::None, position::ConstantAcceleration> kinematic;
  Particle<R, damping::None, position::Exact> exact;
  kinematic.set_position(p0);
  kinematic.set_velocity(v0);
  kinematic.set_acceleration(a);
  exact.set_position(p0);
  exact.set_velocity(v0);
  exact.set_acceleration(a);
  for (int i = 0; i < steps; ++i) {
    kinematic.integrate(t);
    exact.integrate(t);
  }
  const long double time = static_cast<long double>(t) * steps;
  const Vector3<R> expected{R(0 + 3 * time), R(1.5L + 30 * time - 9.807L * time * time / 2),
                            R(40 * time)};
  const Vector3<R> expected_velocity{R(3), R(30 - 9.807L * time), R(40)};
  const R ulps = R(4 * steps);
  CHECK(close(kinematic.position(), expected, ulps, R(160)));
  CHECK(close(kinematic.velocity(), expected_velocity, ulps, R(40)));
  CHECK(close(exact.position(), expected, ulps, R(160)));
  // The short form is not exact: it lags by a t T / 2 in height.
  Particle<R, damping::None, position::Euler> euler;
  euler.set_position(p0);
  euler.set_velocity(v0);
  euler.set_acceleration(a);
  for (int i = 0; i < steps; ++i) euler.integrate(t);
  const R lag = R(9.807L * static_cast<long double>(t) * time / 2);
  CHECK(close(euler.position().y, expected.y + lag, ulps, R(160)));
}

TEST_CASE_TEMPLATE("per-second damping is frame-rate independent, per-frame is not", R, float,
                   double) {
  const R t = R(0.05);
  const R d = R(0.9);
  const Vector3<R> v0{R(1), R(-2), R(3)};

  Particle<R, damping::PerSecond> one, two;
  one.set_velocity(v0);
  two.set_velocity(v0);
  one.set_damping(d);
  two.set_damping(d);
  one.integrate(R(2) * t);
  two.integrate(t);
  two.integrate(t);
  CHECK(close(one.velocity(), two.velocity(), R(4)));

  Particle<R, damping::PerFrame> frame_one, frame_two;
  frame_one.set_velocity(v0);
  frame_two.set_velocity(v0);
  frame_one.set_damping(d);
  frame_two.set_damping(d);
  frame_one.integrate(R(2) * t);
  frame_two.integrate(t);
  frame_two.integrate(t);
  // One frame keeps d, two keep d^2: halving the frame time removes d (1 - d) v0 more.
  CHECK(close(frame_one.velocity(), v0 * d, R(2)));
  CHECK(close(frame_two.velocity(), v0 * (d * d), R(4)));
  CHECK(close(frame_one.velocity() - frame_two.velocity(), v0 * (d * (R(1) - d)), R(16)));
}

TEST_CASE_TEMPLATE("eq. 3.6 and the listing's form differ by a t (d^t - 1)", R, float, double) {
  const R t = R(0.1);
  const R d = R(0.8);
  const Vector3<R> a{R(0), R(-10), R(2)};
  Particle<R, damping::PerSecond> text;
  Particle<R, damping::AccelerateThenDamp> listing;
  text.set_damping(d);
  listing.set_damping(d);
  text.set_acceleration(a);
  listing.set_acceleration(a);
  text.set_velocity({R(5), R(5), R(5)});
  listing.set_velocity({R(5), R(5), R(5)});
  text.integrate(t);
  listing.integrate(t);
  const R kept = std::pow(d, t);
  CHECK(close(listing.velocity() - text.velocity(), a * (t * (kept - R(1))), R(64), R(10)));
}

TEST_CASE("eq. 3.6 and the listing's form err by the same amount, opposite in sign") {
  // Exact: v1 = v0 d^t + a t phi1(kt); eq. 3.6 errs by a t (1 - phi1) ~ -a t kt / 2, the
  // listing by a t (d^t - phi1) ~ +a t kt / 2.
  using R = double;
  const R t = 1e-3;
  Particle<R, damping::PerSecond> text;
  Particle<R, damping::AccelerateThenDamp> listing;
  Particle<R, damping::Exact> exact;
  text.set_damping(0.5);
  listing.set_damping(0.5);
  exact.set_damping(0.5);
  text.set_acceleration({0, -10, 0});
  listing.set_acceleration({0, -10, 0});
  exact.set_acceleration({0, -10, 0});
  text.integrate(t);
  listing.integrate(t);
  exact.integrate(t);
  const R text_error = text.velocity().y - exact.velocity().y;
  const R listing_error = listing.velocity().y - exact.velocity().y;
  CHECK(text_error != 0);
  CHECK(listing_error / text_error == doctest::Approx(-1).epsilon(0.01));
  // ... and the size is a t kt / 2: 10 * 1e-3 * (1e-3 ln 2) / 2.
  CHECK(std::abs(text_error) == doctest::Approx(10 * t * t * std::log(2.0) / 2).epsilon(0.01));
}

TEST_CASE("the exact policies at the limits of damping: no NaN, the right limit") {
  using R = double;
  for (const R d : {1.0, 1.0 - 1e-7, 0.5, 1e-6, 0.0}) {
    INFO("d = ", doctest::String(std::to_string(d).c_str()), " (1 - d = ", 1 - d, ")");
    for (const R t : {1.0 / 60, 5.0}) {
      CAPTURE(t);
      Particle<R, damping::Exact, position::Exact> p;
      p.set_velocity({R(0), R(30), R(40)});
      p.set_acceleration({R(0), R(-20), R(0)});
      p.set_damping(d);
      p.integrate(t);
      REQUIRE(is_finite(p.position()));
      REQUIRE(is_finite(p.velocity()));
      const test::OracleState start{{0, 0, 0}, {0, 30, 40}};
      const long double a[3] = {0, -20, 0};
      if (d > 0) {
        const auto expected = test::oracle_step<damping::Exact, position::Exact>(
            start, a, static_cast<long double>(d), static_cast<long double>(t));
        INFO("position ", p.position(), " expected ", vec<R>(expected.p));
        CHECK(close(p.position(), vec<R>(expected.p), 16.0, 1.0));
        CHECK(close(p.velocity(), vec<R>(expected.v), 16.0, 1.0));
      } else {
        // d = 0: all velocity is removed at once and nothing moves.
        CHECK(p.velocity() == Vector3<R>{});
        CHECK(p.position() == Vector3<R>{});
      }
    }
  }
}

namespace {
// A position policy as a user writes one: the trapezoidal rule on the velocity,
// p1 = p0 + (v0 + v1) t / 2.
struct Trapezoid {
  static constexpr auto position(const auto& p0, const auto& v0, const auto& v1, const auto&,
                                 const auto& t, const auto&) {
    using R = scalar_t<std::remove_cvref_t<decltype(t)>>;
    return p0 + (v0 + v1) * (t * R(0.5));
  }
};
}  // namespace

TEST_CASE("a policy written by a user composes with the library's") {
  static_assert(PositionPolicyFor<Trapezoid, damping::None>);
  Particle<double, damping::None, Trapezoid> p;
  p.set_velocity({0, 10, 0});
  p.set_acceleration({0, -10, 0});
  p.integrate(0.5);
  // Without damping the trapezoid is exact: 10 * 0.5 - 10 * 0.25 / 2 = 3.75.
  CHECK(p.position().y == doctest::Approx(3.75).epsilon(1e-15));
  CHECK(p.velocity().y == 5.0);
}
