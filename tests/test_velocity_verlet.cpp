// SPDX-License-Identifier: BSL-1.0
// position::VelocityVerlet (position.hpp): the exact discrete equations, bit for bit against a
// hand loop of the scheme with a changing step length; exact for constant acceleration without
// damping and for damping alone; second order on the spring, damped and undamped; the pairs it
// composes with. (Against Odeint at every frame time: tests/reference/test_convergence.cpp; a
// ParticleSystem against Particles: tests/system/test_equivalence.cpp.)
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include <pointmass/particle.hpp>

#include "ulp.hpp"

using namespace pointmass;
using pointmass::test::same_bits;

namespace {

using Verlet = position::VelocityVerlet;

// A spring to the origin (stiffness 40 per unit mass) and a drag -0.3 v, as add_force takes them.
template <class R>
Vector3<R> spring_and_drag(const Vector3<R>& p, const Vector3<R>& v) {
  return p * R(-40) + v * R(-0.3);
}

}  // namespace

TEST_CASE_TEMPLATE("VelocityVerlet is its discrete equations, bit for bit, as the step changes", R,
                   float, double) {
  // The hand loop: the kick credited at the last step settled with this step's acceleration,
  // half a kick, the retention d (PerFrame), the trapezoid drift, half a kick on credit.
  constexpr std::array<double, 5> lengths{1.0 / 60, 1.0 / 30, 0.1, 0.005, 1.0 / 60};
  Particle<R, damping::PerFrame, Verlet> particle;
  const R d = R(0.9);
  particle.set_damping(d);
  particle.set_mass(R(2));
  particle.set_acceleration({R(0), R(-9.8), R(0)});
  particle.set_position({R(1), R(2), R(-1)});
  particle.set_velocity({R(0.5), R(0), R(3)});
  Vector3<R> p = particle.position();
  Vector3<R> v = particle.velocity();
  Vector3<R> kick{};
  R last_half = R(0);
  for (int n = 0; n < 40; ++n) {
    const R t = static_cast<R>(lengths[static_cast<std::size_t>(n) % lengths.size()]);
    const Vector3<R> force = spring_and_drag(particle.position(), particle.velocity());
    particle.add_force(force);
    particle.integrate(t);
    const Vector3<R> a = Vector3<R>{R(0), R(-9.8), R(0)} + force * R(0.5);
    const R half = t * R(0.5);
    const Vector3<R> v0 = v - kick + a * (last_half + half);
    const Vector3<R> v1 = v0 * d;
    p = p + (v0 + v1) * half;
    kick = a * half;
    v = v1 + kick;
    last_half = half;
    INFO("step ", n);
    REQUIRE(same_bits(particle.position(), p));
    REQUIRE(same_bits(particle.velocity(), v));
    REQUIRE(same_bits(particle.credited_kick(), kick));
  }
}

TEST_CASE_TEMPLATE("VelocityVerlet is exact for constant acceleration without damping", R, float,
                   double) {
  // p0 + v0 t + g t^2 / 2 and v0 + g t at any step lengths, to rounding.
  Particle<R, damping::None, Verlet> particle;
  const Vector3<R> g{R(0), R(-9.807), R(1)};
  particle.set_acceleration(g);
  particle.set_velocity({R(30), R(40), R(0)});
  double time = 0;
  for (const double t : {0.01, 0.1, 0.02, 0.5, 0.03, 0.25, 0.1}) {
    particle.integrate(static_cast<R>(t));
    time += static_cast<double>(static_cast<R>(t));
  }
  const double tolerance = sizeof(R) == 4 ? 2e-4 : 1e-12;
  CHECK(std::abs(double(particle.position().x) - 30 * time) < tolerance * 30 * time);
  CHECK(std::abs(double(particle.position().y) - (40 * time - 9.807 * time * time / 2)) <
        tolerance * 40 * time);
  CHECK(std::abs(double(particle.velocity().y) - (40 - 9.807 * time)) < tolerance * 40);
  CHECK(std::abs(double(particle.position().z) - time * time / 2) < tolerance * 40 * time);
}

