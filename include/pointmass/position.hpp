// SPDX-License-Identifier: BSL-1.0
// pointmass/position.hpp — how the position moves over one step.
//
// A position policy gets the old position p0, the velocity at the start (v0) and end (v1) of
// the step, the resulting acceleration a, the step t and the damping policy's per-step
// factors, and returns the new position:
//
//   policy                p1                          order*  when to choose
//   Euler                 p0 + v0 t                   1       the default, Millington's
//                                                             short form: the cheapest
//   ConstantAcceleration  p0 + v0 t + a t^2 / 2       1       short bursts of huge
//                                                             acceleration (exact for constant
//                                                             a without damping)
//   SemiImplicit          p0 + v1 t                   1       springs and orbits: symplectic
//                                                             Euler, what most game engines
//                                                             use; does not gain energy on an
//                                                             undamped spring for w t < 2
//   Exact                 the integral of v(t) over   exact   projectiles with drag, with
//                         the step, for constant a            damping::Exact
//                         and per-second damping
//   VelocityVerlet        p0 + (v0 + v1) t / 2 after  2       springs, ropes, orbits: forces
//                         a half kick (see there)             at second order, same cost
//
//   * global order on the continuous model. The explicit forms (Euler, ConstantAcceleration)
//     gain energy on an undamped spring at any step.
//
// Write your own as a type with one static function (see docs/design.md):
//   static constexpr auto position(const auto& p0, const auto& v0, const auto& v1,
//                                  const auto& a, const auto& t, const auto& factors);
// Written over generic arithmetic, it applies to Vector3s, to single components and to
// dimensioned quantities alike.
//
// Owns: the position policies, their traits, the pair traits (order_v,
// is_exact_for_constant_acceleration_v), PositionPolicyFor, the one-sentence pair check and
// integrate_kicked (VelocityVerlet's step on values).
// Must not include: particle.hpp or anything above it.
#pragma once

#include <concepts>
#include <type_traits>

#include "config.hpp"
#include "damping.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::position {

/// Millington's short form: p1 = p0 + v0 t, with the velocity from the start of the step.
/// Local error a t^2 / 2; first order. The cheapest update.
struct Euler {
  /// Global order of accuracy against the continuous model.
  static constexpr int order = 1;
  /// True when, paired with damping policy D, a step is the exact flow for constant
  /// acceleration (never: it drops a t^2 / 2).
  template <class D>
  static constexpr bool exact_for_constant_acceleration = false;
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V&, const A&, const T& t,
                                           const F&) noexcept {
    return p0 + v0 * t;
  }
};

/// The full form: p1 = p0 + v0 t + a t^2 / 2. Exact for constant acceleration without
/// damping; with damping the velocity update still limits the method to first order.
struct ConstantAcceleration {
  /// Global order of accuracy against the continuous model.
  static constexpr int order = 1;
  /// True when, paired with damping policy D, a step is the exact flow for constant
  /// acceleration (without damping only).
  template <class D>
  static constexpr bool exact_for_constant_acceleration = std::is_same_v<D, damping::None>;
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V&, const A& a,
                                           const T& t, const F&) noexcept {
    using R = scalar_t<T>;
    // (a t)(t / 2), not a (t t / 2): t t overflows for steps of 1e19 s (float), and a body
    // at rest (a = 0) would then get 0 * inf = NaN.
    return p0 + v0 * t + (a * t) * (t * R(0.5));
  }
};
/// The name of ConstantAcceleration in 0.1, kept one minor version: "kinematic" names a body
/// that forces do not move in game engines, which this policy is not.
using Kinematic [[deprecated("pointmass 0.2: use position::ConstantAcceleration")]] =
    ConstantAcceleration;

/// Semi-implicit (symplectic) Euler: p1 = p0 + v1 t, with the velocity from the end of the
/// step. First order, but symplectic: on an undamped spring of angular frequency w it keeps
/// the energy bounded for w t < 2, where the explicit forms gain energy at any step.
struct SemiImplicit {
  /// Global order of accuracy against the continuous model.
  static constexpr int order = 1;
  /// True when, paired with damping policy D, a step is the exact flow for constant
  /// acceleration (never: it uses v1 for the whole step).
  template <class D>
  static constexpr bool exact_for_constant_acceleration = false;
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V&, const V& v1, const A&, const T& t,
                                           const F&) noexcept {
    return p0 + v1 * t;
  }
};

