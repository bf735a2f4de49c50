// SPDX-License-Identifier: BSL-1.0
// pointmass/particle.hpp — the point mass and its integrator.
//
//   pointmass::Particle<float>                       the defaults: per-second damping,
//                                                    position p + v t
//   pointmass::Particle<double, damping::PerFrame, position::ConstantAcceleration>
//   pointmass::BasicParticle<Quantities, D, P>       the same over any QuantitySet (units.hpp
//                                                    uses it for SI quantities)
//   pointmass::Particle<Precision<float, double>>    float arithmetic, double positions: far
//                                                    from the origin (precision.hpp)
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
//
// With a position precision other than the arithmetic's (Precision<float, double>,
// Precision<float, Compensated<float>>), p1 is p0 + d with the displacement
// d = P::position(-0, v0, v1, a, t, f) computed in the arithmetic's precision and added in the
// position's (precision.hpp); the velocity is the same, bit for bit, as with plain floats.
//
// Owns: integrate<D, P> (one step of one body's values) and BasicParticle / Particle.
// Must not include: particle_system.hpp, forces.hpp, units.hpp (they build on it).
#pragma once

#include <type_traits>

#include "config.hpp"
#include "damping.hpp"
#include "detail/validate.hpp"
#include "position.hpp"
#include "precision.hpp"
#include "quantities.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// One step of the model on one body's values, the damping factors already computed.
/// Generic arithmetic: p and v may be Vector3s or single components (the batch form steps
/// x, y and z apart), plain numbers or dimensioned quantities.
/// The new velocity is stored before the position is computed from the old one, kept in v0:
/// then v0 cannot be read from memory again for the position (the store overwrote it). In
/// the batch's loop, with the position computed first, g++ loaded each velocity twice (once
/// into a register, once as a multiply-add's memory operand): where loads and stores share
/// two address units, that held the lean step below a hand-written loop's speed. Same
/// arithmetic, same bits either way.
template <class D, class P, class Position, class Velocity, class Acceleration, class Time,
          class Factors>
POINTMASS_HD constexpr void integrate(Position& p, Velocity& v, const Acceleration& a,
                                      const Time& t, const Factors& factors) noexcept {
  const Velocity v0 = v;
  const Velocity v1 = D::velocity(v0, a, t, factors);
  v = v1;
  p = P::position(p, v0, v1, a, t, factors);
}
/// The name of integrate<D, P> in 0.1, kept one minor version.
template <class D, class P, class Position, class Velocity, class Acceleration, class Time,
          class Factors>
[[deprecated("pointmass 0.2: use integrate<D, P>")]] POINTMASS_HD constexpr void advance(
    Position& p, Velocity& v, const Acceleration& a, const Time& t,
    const Factors& factors) noexcept {
  integrate<D, P>(p, v, a, t, factors);
}

namespace detail {

/// One component's step on plain values: integrate<D, P>, or integrate_kicked with `kick`
/// and `last_half` for a kicked policy (untouched otherwise).
template <class D, class P, class Position, class R, class Factors>
POINTMASS_HD constexpr void integrate_component(Position& p, R& v, R& kick, const R& a, const R& t,
                                                const R& last_half,
                                                const Factors& factors) noexcept {
  if constexpr (kicks_v<P>) {
    integrate_kicked<D, P>(p, v, kick, a, t, last_half, factors);
  } else {
    static_cast<void>(kick);
    static_cast<void>(last_half);
    integrate<D, P>(p, v, a, t, factors);
  }
}

/// One component's step with a position stored as Storage says (precision.hpp's
/// PositionStorage): the displacement in the arithmetic's precision (the position policy from
/// p0 = -0, which the policy's p0 + x leaves out exactly: -0 + x is x, zeros' signs included),
/// added to the stored position in the position's. p is the element; lo the error
/// term (Compensated only; untouched otherwise). Particle::integrate computes the same.
template <class D, class P, class Storage, class R, class Factors>
POINTMASS_HD constexpr void integrate_stored(typename Storage::element& p, R& lo, R& v, R& kick,
                                             const R& a, const R& t, const R& last_half,
                                             const Factors& factors) noexcept {
  R displacement = -R(0);  // -0: the policy's p0 + x is then x, exactly (above)
  integrate_component<D, P>(displacement, v, kick, a, t, last_half, factors);
  if constexpr (Storage::compensated) {
    Storage::add(p, lo, displacement);
  } else {
    static_cast<void>(lo);
    Storage::add(p, displacement);
  }
}

}  // namespace detail

