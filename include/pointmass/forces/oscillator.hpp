// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/oscillator.hpp — the damped harmonic oscillator in closed form, and the
// stiff springs built on it.
//
// Owns: OscillatorState, damped_oscillator (the exact solution of x'' = -w0^2 x - 2 gamma x'),
// StiffSpringParameters, StiffSpring (a step that sets a body's position and velocity from
// the closed form: exact at any step when the spring is the only force) and
// PositionOnlyStiffSpring (Cyclone's "fake spring" as a force: right positions
// for one step, a period sqrt(2) times too long; kept for compatibility).
// Must not include: particle.hpp, particle_system.hpp (the bodies are concepts, bodies.hpp),
// generators.hpp or registry.hpp.
#pragma once

#include <limits>

#include "../config.hpp"
#include "../detail/exponential.hpp"
#include "../detail/validate.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "bodies.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces {

/// A position and velocity (relative to the oscillator's rest point).
template <Real R>
struct OscillatorState {
  Vector3<R> position;
  Vector3<R> velocity;
};

/// The exact solution after time t >= 0 of x'' = -w0^2 x - 2 gamma x' from (x0, v0), with
/// w0^2 = k / m >= 0 and gamma = c / (2 m) >= 0. Writing Omega^2 = w0^2 - gamma^2 and
/// y = e^(gamma t) x (so y'' = -Omega^2 y):
///   x(t) = e^(-gamma t) [ x0 C + (v0 + gamma x0) S ]
///   v(t) = e^(-gamma t) [ v0 C - (w0^2 x0 + gamma v0) S ]
/// with C = cos(Omega t), S = sin(Omega t) / Omega        (under-damped, gamma < w0),
///      C = 1,            S = t                           (critically damped, gamma = w0),
///      C = cosh(lambda t), S = sinh(lambda t) / lambda   (over-damped, lambda^2 = -Omega^2).
/// Omega = w0 sqrt((1 - q)(1 + q)) with q = gamma / w0, and lambda = gamma sqrt((1 - r)(1 + r))
/// with r = w0 / gamma: neither squares gamma, which overflows float from gamma = 2e19.
/// The factors e^(-gamma t) C and e^(-gamma t) S are computed together so that nothing
/// overflows for large t: e^(-gamma t) cosh(lambda t) = (e^(-(gamma - lambda) t) +
/// e^(-(gamma + lambda) t)) / 2 with gamma - lambda = w0^2 / (gamma + lambda) (no
/// cancellation), and sinh(lambda t) / lambda through expm1 when lambda t is small. No NaN for
/// finite input and any t >= 0 while w0^2 |x0|, gamma |x0|, gamma |v0| and the phase w0 t are
/// below the largest R (a phase beyond it, 3e38 radians in float, has no digits left).
/// An argument outside its domain (w0^2 or gamma negative, NaN or infinite; x0 or v0 not
/// finite; t negative, NaN or infinite) is a contract violation, checked when
/// POINTMASS_CHECKS is on: reported, naming it, and the result is (x0, v0).
template <Real R>
[[nodiscard]] constexpr OscillatorState<R> damped_oscillator(R w0_squared, R gamma,
                                                             const Vector3<R>& x0,
                                                             const Vector3<R>& v0,
                                                             R t) noexcept(!POINTMASS_HOST_CHECKS);