/// Velocity Verlet (kick, drift, damp, drift, kick): second order under forces for one force
/// evaluation a step, the accumulated force as every policy takes it. A step of t with the
/// acceleration a at p0 completes the last step's second half kick with a (the velocity read
/// between steps took it on credit with the last step's acceleration), kicks t/2, drifts t/2,
/// damps by the step's retention, drifts t/2 and kicks t/2 on credit again:
///   v0 = v - kick + a (t_last / 2 + t / 2);   v1 = v0 d^t;   p1 = p0 + (v0 + v1) t / 2;
///   kick = a t / 2;   v = v1 + kick
/// The body keeps the credited kick (a velocity) and t_last / 2: 4 more numbers per particle.
/// Exact for constant acceleration without damping; exact for damping alone (v1 = v0 d^t).
struct VelocityVerlet {
  /// Global order of accuracy against the continuous model.
  static constexpr int order = 2;
  /// The body keeps the half kick the velocity took on credit (see above).
  static constexpr bool kicks = true;
  /// True when, paired with damping policy D, a step is the exact flow for constant
  /// acceleration (without damping only).
  template <class D>
  static constexpr bool exact_for_constant_acceleration = std::is_same_v<D, damping::None>;
  /// The drift: v0 after the kicks, v1 after the damping.
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V& v1, const A&,
                                           const T& t, const F&) noexcept {
    using R = scalar_t<T>;
    return p0 + (v0 + v1) * (t * R(0.5));
  }
};

namespace detail {

/// Factors an exact position can use: phi1 and phi2 of the step (damping::Exact's), or none
/// at all (damping::None: no damping).
template <class F>
concept ExactFactors = std::is_empty_v<F> || requires(const F& f) {
  f.phi1;
  f.phi2;
};

}  // namespace detail

/// The exact position for constant acceleration a and per-second damping (rate k = ln d):
///   p(t) = p0 + v0 t phi1(kt) + a t^2 phi2(kt),   phi2(x) = (e^x - 1 - x) / x^2,
/// with phi1 and phi2 from damping::Exact's factors (computed once per step). Without damping
/// (damping::None, k = 0: phi1 = 1, phi2 = 1/2) it is the ConstantAcceleration form.
struct Exact {
  /// Global order of accuracy against the continuous model.
  static constexpr int order = 1;
  /// True when, paired with damping policy D, a step is the exact flow for constant
  /// acceleration (with an exact velocity update: damping::None or damping::Exact).
  template <class D>
  static constexpr bool exact_for_constant_acceleration = D::exact_for_constant_acceleration;
  template <class P, class V, class A, class T, class F>
    requires(detail::ExactFactors<F>)
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V&, const A& a,
                                           const T& t, const F& factors) noexcept {
    if constexpr (std::is_empty_v<F>) {
      return ConstantAcceleration::position(p0, v0, v0, a, t, factors);
    } else {
      // As ConstantAcceleration computes it, with phi1 and phi2 for 1 and 1/2.
      return p0 + v0 * (t * factors.phi1) + (a * t) * (t * factors.phi2);
    }
  }
};

}  // namespace pointmass::position

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

namespace detail {

/// True for a position policy whose body keeps a credited half kick (VelocityVerlet).
template <class P>
inline constexpr bool kicks_v = requires {
  requires P::kicks;
};

/// v0 damped over a step: by the factors' retention (d^t, or d per frame), or not at all.
template <class V, class F>
POINTMASS_HD constexpr V retained(const V& v0, const F& factors) noexcept {
  if constexpr (std::is_empty_v<F>) {
    static_cast<void>(factors);
    return v0;
  } else {
    return v0 * factors.kept;
  }
}

}  // namespace detail

/// One step of a kicked position policy (position::VelocityVerlet) on one body's values:
/// `kick` is the half kick the velocity took on credit at the last step, `last_half` that
/// step's length / 2 (both 0 before the first step). Generic arithmetic, as integrate<D, P>.
template <class D, class P, class Position, class Velocity, class Acceleration, class Time,
          class Factors>
