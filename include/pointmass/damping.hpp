// SPDX-License-Identifier: BSL-1.0
// pointmass/damping.hpp — how velocity is damped and updated over one step.
//
// Damping d in [0, 1] is the fraction of velocity kept (1 keeps all of it). With resulting
// acceleration a and step t > 0 the policies compute the new velocity v1 from the old v0:
//
//   policy                 v1                              order*  cost per step     choose for
//   None                   v0 + a t                        1 (exact for constant a)
//                                                                  one multiply-add  huge counts, bullets in vacuum
//   PerFrame   (eq. 3.5)   v0 d + a t                      1       one multiply-add  thousands of sparks at a fixed frame rate
//   PerSecond  (eq. 3.6)   v0 d^t + a t                    1       one exp**         the default: drag independent of frame rate
//   AccelerateThenDamp     (v0 + a t) d^t                  1       one pow           reproducing Cyclone's trajectories
//   Exact                  v0 d^t + a (d^t - 1) / ln d     exact   one exp**         projectiles with drag, large or varying steps
//
//   * global order against the continuous model dv/dt = a + ln(d) v (per-second d); for
//     PerFrame the model's rate is ln(d) / frame_time, so it describes a different drag at
//     every frame rate.
//  ** the library's own exponential (detail/exponential.hpp): d^t = e^(t ln d) with ln d
//     stored when the damping is set, branch-free, so a loop over particles that each have
//     their own damping vectorises; within 4 ulp of the correctly rounded d^t (measured: 1 ulp,
//     docs/numerics.md). AccelerateThenDamp calls the C library's pow (powf for float): Cyclone
//     does, and ported code must get its trajectories bit for bit.
//
// AccelerateThenDamp is the form Cyclone's `Particle::integrate` computes (it adds a t
// and then multiplies by d^t); eq. 3.6 of Millington damps only the old velocity. They differ by
// a t (d^t - 1). PerSecond is the default because it is the equation Millington derives, and
// its terminal velocity under constant a does not depend on the frame rate as strongly; the
// listing's form stays available so that ported code reproduces its old trajectories.
//
// A damping policy is a type with
//   template <Real R> struct State      what one particle (or one uniform system) stores,
//                                       with `value()` returning d. A stateful one is
//                                       constructible from R d; an empty one costs a
//                                       particle no storage (and has no set_damping).
//   static Factors factors(State, t)    what one step needs, computed once per step (and in
//                                       a batch with uniform damping, once for all particles).
//   static V velocity(v0, a, t, Factors)
// and satisfies the DampingPolicy concept. velocity() is written over generic arithmetic, so
// it applies to Vector3s, to one component at a time, and to dimensioned quantities alike.
//
// Owns: the damping policies, their order and exactness traits, the DampingPolicy concept.
// Must not include: position.hpp, particle.hpp or anything above them.
#pragma once

#include <concepts>
#include <limits>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "detail/exponential.hpp"
#include "real.hpp"
#include "vector3.hpp"