namespace detail {
/// damped_oscillator without its checks: the generators below call it with parameters their
/// setters have validated (and k / m, c / m beyond the range are their documented limit).
template <Real R>
constexpr OscillatorState<R> oscillate(R w0_squared, R gamma, const Vector3<R>& x0,
                                       const Vector3<R>& v0, R t) noexcept {
  if (!(t > R(0))) return {x0, v0};
  const R w0 = real_sqrt(w0_squared);
  R ec;  // e^(-gamma t) C
  R es;  // e^(-gamma t) S
  if (gamma < w0) {
    const R q = gamma / w0;
    const R omega = w0 * real_sqrt((R(1) - q) * (R(1) + q));
    const R decay = real_exp(-gamma * t);
    ec = decay * real_cos(omega * t);
    es = decay * real_sin(omega * t) / omega;
  } else if (gamma > w0) {
    const R r = w0 / gamma;
    const R root = real_sqrt((R(1) - r) * (R(1) + r));
    const R lambda = gamma * root;
    const R slow = w0 * r / (R(1) + root);  // gamma - lambda = w0^2 / (gamma + lambda)
    const R e_slow = real_exp(-slow * t);
    const R e_fast = real_exp(-(gamma * t + lambda * t));
    ec = (e_slow + e_fast) / R(2);
    if (lambda * t < R(0.5)) {
      // sinh(lambda t) / lambda = e^(lambda t) (1 - e^(-2 lambda t)) / (2 lambda)
      es = -e_slow * real_expm1(R(-2) * (lambda * t)) / lambda / R(2);
    } else {
      es = (e_slow - e_fast) / lambda / R(2);
    }
  } else {
    const R decay = real_exp(-gamma * t);
    ec = decay;
    es = decay * t;
  }
  return {x0 * ec + (v0 + x0 * gamma) * es, v0 * ec - (x0 * w0_squared + v0 * gamma) * es};
}

/// The oscillator's response to a push, scaled by the step: with psi(s) the velocity after s
/// of a body released at rest from x = 0 with v = 1 (e^(-gamma s) S of oscillate), Q(t) the
/// integral of psi over [0, t] and Q2(t) the integral of Q,
///   psi_over_t = psi(t) / t   (1 at t -> 0),
///   q          = Q(t) / t^2   (1/2 at t -> 0; Q = (1 - x(t) from x0 = 1, v0 = 0) / w0^2),
///   q2         = Q2(t) / t^3  (1/6 at t -> 0).
/// A constant acceleration a held over the step adds a Q to the position and a psi to the
/// velocity (exactly), and x(t) - x0 - v0 t = -w0^2 Q x0 - (w0^2 Q2 + 2 gamma Q) v0, so
/// neither needs 1 - x(t) or x(t) - x0 - v0 t formed as a difference, which cancels when
/// w0 t is small (to nothing at all once w0^2 t^2 is below epsilon). Dimensionless functions
/// of a = w0 t and b = gamma t, by region:
///   * a <= 2 and b <= 2: their Taylor series (the coefficients by the oscillator's
///     recurrence);
///   * over-damped beyond, with lambda t >= 1/2 and S < 1: closed forms in e^(-S) and
///     e^(-F), S and F the slow and fast decay rates times t (divided differences over
///     F - S >= 1, which do not cancel);
///   * otherwise (then a^2 >= 2): the differences themselves, of oscillate's closed form,
///     which lose at most what a^2 divides.
/// No division by w0^2 or gamma anywhere (w0 = 0 and gamma = 0 are fine); t > 0. Within 16
/// epsilons of the exact values for a <= 2 and any b (tests/forces/
/// test_stiff_spring_accuracy.cpp); beyond, as oscillate's phase allows.
template <Real R>
struct PushResponse {
  R psi_over_t;
  R q;
  R q2;
};

template <Real R>
constexpr PushResponse<R> push_response(R w0_squared, R gamma, R t) noexcept {
  const R w0 = real_sqrt(w0_squared);
  const R a = w0 * t;
  const R b = gamma * t;
  if (a <= R(2) && b <= R(2)) {
    // psi(s) = sum over n >= 1 of p_n (s/t)^n t, p_0 = 0, p_1 = 1, and the equation
    // psi'' = -w0^2 psi - 2 gamma psi' gives p_(n+1) (n + 1) n = -a^2 p_(n-1) - 2 b n p_n.
    // Integrating term by term divides p_n by (n + 1) for Q and by (n + 1)(n + 2) for Q2.
    // With a, b <= 2 the terms fall at least as 4^n / (n + 1)!: the count leaves less than
    // an ulp (4^24 / 25! = 2e-11 for float, 4^38 / 39! = 4e-27 for double).
    constexpr int terms = std::numeric_limits<R>::digits / 2 + 12;
    R previous = R(0);
    R p = R(1);
    PushResponse<R> r{R(0), R(0), R(0)};
    for (int n = 1; n <= terms; ++n) {
      const R rn = static_cast<R>(n);
      r.psi_over_t += p;
      r.q += p / (rn + R(1));
      r.q2 += p / ((rn + R(1)) * (rn + R(2)));
      const R next = -(a * a * previous + R(2) * b * rn * p) / ((rn + R(1)) * rn);
      previous = p;
      p = next;
    }
    return r;
  }
  if (w0 < gamma) {
    // Over-damped, gamma - lambda = w0^2 / (gamma + lambda) and gamma + lambda the rates:
    // psi(s) = (e^(-slow s) - e^(-fast s)) / (2 lambda), so with G(x) = (1 - e^(-x)) / x and
    // H(x) = (x - 1 + e^(-x)) / x^2 (G(0) = 1, H(0) = 1/2), S = slow t, F = fast t and
    // L = lambda t = (F - S) / 2:
    //   psi / t = e^(-S) (1 - e^(-2 L)) / (2 L),  q = (G(S) - G(F)) / (2 L),
    //   q2 = (H(S) - H(F)) / (2 L),
    // well conditioned for L >= 1/2 and S < 1 (then F >= S + 1: G and H differ by a part
    // of themselves).
    const R r = w0 / gamma;
    const R root = real_sqrt((R(1) - r) * (R(1) + r));
    const R s = a * r / (R(1) + root);  // slow t
    const R l = b * root;               // lambda t
    if (l >= R(0.5) && s < R(1)) {
      const R f = s + R(2) * l;  // fast t
      const auto g = [](R x) { return x > R(0) ? -real_expm1(-x) / x : R(1); };
      const auto h = [](R x) {  // below 1/2 the series, phi_2(-x): the difference cancels
        return x < R(0.5) ? pointmass::detail::phi_series<2>(-x) : ((x + real_expm1(-x)) / x) / x;
      };
      const R two_l = R(2) * l;
      return {-real_exp(-s) * real_expm1(-two_l) / two_l, (g(s) - g(f)) / two_l,
              (h(s) - h(f)) / two_l};
    }
  }
  // Here a^2 >= 2 (a > 2; or over-damped with lambda t < 1/2 and b > 2, so a > 1.9; or
  // S >= 1, so a^2 = S F >= S (S + 1)): x(t) from (1, 0) and from (0, 1) in one call.
  const OscillatorState<R> unit =
      oscillate(w0_squared, gamma, Vector3<R>{R(1), R(0), R(0)}, Vector3<R>{R(0), R(1), R(0)}, t);
  const R a_squared = w0_squared * t * t;
  const R psi_over_t = unit.position.y / t;
  const R q = (R(1) - unit.position.x) / a_squared;
  return {psi_over_t, q, ((R(1) - psi_over_t) - R(2) * b * q) / a_squared};
}
}  // namespace detail

