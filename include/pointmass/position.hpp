// pointmass/position.hpp — how the position moves over one step.
//
// A position policy gets the old position p0, the velocity at the start (v0) and end (v1) of
// the step, the resulting acceleration a, the step t and the damping policy's per-step
// factors, and returns the new position:
//
//   policy        p1                              order*  when to choose
//   Euler         p0 + v0 t                       1       the default, the text's short form: cheapest
//   Kinematic     p0 + v0 t + a t^2 / 2           1 (exact for constant a without damping)
//                                                         short bursts of huge acceleration
//   SemiImplicit  p0 + v1 t                       1       springs and orbits: symplectic Euler,
//                                                         what most game engines use; does not gain
//                                                         energy on an undamped spring for w t < 2
//   Exact         the integral of v(t) over the step, for constant a and per-second damping
//                                                 exact   projectiles with drag, with damping::Exact
//
//   * global order on the continuous model. The explicit forms (Euler, Kinematic) gain energy
//     on an undamped spring at any step.
//
// Write your own as a type with one static function (see docs/design.md):
//   static constexpr auto position(const auto& p0, const auto& v0, const auto& v1,
//                                  const auto& a, const auto& t, const auto& factors);
// Written over generic arithmetic, it applies to Vector3s, to single components and to
// dimensioned quantities alike.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <type_traits>

#include "config.hpp"
#include "damping.hpp"
#include "real.hpp"
#include "vector3.hpp"

namespace pointmass::position {

/// The text's short form: p1 = p0 + v0 t, with the velocity from the start of the step.
/// Local error a t^2 / 2; first order. The cheapest update.
struct Euler {
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V&, const A&,
                                           const T& t, const F&) noexcept {
    return p0 + v0 * t;
  }
};

/// The full form: p1 = p0 + v0 t + a t^2 / 2. Exact for constant acceleration without
/// damping; with damping the velocity update still limits the method to first order.
struct Kinematic {
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V&, const A& a,
                                           const T& t, const F&) noexcept {
    using R = scalar_t<T>;
    return p0 + v0 * t + a * (t * t * R(0.5));
  }
};

/// Semi-implicit (symplectic) Euler: p1 = p0 + v1 t, with the velocity from the end of the
/// step. First order, but symplectic: on an undamped spring of angular frequency w it keeps
/// the energy bounded for w t < 2, where the explicit forms gain energy at any step.
struct SemiImplicit {
  template <class P, class V, class A, class T, class F>
  POINTMASS_HD static constexpr P position(const P& p0, const V&, const V& v1, const A&,
                                           const T& t, const F&) noexcept {
    return p0 + v1 * t;
  }
};

namespace detail {

/// How many terms of the phi series reach R's precision for |x| < 1/4: the first omitted
/// term, 4^-n / (n + 2)!, is below a quarter of an ulp (float 7, double 12, long double 14).
template <class R>
inline constexpr int phi_terms = sizeof(R) == sizeof(float) ? 7 : sizeof(R) == sizeof(double) ? 12 : 14;

/// 1 / (n + Offset)! for n = 0 .. phi_terms<R> - 1, computed at compile time.
template <int Offset, class R>
constexpr std::array<R, phi_terms<R>> make_phi_coefficients() noexcept {
  std::array<R, phi_terms<R>> coefficients{};
  R factorial = R(1);
  for (int n = 2; n <= Offset; ++n) factorial *= R(n);
  for (int n = 0; n < phi_terms<R>; ++n) {
    coefficients[static_cast<std::size_t>(n)] = R(1) / factorial;
    factorial *= R(n + Offset + 1);
  }
  return coefficients;
}
template <int Offset, class R>
inline constexpr std::array<R, phi_terms<R>> phi_coefficients = make_phi_coefficients<Offset, R>();

/// phi_Offset(x) = sum_{n>=0} x^n / (n + Offset)!, by Horner's rule, for |x| < 1/4.
template <int Offset, class R>
POINTMASS_HD constexpr R phi_series(R x) noexcept {
  const auto& c = phi_coefficients<Offset, R>;
  R sum = c[phi_terms<R> - 1];
  for (int n = phi_terms<R> - 2; n >= 0; --n) sum = sum * x + c[static_cast<std::size_t>(n)];
  return sum;
}

/// The damping's ln-of-fraction-kept over the step: the factors' `log_kept`, or zero for a
/// policy without damping (empty factors).
template <class R, class F>
POINTMASS_HD constexpr R log_kept(const F& factors) noexcept {
  if constexpr (std::is_empty_v<F>) {
    return R(0);
  } else {
    return factors.log_kept;
  }
}

/// phi1(x) = (e^x - 1) / x: from the factors where the damping computed it, else the series.
template <class R, class F>
POINTMASS_HD constexpr R phi1_of(const F& factors, R x) noexcept {
  if constexpr (requires { factors.phi1; }) {
    return factors.phi1;
  } else {
    return phi_series<1>(x);
  }
}

template <class F>
concept ExactFactors = std::is_empty_v<F> || requires(const F& f) { f.log_kept; };

}  // namespace detail

/// The exact position for constant acceleration a and per-second damping (rate k = ln d):
///   p(t) = p0 + v0 t phi1(kt) + a t^2 phi2(kt),   phi2(x) = (e^x - 1 - x) / x^2,
/// and, since v1 - v0 - a t = k (v0 t phi1 + a t^2 phi2), equivalently
///   p(t) = p0 + (v1 - v0 - a t) / k.
/// For |kt| < 1/4 phi1 comes from the damping's factors and phi2 from its series (no
/// cancellation); beyond, the second
/// form, which needs no transcendental function (its cancellation costs at most a factor
/// 1 / |kt| < 4 in relative rounding error).
/// Without damping (k = 0) it is the Kinematic form. Needs damping::Exact or damping::None,
/// whose factors carry kt.
struct Exact {
  template <class P, class V, class A, class T, class F>
    requires detail::ExactFactors<F>
  POINTMASS_HD static constexpr P position(const P& p0, const V& v0, const V& v1, const A& a,
                                           const T& t, const F& factors) noexcept {
    using R = scalar_t<T>;
    const R x = detail::log_kept<R>(factors);
    if (real_abs(x) < R(0.25)) {
      return p0 + v0 * (t * detail::phi1_of(factors, x)) + a * (t * t * detail::phi_series<2>(x));
    }
    return p0 + (v1 - v0 - a * t) * (t / x);
  }
};

}  // namespace pointmass::position

namespace pointmass {

/// A position policy usable with damping policy D (checked for float and double).
template <class P, class D>
concept PositionPolicyFor =
    DampingPolicy<D> &&
    requires(const Vector3<float>& vf, float tf, const damping_factors_t<D, float>& ff,
             const Vector3<double>& vd, double td, const damping_factors_t<D, double>& fd) {
      { P::position(vf, vf, vf, vf, tf, ff) } -> std::same_as<Vector3<float>>;
      { P::position(vd, vd, vd, vd, td, fd) } -> std::same_as<Vector3<double>>;
    };

}  // namespace pointmass