/// P is checked in the body (detail::check_policy_pair), so that an invalid pair of policies
/// is one sentence naming the pairs that work.
template <QuantitySet Q, DampingPolicy D = damping::PerSecond, class P = position::Euler>
class BasicParticle {
  static_assert(detail::check_policy_pair<D, P>());
  using Storage = detail::PositionStorage<typename detail::QuantityPositions<Q>::precision>;

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
  /// How the position is stored: `real` (today's particles), a wider Real, or
  /// Compensated<real> (precision.hpp).
  using position_precision = typename detail::QuantityPositions<Q>::precision;
  /// What position() returns and set_position takes, per component: length_type when the
  /// position is stored as `real`, else a length of position_value_t (double for
  /// Precision<float, double> and Precision<float, Compensated<float>>).
  using position_type = typename detail::QuantityPositions<Q>::type;
  /// The number type of the stored position (real, or a wider Real; real for Compensated).
  using position_element =
      typename detail::PositionStorage<typename detail::QuantityPositions<Q>::precision>::element;
  using damping_state = typename D::template State<real>;
  using damping_factors = damping_factors_t<D, real>;

  /// True when the damping policy stores a damping value (and so has set_damping).
  static constexpr bool stores_damping = !std::is_empty_v<damping_state>;
  /// True when the particle keeps the last step's damping factors and length, so that a step
  /// of the same length computes no exponential or power (the fixed steps games take): the
  /// policies whose factors depend on the step length (all but None and PerFrame). The kept
  /// factors are what D::factors returns, so results do not change, bit for bit.
  static constexpr bool caches_factors = detail::keeps_factors_v<D, real>;
  /// True for a position policy that keeps a credited half kick (position::VelocityVerlet).
  static constexpr bool kicks = detail::kicks_v<P>;
  /// True when the position is stored in the arithmetic's own precision (as today).
  static constexpr bool plain_position = std::is_same_v<position_precision, real>;
  static_assert(plain_position || PositionPrecision<position_precision, real>,
                "BasicParticle: the quantity set's position_precision must be a Real at least "
                "as wide as its real, or Compensated<real>");

  /// At rest at the origin, no acceleration, mass 1, damping 1 (none).
  constexpr BasicParticle() noexcept = default;

  // --- state -------------------------------------------------------------------------------

  [[nodiscard]] POINTMASS_HD constexpr Vector3<position_type> position() const noexcept {
    if constexpr (Storage::compensated) {
      return typed<position_type>(
          Vector3<position_value>{Storage::value_of(position_.x, position_error_.x),
                                  Storage::value_of(position_.y, position_error_.y),
                                  Storage::value_of(position_.z, position_error_.z)});
    } else {
      return typed<position_type>(position_);
    }
  }
  /// The position relative to `origin` (a camera), as float numbers (metres): computed from
  /// the whole stored position, and exact wherever the true offset is a float. T = real gives
  /// it in the arithmetic's own type, as a force generator sees it (forces::relative_to).
  /// A non-finite origin is a contract violation, checked when POINTMASS_CHECKS is on (then
  /// reported, and the result is zero).
  template <Real T = float>
  POINTMASS_HD constexpr Vector3<T> position_relative_to(const Vector3<position_type>& origin) const
      noexcept(!POINTMASS_HOST_CHECKS) {
    const Vector3<position_value> o = raw(origin);
#if POINTMASS_HOST_CHECKS
    if (!detail::check_finite("position_relative_to", "origin", o)) return {};
#endif
    if constexpr (Storage::compensated) {
      return {Storage::template relative<T>(position_.x, position_error_.x, o.x),
              Storage::template relative<T>(position_.y, position_error_.y, o.y),
              Storage::template relative<T>(position_.z, position_error_.z, o.z)};
    } else {
      return {Storage::template relative<T>(position_.x, o.x),
              Storage::template relative<T>(position_.y, o.y),
              Storage::template relative<T>(position_.z, o.z)};
    }
  }
  /// The stored position's numbers: the position itself when it is stored as `real` or a
  /// wider Real, the rounded part of hi + lo for Compensated<real> (precision.hpp).
  [[nodiscard]] POINTMASS_HD constexpr Vector3<position_element> stored_position() const noexcept {
    return position_;
  }
  /// Compensated<real> only: the error part lo of hi + lo.
  [[nodiscard]] POINTMASS_HD constexpr Vector3<real> stored_position_error()
      const noexcept requires Storage::compensated {
    return position_error_;
  }
  [[nodiscard]] POINTMASS_HD constexpr Vector3<velocity_type> velocity() const noexcept {
    return typed<velocity_type>(velocity_);
  }
  /// VelocityVerlet: the half kick velocity() holds on credit, which the next step settles
  /// (position.hpp). set_velocity and set_position leave it: the next step still settles it.
  [[nodiscard]] POINTMASS_HD constexpr Vector3<velocity_type> credited_kick()
      const noexcept requires kicks {
    return typed<velocity_type>(kick_.velocity);
  }
  /// VelocityVerlet: the length / 2 of the step that credited it (0 before the first step).
  [[nodiscard]] POINTMASS_HD constexpr time_type credited_half_step()
      const noexcept requires kicks {
    return Q::template make<time_type>(kick_.last_half);
  }
  [[nodiscard]] POINTMASS_HD constexpr Vector3<acceleration_type> acceleration() const noexcept {
    return typed<acceleration_type>(acceleration_);
  }
  [[nodiscard]] POINTMASS_HD constexpr Vector3<force_type> force_accumulator() const noexcept {
    return typed<force_type>(force_accumulator_);
  }
  /// The fraction of velocity kept (per second or per frame, as the policy says); 1 for
  /// damping::None.
  [[nodiscard]] POINTMASS_HD constexpr real damping() const noexcept { return damping_.value(); }
  [[nodiscard]] POINTMASS_HD constexpr inverse_mass_type inverse_mass() const noexcept {
    return Q::template make<inverse_mass_type>(inverse_mass_);
  }
  /// The mass; infinity for an immovable particle (inverse mass 0).
  [[nodiscard]] POINTMASS_HD constexpr mass_type mass() const noexcept {
    return Q::template make<mass_type>(inverse_mass_ > real(0) ? real(1) / inverse_mass_
                                                               : real_infinity<real>);
  }
  /// False for an immovable particle (inverse mass 0).
  [[nodiscard]] POINTMASS_HD constexpr bool has_finite_mass() const noexcept {
    return inverse_mass_ > real(0);
  }