template <Real R>
[[nodiscard]] constexpr OscillatorState<R> damped_oscillator(R w0_squared, R gamma,
                                                             const Vector3<R>& x0,
                                                             const Vector3<R>& v0,
                                                             R t) noexcept(!POINTMASS_HOST_CHECKS) {
#if POINTMASS_HOST_CHECKS
  constexpr const char* function = "forces::damped_oscillator";
  if (!pointmass::detail::check_non_negative(function, "w0_squared", w0_squared) ||
      !pointmass::detail::check_non_negative(function, "gamma", gamma) ||
      !pointmass::detail::check_finite(function, "x0", x0) ||
      !pointmass::detail::check_finite(function, "v0", v0) ||
      !pointmass::detail::check_duration(function, "t", t)) {
    return {x0, v0};
  }
#endif
  return detail::oscillate(w0_squared, gamma, x0, v0, t);
}

/// What both stiff springs share: a damped spring of rest length 0 from a body to a fixed
/// anchor, stiffness k >= 0 and damping c >= 0 (force -k x - c v, x = p - anchor), validated;
/// and the exact state after a step of this spring alone.
template <Real R>
class StiffSpringParameters {
 public:
  using real = R;
  constexpr StiffSpringParameters() noexcept = default;
  /// Every argument is checked (each rejected one is reported); one rejected leaves the
  /// spring inert: anchor, stiffness and damping 0 (integrate moves a body as without it).
  constexpr StiffSpringParameters(const Vector3<R>& anchor, R stiffness, R damping) {
    using pointmass::detail::check_finite;
    using pointmass::detail::check_non_negative;
    const bool anchor_valid = check_finite("StiffSpring::set_anchor", "anchor", anchor);
    const bool k_valid = check_non_negative("StiffSpring::set_stiffness", "stiffness", stiffness);
    const bool c_valid = check_non_negative("StiffSpring::set_damping", "damping", damping);
    if (anchor_valid && k_valid && c_valid) {
      anchor_ = anchor;
      k_ = stiffness;
      c_ = damping;
    }
  }