TEST_CASE_TEMPLATE("VelocityVerlet under damping alone keeps exactly the retention each step", R,
                   float, double) {
  Particle<R, damping::PerSecond, Verlet> verlet;
  Particle<R, damping::PerSecond, position::SemiImplicit> semi;
  verlet.set_damping(R(0.5));
  semi.set_damping(R(0.5));
  verlet.set_velocity({R(3), R(-1), R(2)});
  semi.set_velocity({R(3), R(-1), R(2)});
  for (int n = 0; n < 30; ++n) {
    verlet.integrate(R(1) / R(60));
    semi.integrate(R(1) / R(60));
    // Both velocities are v d^t each step, the same retention: the same bits.
    REQUIRE(same_bits(verlet.velocity(), semi.velocity()));
  }
}

TEST_CASE("VelocityVerlet is second order on the spring, damped and undamped") {
  // One period of the 1 s spring (and with damping 0.5 per second and a drag of 0.5 v): the
  // largest distance from the closed form x = e^(-gt) (cos(wd t) + g / wd sin(wd t)) over
  // the period. Each halving of the step from 1/30 s divides it by about 4 (order 2 +- 0.1).
  const double pi = std::acos(-1.0);
  const double w2 = 4 * pi * pi;
  const auto largest_error = [&](double h, bool damped) {
    Particle<double, damping::PerSecond, Verlet> particle;
    particle.set_position({1, 0, 0});
    if (damped) particle.set_damping(0.5);
    const double gamma = damped ? (0.5 - std::log(0.5)) / 2 : 0.0;
    const double wd = std::sqrt(w2 - gamma * gamma);
    const long steps = std::lround(1 / h);
    double largest = 0;
    for (long n = 1; n <= steps; ++n) {
      particle.add_force(particle.position() * -w2 + particle.velocity() * (damped ? -0.5 : 0));
      particle.integrate(h);
      const double t = static_cast<double>(n) * h;
      const double x = std::exp(-gamma * t) * (std::cos(wd * t) + gamma / wd * std::sin(wd * t));
      largest = std::max(largest, magnitude(particle.position() - Vector3<double>{x, 0, 0}));
    }
    return largest;
  };
  for (const bool damped : {false, true}) {
    double previous = 0;
    for (const double h : {1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240}) {
      const double error = largest_error(h, damped);
      if (previous > 0) {
        INFO("damped: ", damped, ", h = 1/", 1 / h, ", error ", error);
        CHECK(std::log2(previous / error) > 1.9);
        CHECK(std::log2(previous / error) < 2.1);
      }
      previous = error;
    }
  }
  // At 1/60 s undamped, within a tenth of SemiImplicit's 5.46e-2 (docs/accuracy.md).
  CHECK(largest_error(1.0 / 60, false) < 5.46e-3);
}

TEST_CASE("VelocityVerlet composes with every damping policy but Cyclone's order") {
  static_assert(PositionPolicyFor<Verlet, damping::None>);
  static_assert(PositionPolicyFor<Verlet, damping::PerFrame>);
  static_assert(PositionPolicyFor<Verlet, damping::PerSecond>);
  static_assert(PositionPolicyFor<Verlet, damping::Exact>);
  // (AccelerateThenDamp: compile-fail test velocity_verlet_with_cyclone_order.)
  static_assert(!PositionPolicyFor<Verlet, damping::AccelerateThenDamp>);
  static_assert(order_v<damping::PerSecond, Verlet> == 2);
  static_assert(order_v<damping::PerSecond, position::SemiImplicit> == 1);
  static_assert(is_exact_for_constant_acceleration_v<damping::None, Verlet>);
  static_assert(!is_exact_for_constant_acceleration_v<damping::PerSecond, Verlet>);
  CHECK(sizeof(Particle<float, damping::None, Verlet>) ==
        sizeof(Particle<float, damping::None, position::SemiImplicit>) + 4 * sizeof(float));
}
