// SPDX-License-Identifier: BSL-1.0
// The stiff springs where the closed form's differences cancel: a weak spring (w0 t small)
// with any damping. The oracle is the closed form itself in 100-digit arithmetic
// (Boost.Multiprecision), where those differences keep their digits:
//   * detail::push_response (psi / t, Q / t^2, Q2 / t^3) within a few epsilons over a grid
//     of w0 t and gamma t;
//   * PositionOnlyStiffSpring's force, m [ (x(t) - x0) / t - v0 ] / t, within a few epsilons
//     of its scale, where the difference quotient lost every digit (a force of 0);
//   * StiffSpring::integrate under gravity with strong damping: the exact trajectory, the
//     terminal velocity included (a half-kick splitting left a t / 2 instead).
#include <doctest/doctest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

namespace {

using pointmass::Vector3;
namespace forces = pointmass::forces;
using Big = boost::multiprecision::cpp_bin_float_100;

/// The push's response in 100 digits, from the textbook closed form of each regime:
/// phi(t) (released at 1 from rest), psi(t) (released at 0 with velocity 1), then
/// Q = (1 - phi) / w0^2 and Q2 = (t - psi - 2 gamma Q) / w0^2 (or, for w0 = 0, the drift
/// under drag: Q = (t - psi) / (2 gamma), Q2 = (t^2 / 2 - Q) / (2 gamma)).
struct BigResponse {
  Big phi, psi, q, q2;  // phi and psi themselves; q = Q, q2 = Q2 (not scaled)
};

BigResponse big_response(const Big& w0_squared, const Big& gamma, const Big& t) {
  using boost::multiprecision::cos;
  using boost::multiprecision::cosh;
  using boost::multiprecision::exp;
  using boost::multiprecision::sin;
  using boost::multiprecision::sinh;
  using boost::multiprecision::sqrt;
  BigResponse r;
  if (w0_squared == 0) {
    if (gamma == 0) return {Big(1), t, t * t / 2, t * t * t / 6};
    r.phi = 1;
    r.psi = (1 - exp(-2 * gamma * t)) / (2 * gamma);
    r.q = (t - r.psi) / (2 * gamma);
    r.q2 = (t * t / 2 - r.q) / (2 * gamma);
    return r;
  }
  const Big decay = exp(-gamma * t);
  const Big g2 = gamma * gamma;
  if (g2 < w0_squared) {
    const Big omega = sqrt(w0_squared - g2);
    r.phi = decay * (cos(omega * t) + gamma * sin(omega * t) / omega);
    r.psi = decay * sin(omega * t) / omega;
  } else if (g2 > w0_squared) {
    const Big lambda = sqrt(g2 - w0_squared);
    r.phi = decay * (cosh(lambda * t) + gamma * sinh(lambda * t) / lambda);
    r.psi = decay * sinh(lambda * t) / lambda;
  } else {
    r.phi = decay * (1 + gamma * t);
    r.psi = t * decay;
  }
  r.q = (1 - r.phi) / w0_squared;
  r.q2 = (t - r.psi - 2 * gamma * r.q) / w0_squared;
  return r;
}

template <class R>
double error_in_epsilons(R got, const Big& exact, const Big& scale) {
  return double(abs((Big(got) - exact) / scale)) / double(std::numeric_limits<R>::epsilon());
}

}  // namespace

TEST_CASE_TEMPLATE(
    "push response: psi / t, Q / t^2 and Q2 / t^3 within 16 epsilons of 100 "
    "digits, for w0 t up to 2 and any damping",
    R, float, double) {
  // Every region of push_response: the series (w0 t, gamma t <= 2), the over-damped closed
  // forms (up to gamma t = 1000) and the differences (w0 t near 2, gamma t beyond 2), with
  // w0 = 0 and gamma = 0 among them; each at steps of 1/60, 1e-3 and 1 s.
  double worst = 0;
  for (const double t : {1.0 / 60, 1e-3, 1.0}) {
    for (const double a : {0.0, 1e-8, 1e-4, 0.01, 0.3, 0.7, 0.99, 1.0, 1.5, 1.99, 2.0}) {
      for (const double b : {0.0, 1e-8, 1e-4, 0.01, 0.3, 0.99, 1.0, 1.01, 1.5, 1.97, 2.0, 2.03, 3.0,
                             10.0, 100.0, 1000.0}) {
        const R step = R(t);
        const R w0 = R(a / t);
        const R w0_squared = w0 * w0;
        const R gamma = R(b / t);
        const auto got = forces::detail::push_response(w0_squared, gamma, step);
        const BigResponse exact = big_response(Big(w0_squared), Big(gamma), Big(step));
        const Big s(step);
        const double errors[] = {
            error_in_epsilons(got.psi_over_t, exact.psi / s, exact.psi / s),
            error_in_epsilons(got.q, exact.q / (s * s), exact.q / (s * s)),
            error_in_epsilons(got.q2, exact.q2 / (s * s * s), exact.q2 / (s * s * s))};
        CAPTURE(t);
        CAPTURE(a);
        CAPTURE(b);
        CAPTURE(errors[0]);
        CAPTURE(errors[1]);
        CAPTURE(errors[2]);
        for (const double e : errors) {
          CHECK(e <= 16);
          worst = std::max(worst, e);
        }
      }
    }
  }
  MESSAGE("worst push_response error (epsilons): " << worst);
}