  constexpr Vector3<R> anchor() const noexcept { return anchor_; }
  constexpr R stiffness() const noexcept { return k_; }
  constexpr R damping() const noexcept { return c_; }
  constexpr void set_anchor(const Vector3<R>& anchor) {
    if (pointmass::detail::check_finite("StiffSpring::set_anchor", "anchor", anchor))
      anchor_ = anchor;
  }
  constexpr void set_stiffness(R stiffness) {
    if (pointmass::detail::check_non_negative("StiffSpring::set_stiffness", "stiffness",
                                              stiffness)) {
      k_ = stiffness;
    }
  }
  /// The damping coefficient c >= 0 (force -c v, in N s/m).
  constexpr void set_damping(R damping) {
    if (pointmass::detail::check_non_negative("StiffSpring::set_damping", "damping", damping))
      c_ = damping;
  }

  /// The exact state, relative to the world, after `duration` of this spring alone, for a
  /// body of inverse mass `inverse_mass` > 0. Range: k / m and c / m finite, and
  /// damped_oscillator's.
  constexpr OscillatorState<R> exact_state(const Vector3<R>& p, const Vector3<R>& v, R inverse_mass,
                                           R duration) const noexcept {
    OscillatorState<R> s =
        detail::oscillate(k_ * inverse_mass, c_ * inverse_mass / R(2), p - anchor_, v, duration);
    s.position += anchor_;
    return s;
  }

 protected:
  Vector3<R> anchor_{};
  R k_ = R(0);
  R c_ = R(0);
};

/// A stiff damped spring from a body to a fixed anchor, stepped in closed form instead of
/// integrated by the body: call `spring.integrate(body, t)` in place of
/// `body.integrate(t)`. For a body of mass m,
/// x = p - anchor obeys m x'' = -k x - c x' + m a, where a is the body's own acceleration plus
/// its accumulated forces over m, held constant over the step. With w0^2 = k / m:
///   * w0 t >= 1 (the spring is stiff for this step): exact for constant a. The body
///     oscillates about the shifted rest point anchor + a / w0^2, in closed form.
///   * w0 t < 1: the spring's closed form from (x, v), plus what a constant a adds to it
///     (a Q(t) to x and a psi(t) to v, detail::push_response): exact for constant a too,
///     and never dividing by w0^2 (the rest point is far away, or nowhere for k = 0).
/// So with the spring the only force (a = 0), or with a constant a (gravity), the position
/// and velocity after every step are the closed form's at any step: no stability limit, no
/// period error, the terminal velocity of a strongly damped body; with forces that change
/// during the step, the error of holding them constant over it.
/// The body's damping policy is not applied (the spring's damping c is the damping); as
/// `integrate` does, a zero step changes nothing (an immovable body's accumulator included),
/// and otherwise the accumulator is cleared and an immovable body does not move. A negative
/// or non-finite duration is reported, as is a state beyond the range of the number type
/// (docs/forces.md, "Ranges"); either changes nothing.
template <Real R>
class StiffSpring : public StiffSpringParameters<R> {
 public:
  using StiffSpringParameters<R>::StiffSpringParameters;