  // --- setters: always validated; a rejected value leaves the particle unchanged ------------

  /// A finite position (for Compensated<real>, also within real's range: at most half an ulp
  /// beyond its largest, the midpoint included; hi is then the largest, lo the rest).
  constexpr void set_position(const Vector3<position_type>& position) {
    const auto p = raw(position);
    if constexpr (Storage::compensated) {
      if (!detail::check_finite("set_position", "position", p)) return;
      const Vector3<real> hi{Storage::element_of(p.x), Storage::element_of(p.y),
                             Storage::element_of(p.z)};
      if (!detail::check_representable("set_position", "position", p, hi)) return;
      position_ = hi;
      position_error_ = {Storage::error_of(p.x), Storage::error_of(p.y), Storage::error_of(p.z)};
    } else {
      if (detail::check_finite("set_position", "position", p)) position_ = p;
    }
  }
  constexpr void set_velocity(const Vector3<velocity_type>& velocity) {
    if (const auto v = raw(velocity); detail::check_finite("set_velocity", "velocity", v))
      velocity_ = v;
  }
  constexpr void set_acceleration(const Vector3<acceleration_type>& acceleration) {
    if (const auto a = raw(acceleration);
        detail::check_finite("set_acceleration", "acceleration", a)) {
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
  /// Inlined at any optimisation level, as is the step it takes with kept factors: a loop of
  /// fixed steps then makes no call per particle (g++ -O2 would call the whole function, and
  /// at -O3 it called the step; a call costs about as much as the step, and the force the
  /// caller has just added is stored and reloaded across it). A new step length goes to
  /// integrate_new_length, which the compiler inlines or calls as it judges.
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr void integrate(const time_type& duration) {
#if POINTMASS_HOST_CHECKS
    if (!detail::check_duration("integrate", Q::raw(duration))) return;
#endif
    if constexpr (caches_factors) {
      // The length of the last step (the fixed steps games take): the kept factors, and one
      // comparison fewer. The kept length is never 0 or NaN, so comparing bit patterns is
      // comparing values (one branch where == takes two), and a zero duration goes on below.
      // A stored inverse mass is never NaN or negative: zero (either sign) is immovable.
      if (detail::same_bits(Q::raw(duration), cache_.duration)) {
        if (!detail::is_zero(inverse_mass_)) step_with(duration, cache_.factors);
        else force_accumulator_ = {};  // immovable: forces cannot move it
        return;
      }
    }
    integrate_new_length(duration);
  }

 private:
  /// integrate for a step length whose factors are not kept (all of them, for a policy that
  /// keeps none): 0 <= duration, finite.
  POINTMASS_HD constexpr void integrate_new_length(const time_type& duration) {
    const real t = Q::raw(duration);
    // Nothing changes, the accumulated force waits. A comparison, as the batch's: a subnormal
    // t reads as 0 under FlushDenormals. As t > 0: t == 0 slowed the fixed step 6% (g++ 12).
    if (!(t > real(0))) return;
    if (detail::is_zero(inverse_mass_)) {  // immovable: forces cannot move it
      force_accumulator_ = {};
      return;
    }
    // The factors first: a power function's call then comes before the particle's values are
    // loaded, so none has to be kept across it.
    const damping_factors factors = detail::scalar_factors<D>(damping_, duration);
    if constexpr (caches_factors) cache_ = {t, factors};
    step_with(duration, factors);
  }

  /// The step once its damping factors are known (duration > 0, inverse mass > 0).
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr void step_with(
      const time_type& duration, const damping_factors factors) noexcept {
    const Vector3<acceleration_type> resulting_acceleration =
        typed<acceleration_type>(acceleration_) +
        typed<force_type>(force_accumulator_) * Q::template make<inverse_mass_type>(inverse_mass_);
    auto v = typed<velocity_type>(velocity_);
    if constexpr (!PositionPolicyFor<P, D>) {
      // the static_assert above has said why
    } else if constexpr (plain_position) {
      auto p = typed<length_type>(position_);
      step_values(p, v, resulting_acceleration, duration, factors);
      position_ = raw(p);
    } else {
      // The displacement from p0 = -0 (see integrate_stored), typed (so SI quantities check its
      // dimensions), then added to the stored position in its own precision (precision.hpp).
      auto displacement = typed<length_type>(Vector3<real>{-real(0), -real(0), -real(0)});
      step_values(displacement, v, resulting_acceleration, duration, factors);
      const Vector3<real> d = raw(displacement);
      if constexpr (Storage::compensated) {
        Storage::add(position_.x, position_error_.x, d.x);
        Storage::add(position_.y, position_error_.y, d.y);
        Storage::add(position_.z, position_error_.z, d.z);
      } else {
        Storage::add(position_.x, d.x);
        Storage::add(position_.y, d.y);
        Storage::add(position_.z, d.z);
      }
    }
    velocity_ = raw(v);
    force_accumulator_ = {};
  }

  // integrate<D, P> on typed values, or integrate_kicked with this particle's credited kick.
  template <class Position, class Velocity, class Acceleration>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr void step_values(
      Position& p, Velocity& v, const Acceleration& a, const time_type& duration,
      const damping_factors& factors) noexcept {
    if constexpr (kicks) {
      auto kick = typed<velocity_type>(kick_.velocity);
      pointmass::integrate_kicked<D, P>(p, v, kick, a, duration,
                                        Q::template make<time_type>(kick_.last_half), factors);
      kick_ = {raw(kick), Q::raw(duration) * real(0.5)};  // the same product as the step's
    } else {
      pointmass::integrate<D, P>(p, v, a, duration, factors);
    }
  }

  using position_value = typename Storage::value;
  struct NoPositionError {};
  struct Kick {  // VelocityVerlet's credited half kick, and the last step's length / 2
    Vector3<real> velocity{};
    real last_half = real(0);
  };
  struct NoKick {};

  template <class T, class N>
  POINTMASS_HD static constexpr Vector3<T> typed(const Vector3<N>& v) noexcept {
    return {Q::template make<T>(v.x), Q::template make<T>(v.y), Q::template make<T>(v.z)};
  }
  template <class T>
  POINTMASS_HD static constexpr auto raw(const Vector3<T>& v) noexcept {
    using N = std::remove_cvref_t<decltype(Q::raw(v.x))>;
    return Vector3<N>{Q::raw(v.x), Q::raw(v.y), Q::raw(v.z)};
  }

  // The inverse mass, which a step never writes, stands between the position and the
  // velocity: with the two vectors a step writes side by side (the textbook's order), g++
  // stored position x, y, z and velocity x as one four-wide store gathered by shuffles, and
  // the float step was slower than the double one. 52 bytes in float with damping::None;
  // PerSecond adds 12 of state (d, ln d as hi + lo) and 8 of kept factors: 72.
  Vector3<typename Storage::element> position_{};
  real inverse_mass_ = real(1);
  Vector3<real> velocity_{};
  Vector3<real> acceleration_{};
  Vector3<real> force_accumulator_{};
  [[no_unique_address]] damping_state damping_{};
  [[no_unique_address]] std::conditional_t<Storage::compensated, Vector3<real>, NoPositionError>
      position_error_{};
  [[no_unique_address]] std::conditional_t<caches_factors, detail::KeptFactors<D, real>,
                                           detail::NoKeptFactors>
      cache_{};
  [[no_unique_address]] std::conditional_t<kicks, Kick, NoKick> kick_{};
};

/// The particle over plain numbers (SI units by convention: metres, seconds, kilograms). R is
/// a Real, or a Precision<Real, Position> (precision.hpp) for positions stored wider than
/// the arithmetic (Precision<R> computes and stores as R does). R is used as it is, so that
/// generic code can deduce it from a Particle<R>.
/// (R is checked by PlainQuantities; a constraint on this alias itself made g++ 12 fail
/// nondeterministically.)
template <class R, DampingPolicy D = damping::PerSecond, class P = position::Euler>
using Particle = BasicParticle<PlainQuantities<R>, D, P>;

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