// The per-second policies' factors are inlined into a batch's loop at any optimisation level
// (POINTMASS_DETAIL_ALWAYS_INLINE): g++ -O2 would otherwise call them per particle, and a call
// stops vectorisation.

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::damping {

/// A damping value d in [0, 1]; the states of the policies that store one.
template <Real R>
class StoredDamping {
 public:
  constexpr StoredDamping() noexcept = default;
  POINTMASS_HD constexpr explicit StoredDamping(R d) noexcept : value_(d) {}
  [[nodiscard]] POINTMASS_HD constexpr R value() const noexcept { return value_; }

 private:
  R value_ = R(1);
};

/// A damping value d in [0, 1] and its logarithm, stored when it is set so that a step needs
/// no logarithm: the states of PerSecond and Exact. ln d is split in two parts (a single
/// rounded ln d would cost up to 7 ulp of d^t); d itself is kept because damping() must
/// return exactly what was set, which e^(ln d) need not be.
template <Real R>
class LogDamping {
 public:
  constexpr LogDamping() noexcept = default;
  POINTMASS_HD constexpr explicit LogDamping(R d) noexcept
      : value_(d), log_(detail::split_log(d)) {}
  /// d and split_log(d), computed before (a ParticleSystem stores them in separate columns).
  POINTMASS_HD constexpr LogDamping(R d, const detail::SplitLog<R>& log) noexcept
      : value_(d), log_(log) {}
  [[nodiscard]] POINTMASS_HD constexpr R value() const noexcept { return value_; }
  /// ln d as hi + lo (detail::split_log): both 0 for d = 1, a huge negative hi for d = 0.
  [[nodiscard]] POINTMASS_HD constexpr const detail::SplitLog<R>& split_log() const noexcept {
    return log_;
  }
  /// k = ln d, the damping rate per second (<= 0; -infinity for d = 0).
  [[nodiscard]] POINTMASS_HD constexpr R log_value() const noexcept {
    return value_ > R(0) ? log_.hi + log_.lo : -real_infinity<R>;
  }

 private:
  R value_ = R(1);
  detail::SplitLog<R> log_{};
};

/// The damping factors of PerFrame, PerSecond and AccelerateThenDamp: the retention alone.
template <Real R>
struct Retention {
  R kept;  ///< the retention: d^t (d for PerFrame), the fraction of velocity the step keeps
};

}  // namespace pointmass::damping

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {
/// What damping::PerFrame and damping::PerSecond share: the retention (Retention) applied to
/// the velocity before the acceleration is added: v1 = v0 * retention + a t.
struct DampThenAccelerate {
  template <Real R>
  using Factors = damping::Retention<R>;
  template <class V, class A, class T, class R>
  POINTMASS_HD static constexpr V velocity(const V& v0, const A& a, const T& t,
                                           const Factors<R>& f) noexcept {
    return v0 * f.kept + a * t;
  }
};
}  // namespace pointmass::detail

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::damping {

/// No damping: v1 = v0 + a t. Stores nothing and calls no power function.
/// Exact for constant acceleration; the cheapest update, for very large particle counts.
struct None {
  /// Global order of accuracy against the continuous model; exact for constant acceleration.
  static constexpr int order = 1;
  /// True when v1 is the continuous model's exact velocity under constant acceleration.
  static constexpr bool exact_for_constant_acceleration = true;
  template <Real R>
  struct State {
    POINTMASS_HD static constexpr R value() noexcept { return R(1); }
  };
  /// Nothing to compute per step. (Being empty tells position::Exact there is no damping.)
  struct Factors {};

  template <Real R, class T>
  POINTMASS_HD static constexpr Factors factors(const State<R>&, const T&) noexcept {
    return {};
  }
  template <class V, class A, class T>
  POINTMASS_HD static constexpr V velocity(const V& v0, const A& a, const T& t,
                                           const Factors&) noexcept {
    return v0 + a * t;
  }
};

/// Eq. 3.5, per-frame damping: v1 = v0 d + a t.
/// Removes the same fraction each step whatever its length, so drag changes with the frame
/// rate (continuous model: rate ln(d) / t). First order. No power function: meant for
/// thousands of sparks at a fixed frame rate.
struct PerFrame : detail::DampThenAccelerate {
  /// Global order of accuracy against the continuous model; the model itself changes with the frame rate.
  static constexpr int order = 1;
  /// True when v1 is the continuous model's exact velocity under constant acceleration.
  static constexpr bool exact_for_constant_acceleration = false;
  template <Real R>
  using State = StoredDamping<R>;

  template <Real R, class T>
  POINTMASS_HD static constexpr Factors<R> factors(const State<R>& state, const T&) noexcept {
    return {state.value()};
  }
};

/// Eq. 3.6, per-second damping (the default): v1 = v0 d^t + a t.
/// d is the fraction kept per second, so damping alone is frame-rate independent (one step
/// of 2t equals two of t). First order in the acceleration term. One exponential a step,
/// d^t = e^(t ln d), the library's own (ln d is stored with d; long double calls powl).
struct PerSecond : detail::DampThenAccelerate {
  /// Global order of accuracy against the continuous model; exact without acceleration.
  static constexpr int order = 1;
  /// True when v1 is the continuous model's exact velocity under constant acceleration.
  static constexpr bool exact_for_constant_acceleration = false;
  template <Real R>
  using State = LogDamping<R>;

  template <Real R, class T>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr Factors<R> factors(
      const State<R>& state, const T& t) noexcept {
    if constexpr (wider_than_double_v<R>) {
      return {real_pow(state.value(), in_seconds(t))};
    } else {
      return {detail::pow_unit(state.split_log(), in_seconds(t))};
    }
  }
  /// The same factors, bit for bit, for one particle at a time (Particle::integrate): the
  /// exponential with a branch on its range (detail::pow_unit_scalar) instead of selects.
  template <Real R, class T>
  POINTMASS_HD static constexpr Factors<R> scalar_factors(const State<R>& state,
                                                          const T& t) noexcept {
    if constexpr (wider_than_double_v<R>) {
      return factors(state, t);
    } else {
      return {detail::pow_unit_scalar(state.split_log(), in_seconds(t))};
    }
  }
};

/// Cyclone's `Particle::integrate`: v1 = (v0 + a t) d^t.
/// Adds the acceleration first and damps the sum, so it differs from eq. 3.6 by
/// a t (d^t - 1). First order. One power function a step. Choose it to reproduce
/// trajectories of code ported from Cyclone: for that it keeps the C library's
/// pow (powf for float), which the engine calls, rather than the library's own exponential
/// (1 ulp from the correctly rounded d^t, so not always powf's result). The price is a call
/// per particle and step in a batch with per-particle damping, which does not vectorise.
struct AccelerateThenDamp {
  /// Global order of accuracy against the continuous model; exact without acceleration.
  static constexpr int order = 1;
  /// True when v1 is the continuous model's exact velocity under constant acceleration.
  static constexpr bool exact_for_constant_acceleration = false;
  template <Real R>
  using State = StoredDamping<R>;
  template <Real R>
  using Factors = Retention<R>;

  template <Real R, class T>
  POINTMASS_HD static Factors<R> factors(const State<R>& state, const T& t) noexcept {
    return {real_pow(state.value(), in_seconds(t))};
  }
  template <class V, class A, class T, class R>
  POINTMASS_HD static constexpr V velocity(const V& v0, const A& a, const T& t,
                                           const Factors<R>& f) noexcept {
    return (v0 + a * t) * f.kept;
  }
};

/// Exact per-second damping under constant acceleration.
/// The continuous model dv/dt = a + k v with k = ln d (per second) has the solution
///   v(t) = v0 e^(kt) + a (e^(kt) - 1) / k = v0 d^t + a t phi1(kt),  phi1(x) = (e^x - 1) / x,
/// which this policy evaluates with expm1, so d -> 1 (k -> 0) stays accurate and d = 1
/// reduces to v0 + a t. d = 0 gives v1 = 0 (the limit). No truncation error at any step;
/// costs one expm1 a step (ln d is computed once, when the damping is set). Its factors also
/// carry phi2, so position::Exact gives the exact position at no further cost.
struct Exact {
  /// Global order of accuracy against the continuous model; exact for constant acceleration
  /// (the order applies when the acceleration varies over the step, as under a spring).
  static constexpr int order = 1;
  /// True when v1 is the continuous model's exact velocity under constant acceleration.
  static constexpr bool exact_for_constant_acceleration = true;
  template <Real R>
  using State = LogDamping<R>;

  template <Real R>
  struct Factors {
    R kept;  ///< the retention e^x = d^t (x = k t)
    R phi1;  ///< (e^x - 1) / x: 1 at x = 0, 0 at x = -infinity
    R phi2;  ///< (e^x - 1 - x) / x^2: 1/2 at x = 0, 0 at x = -infinity (for position::Exact)
  };

  /// Once per step: one exponential (d^t and d^t - 1 together, detail::exp_unit), and for
  /// |x| < 1 the series of phi2 (where (phi1 - 1) / x would cancel); beyond, (phi1 - 1) / x
  /// multiplies phi1's relative rounding error by phi1 / (|x| phi2), below 2 / |x| <= 2.
  /// Branch-free (selects), so a loop over particles with their own damping vectorises.
  template <Real R, class T>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr Factors<R> factors(
      const State<R>& state, const T& t) noexcept {
    // x = k t <= 0: zero when d = 1 or t = 0, and nothing is taken away: phi1 = 1,
    // phi2 = 1/2. Every branch is computed and the right one selected, on inputs that raise
    // no floating-point exception (no 0 / 0, no series of a huge x).
    const detail::UnitPower<R> power = detail::exp_unit(state.split_log(), in_seconds(t));
    const R x = power.exponent;
    const R divisor = detail::select_if_less(x, R(0), x, R(-1));
    const R phi1 = detail::select_if_less(x, R(0), power.kept_minus_one / divisor, R(1));
    const R series_x = detail::select_if_less(R(-1), x, x, R(0));
    const R phi2 =
        detail::select_if_less(R(-1), x, detail::phi_series<2>(series_x), (phi1 - R(1)) / divisor);
    // d = 0 keeps nothing, not even this step's push: the limit k -> -infinity (phi1 = -1 / x
    // would leave a tiny remainder of t ln 0's finite stand-in).
    const R d = state.value();
    return {power.kept, detail::select_if_less(R(0), d, phi1, R(0)),
            detail::select_if_less(R(0), d, phi2, R(0))};
  }
  template <class V, class A, class T, class R>
  POINTMASS_HD static constexpr V velocity(const V& v0, const A& a, const T& t,
                                           const Factors<R>& f) noexcept {
    return v0 * f.kept + a * (t * f.phi1);
  }
};

}  // namespace pointmass::damping

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// A damping policy: a State<R> made from a damping value, per-step factors, and a velocity
/// update over vectors of R (checked for float, double and long double). A policy states its
/// order and exactness as `order` and `exact_for_constant_acceleration` (the library's all
/// do); one that does not is taken as first order and not exact.
template <class D>
concept DampingPolicy = requires(const Vector3<float>& vf, float tf, const Vector3<double>& vd,
                                 double td, const Vector3<long double>& vl, long double tl) {
  typename D::template State<float>;
  typename D::template State<double>;
  { typename D::template State<float>{}.value() } -> std::same_as<float>;
  { typename D::template State<double>{}.value() } -> std::same_as<double>;
  {
    D::velocity(vf, vf, tf, D::factors(typename D::template State<float>{}, tf))
    } -> std::same_as<Vector3<float>>;
  {
    D::velocity(vd, vd, td, D::factors(typename D::template State<double>{}, td))
    } -> std::same_as<Vector3<double>>;
  { typename D::template State<long double>{}.value() } -> std::same_as<long double>;
  {
    D::velocity(vl, vl, tl, D::factors(typename D::template State<long double>{}, tl))
    } -> std::same_as<Vector3<long double>>;
};