  template <SteppableBody<R> B>
  constexpr void integrate(B& body, R duration) const {
    if (!pointmass::detail::check_duration("StiffSpring::integrate", duration)) return;
    if (duration == R(0)) return;  // before the immovable case: integrate(0) keeps the forces
    const R inverse_mass = body.inverse_mass();
    if (!(inverse_mass > R(0))) {
      body.clear_accumulator();
      return;
    }
    const Vector3<R> a = body.acceleration() + body.force_accumulator() * inverse_mass;
    const R w0_squared = this->k_ * inverse_mass;
    OscillatorState<R> s;
    if (w0_squared * duration * duration >= R(1)) {
      const Vector3<R> rest = this->anchor_ + a / w0_squared;
      s = detail::oscillate(w0_squared, this->c_ * inverse_mass / R(2), body.position() - rest,
                            body.velocity(), duration);
      s.position += rest;
    } else {
      // The spring alone, plus what a constant a adds along the oscillator: a Q to the
      // position, a psi to the velocity (push_response), with no division by w0^2.
      const R gamma = this->c_ * inverse_mass / R(2);
      const detail::PushResponse<R> push = detail::push_response(w0_squared, gamma, duration);
      s = this->exact_state(body.position(), body.velocity(), inverse_mass, duration);
      s.position += a * (push.q * duration * duration);
      s.velocity += a * (push.psi_over_t * duration);
    }
    if (!pointmass::detail::check_state("StiffSpring::integrate", s.position, s.velocity)) {
      return;
    }
    body.set_position(s.position);
    body.set_velocity(s.velocity);
    body.clear_accumulator();
  }
  template <SteppableBody<R> B>
  [[deprecated("pointmass 0.2: use StiffSpring::integrate")]] constexpr void advance(
      B& body, R duration) const {
    integrate(body, duration);
  }
};

/// Cyclone's "fake" stiff spring as a force, kept for compatibility; prefer
/// StiffSpring::integrate. What it does wrong: for a step t it adds the force that brings a body
/// with position::SemiImplicit and damping::None to the closed form's position,
///   f = m [ (x(t) - x0) / t - v0 ] / t,
/// so every step ends at the closed form's position from the body's current state, but the
/// velocity it leaves is the step's mean velocity, which the next step takes as the initial
/// velocity: the body oscillates with a period sqrt(2) times the true one at every step size
/// (it does not converge as t shrinks) and a wrong amplitude. What it does right, unlike the
/// Cyclone's: no NaN when over-damped (sqrt(4 k - c^2) there), a force when
/// critically damped. Stability of its step map: see docs/forces.md.
/// The difference quotient is not formed (it cancels when w0 t is small, to nothing once
/// w0^2 t^2 is below epsilon, whatever gamma t is): the force is computed as
/// -k (Q / t^2) x0 - (c Q / t^2 + k t Q2 / t^3) v0 (detail::push_response), whose limit as
/// t -> 0 is -(k x + c v) / 2 (half the spring's force: that is its error, seen at small
/// steps); it never divides by t^2 or by inverse_mass t. Nothing on an immovable body,
/// nothing for t = 0. Range: k |x| + (c + k t) |v| below the largest R; k / m and c / m
/// finite, and exact_state's.
template <Real R>
class PositionOnlyStiffSpring : public StiffSpringParameters<R> {
 public:
  using StiffSpringParameters<R>::StiffSpringParameters;

  constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>& v, R inverse_mass,
                             R duration) const noexcept {
    if (!(inverse_mass > R(0)) || !(duration > R(0))) return {};
    const R w0_squared = this->k_ * inverse_mass;
    const R gamma = this->c_ * inverse_mass / R(2);
    const Vector3<R> x = p - this->anchor_;
    // m (x(t) - x0 - v0 t) / t^2 = -k Q x0 / t^2 - (k Q2 / t^2 + c Q / t^2) v0 (push_response).
    const detail::PushResponse<R> push = detail::push_response(w0_squared, gamma, duration);
    return -(x * (this->k_ * push.q) + v * (this->c_ * push.q + this->k_ * duration * push.q2));
  }
};

}  // namespace pointmass::forces
POINTMASS_DETAIL_UNFUSED_END