POINTMASS_HD constexpr void integrate_kicked(Position& p, Velocity& v, Velocity& kick,
                                             const Acceleration& a, const Time& t,
                                             const Time& last_half,
                                             const Factors& factors) noexcept {
  using R = scalar_t<Time>;
  const Time half = t * R(0.5);
  const Velocity v0 = v - kick + a * (last_half + half);  // the credit settled, half a kick
  const Velocity v1 = detail::retained(v0, factors);
  kick = a * half;
  v = v1 + kick;
  p = P::position(p, v0, v1, a, t, factors);
}

/// True when the pair (D, P) steps exactly along the continuous model for constant
/// acceleration at any step length (its error is rounding only): (None, ConstantAcceleration),
/// (None, Exact) and (Exact, Exact).
/// (A policy that does not state its exactness is taken as not exact.)
template <class D, class P>
inline constexpr bool is_exact_for_constant_acceleration_v = requires {
  requires D::exact_for_constant_acceleration;
  requires P::template exact_for_constant_acceleration<D>;
};

/// The pair's global order of accuracy against the continuous model when the acceleration
/// varies over a step (a spring): the lower of the two policies' orders (1 where a policy
/// does not state one); a kicked policy's own (VelocityVerlet: 2), whose step damps by the
/// exact retention between its drifts instead of the damping policy's velocity update.
template <class D, class P>
inline constexpr int order_v = detail::kicks_v<P> ? detail::stated_order<P>()
                               : detail::stated_order<D>() < detail::stated_order<P>()
                                   ? detail::stated_order<D>()
                                   : detail::stated_order<P>();

namespace detail {

/// A damping policy a kicked step (VelocityVerlet) damps with: none, or a retention d^t (or d)
/// in its factors, applied between the drifts. Not AccelerateThenDamp: its order is Cyclone's.
template <class D>
inline constexpr bool damps_by_retention_v = std::is_same_v<D, damping::None> ||
                                             (!std::is_same_v<D, damping::AccelerateThenDamp> &&
                                              requires(const damping_factors_t<D, float>& f) {
                                                f.kept;
                                              });

}  // namespace detail

/// A position policy usable with damping policy D (checked for float and double).
template <class P, class D>
concept PositionPolicyFor = DampingPolicy<D> &&
    (!detail::kicks_v<P> ||
     detail::damps_by_retention_v<D>)&&requires(const Vector3<float>& vf, float tf,
                                                const damping_factors_t<D, float>& ff,
                                                const Vector3<double>& vd, double td,
                                                const damping_factors_t<D, double>& fd) {
  { P::position(vf, vf, vf, vf, tf, ff) } -> std::same_as<Vector3<float>>;
  { P::position(vd, vd, vd, vd, td, fd) } -> std::same_as<Vector3<double>>;
};

namespace detail {

/// Checks the pair (D, P) with a one-sentence error instead of a page of unmet constraints.
/// A class over a damping policy D and a position policy P takes P unconstrained and puts
///   static_assert(detail::check_policy_pair<D, P>());
/// in its body (and steps only `if constexpr (PositionPolicyFor<P, D>)`, so that nothing
/// follows the sentence); the function is true for a valid pair and fails to compile otherwise.
template <class D, class P>
constexpr bool check_policy_pair() {
  // A plain bool, so that the compiler prints the sentence and not the unmet constraints.
  constexpr bool fits = PositionPolicyFor<P, D>;
  if constexpr (kicks_v<P>) {
    static_assert(fits,
                  "position::VelocityVerlet works with damping::None, PerSecond, PerFrame and "
                  "Exact (the step's retention between its drifts); AccelerateThenDamp is "
                  "Cyclone's order of acceleration and damping, which a Verlet step is not");
  } else if constexpr (std::is_same_v<P, position::Exact>) {
    static_assert(fits,
                  "position::Exact works only with damping::Exact or damping::None; with "
                  "damping::PerSecond, PerFrame or AccelerateThenDamp choose position::Euler, "
                  "ConstantAcceleration or SemiImplicit, which work with every damping policy");
  } else {
    static_assert(fits,
                  "this position policy does not fit this damping policy: it needs a static "
                  "position(p0, v0, v1, a, t, factors) that takes the damping policy's factors "
                  "and returns the position's type, for float and double (see position.hpp)");
  }
  return true;  // a failed pair has already stopped at the static_assert above
}

}  // namespace detail

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
