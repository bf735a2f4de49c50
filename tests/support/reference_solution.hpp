// SPDX-License-Identifier: BSL-1.0
// Reference solutions of the continuous model every policy combination approximates.
//
// The model of one particle, with the resulting acceleration of a constant acceleration g, a
// spring to the origin (stiffness K) and a friction force (coefficient c), and linear
// per-second damping at rate k = ln d (k = 0 for no damping):
//
//   dp/dt = v
//   dv/dt = g - (K/m) p - (c/m) v + k v
//
// Per-frame damping d at frame time h is the same model with k = ln(d) / h.
//
// Two solutions:
//   * `odeint_trajectory`: Boost.Odeint's runge_kutta_dopri5 with dense output, absolute and
//     relative tolerance 1e-12, plain std::array<double, 6> state, sampled at n h for
//     n = 0 .. steps by integrate_n_steps (never integrate_const, which may drop the last
//     step when the end time is not an exact multiple of h);
//   * `analytic_ballistic`: the closed form without a spring, in long double:
//       v(t) = v0 e^{kt} + g t phi1(kt),  p(t) = p0 + v0 t phi1(kt) + g t^2 phi2(kt),
//     phi1(x) = (e^x - 1)/x, phi2(x) = (e^x - 1 - x)/x^2, evaluated by expm1 (and a series
//     near x = 0), written independently of the library's own evaluation.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include <pointmass/vector3.hpp>

namespace pointmass::reference {

using State = std::array<double, 6>;  ///< p (0..2), v (3..5)

/// The continuous model's parameters (all per unit mass, SI units).
struct Model {
  Vector3<double> gravity{};  ///< constant acceleration g, m/s^2
  double stiffness = 0;       ///< K/m, 1/s^2
  double friction = 0;        ///< c/m, 1/s
  double damping_rate = 0;    ///< k = ln d, 1/s (<= 0)

  void operator()(const State& y, State& dydt, double /*t*/) const {
    const double g[3] = {gravity.x, gravity.y, gravity.z};
    for (std::size_t i = 0; i < 3; ++i) {
      dydt[i] = y[3 + i];
      dydt[3 + i] = g[i] - stiffness * y[i] + (damping_rate - friction) * y[3 + i];
    }
  }
};

/// A sample of a trajectory.
struct Sample {
  Vector3<double> position;
  Vector3<double> velocity;
};

inline State to_state(const Vector3<double>& p, const Vector3<double>& v) {
  return {p.x, p.y, p.z, v.x, v.y, v.z};
}
inline Sample to_sample(const State& y) { return {{y[0], y[1], y[2]}, {y[3], y[4], y[5]}}; }

/// The model's solution at t = n h, n = 0 .. steps (steps + 1 samples), by dopri5 with dense
/// output at absolute and relative `tolerance` (1e-12 unless a test needs it tighter).
inline std::vector<Sample> odeint_trajectory(const Model& model, const Vector3<double>& p0,
                                             const Vector3<double>& v0, double h, long steps,
                                             double tolerance = 1e-12) {
  namespace odeint = boost::numeric::odeint;
  std::vector<Sample> samples;
  samples.reserve(static_cast<std::size_t>(steps) + 1);
  State y = to_state(p0, v0);
  auto stepper =
      odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  odeint::integrate_n_steps(
      stepper, model, y, 0.0, h, static_cast<std::size_t>(steps),
      [&](const State& state, double) { samples.push_back(to_sample(state)); });
  if (samples.size() != static_cast<std::size_t>(steps) + 1) {
    throw std::logic_error("odeint_trajectory: " + std::to_string(samples.size()) +
                           " samples for " + std::to_string(steps) + " steps");
  }
  return samples;
}

/// phi1(x) = (e^x - 1)/x and phi2(x) = (e^x - 1 - x)/x^2 in long double, x <= 0 finite.
inline long double phi1(long double x) {
  if (x == 0.0L) return 1.0L;
  return std::expm1(x) / x;
}
inline long double phi2(long double x) {
  if (std::fabs(x) < 0.125L) {  // series: sum x^n / (n + 2)!, 20 terms
    long double term = 0.5L, sum = 0.0L;
    for (int n = 0; n < 20; ++n) {
      sum += term;
      term *= x / static_cast<long double>(n + 3);
    }
    return sum;
  }
  return (std::expm1(x) - x) / (x * x);
}

/// The exact solution without a spring (constant g, damping rate k), at time t, in long
/// double. k = -infinity (d = 0) is the limit: the velocity is removed at once.
inline Sample analytic_ballistic(const Vector3<double>& p0, const Vector3<double>& v0,
                                 const Vector3<double>& g, double rate, double time) {
  const auto k = static_cast<long double>(rate), t = static_cast<long double>(time);
  const auto component = [&](double p, double v, double a, long double& p_t, long double& v_t) {
    if (std::isinf(k)) {  // d = 0: v(t) = 0 for t > 0, p stays
      p_t = static_cast<long double>(p);
      v_t = t > 0.0L ? 0.0L : static_cast<long double>(v);
      return;
    }
    const long double x = k * t;
    v_t = static_cast<long double>(v) * std::exp(x) + static_cast<long double>(a) * t * phi1(x);
    p_t = static_cast<long double>(p) + static_cast<long double>(v) * t * phi1(x) +
          static_cast<long double>(a) * t * t * phi2(x);
  };
  long double p[3], v[3];
  component(p0.x, v0.x, g.x, p[0], v[0]);
  component(p0.y, v0.y, g.y, p[1], v[1]);
  component(p0.z, v0.z, g.z, p[2], v[2]);
  return {{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])},
          {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])}};
}

}  // namespace pointmass::reference
