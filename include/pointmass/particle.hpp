// SPDX-License-Identifier: BSL-1.0
// pointmass/particle.hpp — the point mass and its integrator.
//
//   pointmass::Particle<float>                       the seed's engine: per-second damping,
//                                                    position p + v t
//   pointmass::Particle<double, damping::PerFrame, position::Kinematic>
//   pointmass::BasicParticle<Quantities, D, P>       the same over any QuantitySet (units.hpp
//                                                    uses it for SI quantities)
//
// One step of duration t (`integrate`), as the policies compose:
//   a  = acceleration + force_accumulator * inverse_mass     resulting acceleration
//   f  = D::factors(damping, t)                              per-step damping factors (d^t, ...),
//                                                            kept from the last step when t repeats
//   v1 = D::velocity(v0, a, t, f)                            eq. 3.5, 3.6, listing form, none, exact
//   p1 = P::position(p0, v0, v1, a, t, f)                    p + v0 t, + a t^2/2, p + v1 t, exact
//   force_accumulator = 0
// A zero duration changes nothing (the accumulated force waits for the next step). An
// infinite-mass particle (inverse mass 0) does not move: a step of t > 0 only clears its
// accumulator. ParticleSystem follows the same rule, so the two agree bit for bit. The
// acceleration is the user's (mainly gravity) and is never changed by a step.
#pragma once

#include <type_traits>

#include "config.hpp"
#include "detail/validate.hpp"
#include "damping.hpp"
#include "position.hpp"
#include "quantities.hpp"
#include "real.hpp"
#include "vector3.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// One step of the model on one body's values, the damping factors already computed.
/// Generic arithmetic: p and v may be Vector3s or single components (the batch form steps
/// x, y and z apart), plain numbers or dimensioned quantities.
template <class D, class P, class Position, class Velocity, class Acceleration, class Time,
          class Factors>
POINTMASS_HD constexpr void advance(Position& p, Velocity& v, const Acceleration& a,
                                    const Time& t, const Factors& factors) noexcept {
  const Velocity v1 = D::velocity(v, a, t, factors);
  p = P::position(p, v, v1, a, t, factors);
  v = v1;
}

/// P is checked in the body (detail::check_policy_pair), so that an invalid pair of policies
/// is one sentence naming the pairs that work.
template <QuantitySet Q, DampingPolicy D = damping::PerSecond, class P = position::Euler>
class BasicParticle {
  static_assert(detail::check_policy_pair<D, P>());

 public:
  using quantities = Q;
  using real = typename Q::real;
  using damping_policy = D;
  using position_policy = P;
  using length_type = typename Q::length;
  using velocity_type = typename Q::velocity;
  using acceleration_type = typename Q::acceleration;
  using time_type = typename Q::time;
  using mass_type = typename Q::mass;
  using inverse_mass_type = typename Q::inverse_mass;
  using force_type = typename Q::force;
  using damping_state = typename D::template State<real>;
  using damping_factors = damping_factors_t<D, real>;

  /// True when the damping policy stores a damping value (and so has set_damping).
  static constexpr bool stores_damping = !std::is_empty_v<damping_state>;
  /// True when the particle keeps the last step's damping factors and length, so that a step
  /// of the same length computes no exponential or power (the fixed steps games take): the
  /// policies whose factors depend on the step length (all but None and PerFrame). The kept
  /// factors are what D::factors returns, so results do not change, bit for bit.
  static constexpr bool caches_factors =
      !std::is_empty_v<damping_factors> && !std::is_same_v<D, damping::PerFrame>;

  /// At rest at the origin, no acceleration, mass 1, damping 1 (none).
  constexpr BasicParticle() noexcept = default;

  // --- state -------------------------------------------------------------------------------

  POINTMASS_HD constexpr Vector3<length_type> position() const noexcept {
    return typed<length_type>(position_);
  }
  POINTMASS_HD constexpr Vector3<velocity_type> velocity() const noexcept {
    return typed<velocity_type>(velocity_);
  }
  POINTMASS_HD constexpr Vector3<acceleration_type> acceleration() const noexcept {
    return typed<acceleration_type>(acceleration_);
  }
  POINTMASS_HD constexpr Vector3<force_type> force_accumulator() const noexcept {
    return typed<force_type>(force_accumulator_);
  }
  /// The fraction of velocity kept (per second or per frame, as the policy says); 1 for
  /// damping::None.
  POINTMASS_HD constexpr real damping() const noexcept { return damping_.value(); }
  POINTMASS_HD constexpr inverse_mass_type inverse_mass() const noexcept {
    return Q::template make<inverse_mass_type>(inverse_mass_);
  }
  /// The mass; infinity for an immovable particle (inverse mass 0).
  POINTMASS_HD constexpr mass_type mass() const noexcept {
    return Q::template make<mass_type>(inverse_mass_ > real(0) ? real(1) / inverse_mass_
                                                               : real_infinity<real>);
  }
  /// False for an immovable particle (inverse mass 0).
  POINTMASS_HD constexpr bool has_finite_mass() const noexcept { return inverse_mass_ > real(0); }

  // --- setters: always validated; a rejected value leaves the particle unchanged ------------