namespace detail {
/// A policy's stated `order`, or 1.
template <class Policy>
constexpr int stated_order() {
  if constexpr (requires { Policy::order; }) return Policy::order;
  else return 1;
}
}  // namespace detail

namespace detail {
/// D::scalar_factors(state, t) where the policy has one (the same bits as D::factors,
/// written for one particle at a time: a Particle's step), else D::factors(state, t).
template <class D, class State, class T>
POINTMASS_HD constexpr auto scalar_factors(const State& state, const T& t) noexcept {
  if constexpr (requires { D::scalar_factors(state, t); }) {
    return D::scalar_factors(state, t);
  } else {
    return D::factors(state, t);
  }
}
}  // namespace detail

/// The factors type a damping policy computes for one step in precision R.
template <class D, class R>
using damping_factors_t =
    decltype(D::factors(std::declval<typename D::template State<R>>(), std::declval<R>()));

namespace detail {
/// True when D's factors depend on the step length (every policy but None and PerFrame): a
/// Particle, and a ParticleSystem with uniform damping, keep them for the next step of the
/// same length.
template <class D, class R>
inline constexpr bool keeps_factors_v =
    !std::is_empty_v<damping_factors_t<D, R>> && !std::is_same_v<D, damping::PerFrame>;
/// The last step's length (-1 before the first: never a valid one) and its factors.
template <class D, class R>
struct KeptFactors {
  R duration = R(-1);
  damping_factors_t<D, R> factors{};
};
struct NoKeptFactors {};
}  // namespace detail

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