TEST_CASE_TEMPLATE(
    "position-only stiff spring: the force m ((x(t) - x0) / t - v0) / t within "
    "16 epsilons of its scale, a weak spring with damping included",
    R, float, double) {
  // A weak spring with damping: w0 t far below the cube root of epsilon, gamma t not. The
  // difference quotient of the closed form lost the whole spring term there (float: k = 1e-4,
  // c = 1, m = 1 at 60 Hz from x0 = 1000 gave a force of 0 for -0.0497).
  struct Case {
    double k, c, mass, dt, x0, v0;
  };
  const Case cases[] = {{1e-4, 1, 1, 1.0 / 60, 10, 0},     {1e-4, 1, 1, 1.0 / 60, 100, 0},
                        {1e-4, 1, 1, 1.0 / 60, 1000, 0},   {1e-12, 1, 1, 1.0 / 60, 1, 0},
                        {1e-12, 1, 1, 1.0 / 60, 1000, 0},  {1e-4, 1, 1, 1.0 / 60, 1000, -3},
                        {1, 1000, 1, 0.5, 2, 1},           {50, 3, 2, 1.0 / 60, 0.5, 4},
                        {1e6, 0.01, 1, 1.0 / 60, 1e-3, 0}, {4, 4, 1, 0.1, 1, -1},
                        {0, 2, 1, 1.0 / 60, 5, 7},         {10, 600, 1, 1.0 / 60, -3, 0.25},
                        {1e-4, 0, 1, 1.0 / 60, 1000, 2},   {1, 1e-3, 3, 1.0 / 30, 100, 0}};
  for (const Case& e : cases) {
    const R inverse_mass = R(1) / R(e.mass);
    const R dt = R(e.dt);
    const forces::PositionOnlyStiffSpring<R> spring({}, R(e.k), R(e.c));
    const Vector3<R> x{R(e.x0), R(0), R(0)};
    const Vector3<R> v{R(e.v0), R(0), R(0)};
    const R f = spring.force(x, v, inverse_mass, dt).x;
    // The exact force for the rounded inputs: m [ (x(t) - x0) / t - v0 ] / t, x(t) = x0 phi +
    // v0 psi (phi and psi of the rounded w0^2 and gamma the spring forms from them).
    const R w0_squared = R(e.k) * inverse_mass;
    const R gamma = R(e.c) * inverse_mass / R(2);
    const BigResponse r = big_response(Big(w0_squared), Big(gamma), Big(dt));
    const Big t(dt);
    const Big m = Big(1) / Big(inverse_mass);
    const Big x0(x.x);
    const Big v0(v.x);
    const Big exact = m * (((x0 * r.phi + v0 * r.psi) - x0) / t - v0) / t;
    // The scale the force is accurate to: what it adds up (|k Q x0| and |(c Q + k Q2) v0|,
    // over t^2), each rounded in R.
    const Big scale =
        (abs(Big(R(e.k)) * x0 * r.q) + abs((Big(R(e.c)) * r.q + Big(R(e.k)) * r.q2) * v0)) /
        (t * t);
    CAPTURE(e.k);
    CAPTURE(e.c);
    CAPTURE(e.mass);
    CAPTURE(e.dt);
    CAPTURE(e.x0);
    CAPTURE(e.v0);
    CAPTURE(f);
    CAPTURE(double(exact));
    CHECK(error_in_epsilons(f, exact, scale) <= 16);
    CHECK(double(f) * double(exact) > 0);  // the right sign, and not a cancelled 0
  }
}

TEST_CASE_TEMPLATE(
    "stiff spring integrate under gravity with strong damping: the exact trajectory, "
    "terminal velocity included",
    R, float, double) {
  // m x'' = -k x - c x' + m g: with c t / m large and w0 t small the velocity is the terminal
  // m g / c within a step or two. Exact for constant g at every step, so after n steps the
  // state is the closed form's at n t (to the rounding of n steps).
  struct Case {
    double k, c, dt;
    int steps;
  };
  for (const Case e : {Case{1, 1000, 0.5, 10}, Case{10, 600, 1.0 / 60, 60},
                       Case{1e-4, 50, 1.0 / 60, 120}, Case{0, 20, 0.1, 50}}) {
    const R g = R(-9.807);
    pointmass::Particle<R, pointmass::damping::None, pointmass::position::SemiImplicit> body;
    body.set_position({R(1), R(0), R(0)});
    body.set_acceleration({g, R(0), R(0)});
    const forces::StiffSpring<R> spring({}, R(e.k), R(e.c));
    for (int n = 0; n < e.steps; ++n) spring.integrate(body, R(e.dt));
    // The closed form at n t: the released body's x0 phi plus g Q (the push's response).
    const R w0_squared = R(e.k);  // mass 1
    const R gamma = R(e.c) / R(2);
    const Big t = Big(R(e.dt)) * e.steps;
    const BigResponse r = big_response(Big(w0_squared), Big(gamma), t);
    const Big exact_x = r.phi + Big(g) * r.q;
    // d/dt of x0 phi is -w0^2 psi (phi' = -w0^2 psi), of g Q is g psi
    const Big exact_v = -Big(w0_squared) * r.psi + Big(g) * r.psi;
    const double tolerance = std::is_same_v<R, float> ? 1e-5 : 1e-13;
    const Big x_scale = 1 + abs(Big(g) * r.q);
    const Big v_scale = 1 + abs(exact_v);
    CAPTURE(e.k);
    CAPTURE(e.c);
    CAPTURE(e.dt);
    CAPTURE(body.position().x);
    CAPTURE(double(exact_x));
    CAPTURE(body.velocity().x);
    CAPTURE(double(exact_v));
    CHECK(double(abs(Big(body.position().x) - exact_x) / x_scale) < tolerance);
    CHECK(double(abs(Big(body.velocity().x) - exact_v) / v_scale) < tolerance);
  }
}