  constexpr void set_position(const Vector3<length_type>& position) {
    if (const auto p = raw(position); detail::check_finite("set_position", "position", p)) position_ = p;
  }
  constexpr void set_velocity(const Vector3<velocity_type>& velocity) {
    if (const auto v = raw(velocity); detail::check_finite("set_velocity", "velocity", v)) velocity_ = v;
  }
  constexpr void set_acceleration(const Vector3<acceleration_type>& acceleration) {
    if (const auto a = raw(acceleration); detail::check_finite("set_acceleration", "acceleration", a)) {
      acceleration_ = a;
    }
  }
  /// mass > 0 (infinity makes the particle immovable); zero, negative, NaN, a mass so small
  /// that 1/mass overflows `real`, or so large that 1/mass is subnormal, is rejected (so
  /// mass() is finite whenever has_finite_mass() is true).
  constexpr void set_mass(const mass_type& mass) {
    if (const real m = Q::raw(mass); detail::check_mass("set_mass", m)) inverse_mass_ = real(1) / m;
  }
  /// inverse mass 0 (immovable) or finite, normal and > 0. Zero mass (infinite inverse
  /// mass) cannot be expressed.
  constexpr void set_inverse_mass(const inverse_mass_type& inverse_mass) {
    const real im = Q::raw(inverse_mass);
    if (detail::check_inverse_mass("set_inverse_mass", im)) inverse_mass_ = im;
  }
  /// 0 <= damping <= 1: the fraction of velocity kept per second (per frame for PerFrame).
  /// Only for a policy that stores a damping value (stores_damping); generic code tests
  /// stores_damping before calling it.
  constexpr void set_damping(real damping) {
    static_assert(stores_damping,
                  "set_damping: this damping policy has no damping value to set (damping::None "
                  "damps nothing); choose damping::PerSecond, PerFrame, AccelerateThenDamp or "
                  "Exact to damp");
    if constexpr (stores_damping) {  // else the static_assert has said why
      if (detail::check_damping("set_damping", damping)) {
        damping_ = damping_state(damping);
        if constexpr (caches_factors) cache_ = {};
      }
    }
  }

  // --- forces and integration --------------------------------------------------------------

  /// Adds a force for the next step only. A non-finite force is a contract violation,
  /// checked when POINTMASS_CHECKS is on (debug builds by default).
  POINTMASS_HD constexpr void add_force(const Vector3<force_type>& force) {
    const auto f = raw(force);
#if POINTMASS_HOST_CHECKS
    if (!detail::check_finite("add_force", "force", f)) return;
#endif
    force_accumulator_ += f;
  }
  POINTMASS_HD constexpr void clear_accumulator() noexcept { force_accumulator_ = {}; }

  /// Advances the particle by `duration` (see the file comment). A negative, NaN or infinite
  /// duration is a contract violation, checked when POINTMASS_CHECKS is on; zero changes
  /// nothing.
  POINTMASS_HD constexpr void integrate(const time_type& duration) {
    const real t = Q::raw(duration);
#if POINTMASS_HOST_CHECKS
    if (!detail::check_duration("integrate", t)) return;
#endif
    if (real_equal(t, real(0))) return;         // nothing changes, the accumulated force waits
    if (!(inverse_mass_ > real(0))) {  // immovable: forces cannot move it
      force_accumulator_ = {};
      return;
    }

    // The factors first: a power function's call then comes before the particle's values are
    // loaded, so none has to be kept across it.
    const damping_factors factors = step_factors(duration);
    const Vector3<acceleration_type> resulting_acceleration =
        typed<acceleration_type>(acceleration_) +
        typed<force_type>(force_accumulator_) * Q::template make<inverse_mass_type>(inverse_mass_);
    auto p = typed<length_type>(position_);
    auto v = typed<velocity_type>(velocity_);
    if constexpr (PositionPolicyFor<P, D>) {  // else the static_assert above has said why
      advance<D, P>(p, v, resulting_acceleration, duration, factors);
    }
    position_ = raw(p);
    velocity_ = raw(v);
    force_accumulator_ = {};
  }

 private:
  /// The last step's length (-1 before the first: never a valid one) and its factors.
  struct FactorCache {
    real duration = real(-1);
    damping_factors factors{};
  };
  struct NoFactorCache {};

  /// D::factors(damping_, duration), computed again only when the length changes.
  POINTMASS_HD constexpr damping_factors step_factors(const time_type& duration) noexcept {
    if constexpr (caches_factors) {
      const real t = Q::raw(duration);
      if (real_equal(t, cache_.duration)) return cache_.factors;
      const damping_factors factors = detail::scalar_factors<D>(damping_, duration);
      cache_ = {t, factors};
      return factors;
    } else {
      return detail::scalar_factors<D>(damping_, duration);
    }
  }

  template <class T>
  POINTMASS_HD static constexpr Vector3<T> typed(const Vector3<real>& v) noexcept {
    return {Q::template make<T>(v.x), Q::template make<T>(v.y), Q::template make<T>(v.z)};
  }
  template <class T>
  POINTMASS_HD static constexpr Vector3<real> raw(const Vector3<T>& v) noexcept {
    return {Q::raw(v.x), Q::raw(v.y), Q::raw(v.z)};
  }

  Vector3<real> position_{};
  Vector3<real> velocity_{};
  Vector3<real> acceleration_{};
  Vector3<real> force_accumulator_{};
  real inverse_mass_ = real(1);
  [[no_unique_address]] damping_state damping_{};
  [[no_unique_address]] std::conditional_t<caches_factors, FactorCache, NoFactorCache> cache_{};
};

/// The particle over plain numbers (SI units by convention: metres, seconds, kilograms).
template <Real R, DampingPolicy D = damping::PerSecond, class P = position::Euler>
using Particle = BasicParticle<PlainQuantities<R>, D, P>;

}  // namespace pointmass
