// SPDX-License-Identifier: BSL-1.0
// pointmass/units.hpp — the particle with Boost.Units SI quantities: a dimension error is a
// compile error, at no run-time cost. The one public header that needs Boost (headers only).
//
//   pointmass::units::Particle<double>                          SI quantities of double
//   pointmass::units::Particle<float, damping::PerFrame, position::ConstantAcceleration>
//   pointmass::units::Particle<Precision<float, double>>        float quantities, the position
//                                                               a units::length<double>
//
// Every input and output is a quantity of the particle's Real:
//
//   member / argument                     type                                   unit
//   position()         set_position        Vector3<units::length<R>>              m
//   velocity()         set_velocity        Vector3<units::velocity<R>>            m/s
//   acceleration()     set_acceleration    Vector3<units::acceleration<R>>        m/s^2
//   force_accumulator()  add_force         Vector3<units::force<R>>               N
//   mass()             set_mass            units::mass<R>                         kg
//   inverse_mass()     set_inverse_mass    units::inverse_mass<R>                 1/kg
//   integrate(duration)                    units::time<R>                         s
//   damping()          set_damping         R, a dimensionless fraction kept per second
//                                          (per frame for damping::PerFrame)
//
// The same class template as the plain pointmass::Particle (BasicParticle) with a different
// QuantitySet, so the same policies give the same results, bit for bit. The particle stores
// raw numbers (a Boost.Units quantity is not trivially copyable, which costs when it is
// passed through a call that is not inlined) and converts at its public boundary; the step
// itself runs on Vector3s of length, velocity and acceleration and on a time quantity, so
// `p + v t + a t^2 / 2` and every other policy equation is checked for dimensions when it
// is instantiated here. No quantity is turned into a raw number inside the step, except the
// exponent of d^t, which is the duration divided by one second (TimeTraits below).
//
// Building a vector of quantities: a Vector3 of numbers times a unit,
//   using namespace boost::units;
//   particle.set_velocity(pointmass::Vector3<double>{0, 30, 40} * si::meters_per_second);
//   particle.integrate(0.01 * si::seconds);
//
// What is checked, at compile time: a quantity of the wrong dimension anywhere (a velocity
// given as a position, a force given as an acceleration, a duration in metres); a Vector3 of
// quantities of another Real (Vector3<length<double>> for a float particle, and the
// reverse); a scalar quantity of a wider Real narrowed to the particle's (a double mass or
// duration for a float particle). Boost.Units converts a scalar float quantity to a double
// one implicitly, since that loses nothing. See docs/units.md for what the errors look like.
//
// With a Precision<R, Position> (precision.hpp) every value is a quantity of R but the
// position, read and set as a units::length of position_value_t (double for
// Precision<float, double> and Precision<float, Compensated<float>>); the step's
// displacement is still a length<R>, checked for dimensions as above.
//
// Owns: the Boost.Units face (SiQuantities, units::Particle); the one header that needs Boost.
// Must not include: particle_system.hpp or forces.hpp (the face is the particle's).
#pragma once

#include <type_traits>

#include <boost/units/quantity.hpp>
#include <boost/units/systems/si/acceleration.hpp>
#include <boost/units/systems/si/dimensionless.hpp>
#include <boost/units/systems/si/force.hpp>
#include <boost/units/systems/si/length.hpp>
#include <boost/units/systems/si/mass.hpp>
#include <boost/units/systems/si/time.hpp>
#include <boost/units/systems/si/velocity.hpp>

#include "damping.hpp"
#include "gravity.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "quantities.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::units {

namespace bu = ::boost::units;

/// The SI unit of inverse mass, 1/kg.
using inverse_kilogram_unit = bu::divide_typeof_helper<bu::si::dimensionless, bu::si::mass>::type;

template <Real R>
using length = bu::quantity<bu::si::length, R>;
template <Real R>
using velocity = bu::quantity<bu::si::velocity, R>;
template <Real R>
using acceleration = bu::quantity<bu::si::acceleration, R>;
template <Real R>
using time = bu::quantity<bu::si::time, R>;
template <Real R>
using mass = bu::quantity<bu::si::mass, R>;
template <Real R>
using inverse_mass = bu::quantity<inverse_kilogram_unit, R>;
template <Real R>
using force = bu::quantity<bu::si::force, R>;

/// The acceleration of gravity g pointing down (-Y), as a quantity: (0, -g, 0) m/s^2, by
/// default the Earth's (pointmass::gravity as SI quantities).
///   particle.set_acceleration(pointmass::units::gravity<double>());
template <Real R>
[[nodiscard]] constexpr Vector3<acceleration<R>> gravity(
    acceleration<R> g = acceleration<R>::from_value(earth_gravity<R>)) noexcept {
  return {acceleration<R>::from_value(R(0)), -g, acceleration<R>::from_value(R(0))};
}

/// The QuantitySet of Boost.Units SI quantities of R; S is a Real R or a
/// `Precision<R, Position>`, whose position is a length of `position_value_t<S>`.
template <PrecisionChoice S>
struct SiQuantities {
  using R = real_of_t<S>;
  using real = R;
  using position_precision = position_precision_of_t<S>;
  using position = units::length<position_value_t<S>>;
  using length = units::length<R>;
  using velocity = units::velocity<R>;
  using acceleration = units::acceleration<R>;
  using time = units::time<R>;
  using mass = units::mass<R>;
  using inverse_mass = units::inverse_mass<R>;
  using force = units::force<R>;

  /// The quantity of type Q (one of the above) whose number, in SI units, is `raw`.
  template <class Q>
  POINTMASS_HD static constexpr Q make(typename Q::value_type raw) noexcept {
    return Q::from_value(raw);
  }
  /// The number a quantity holds, in SI units.
  template <class Unit, class Y>
  POINTMASS_HD static constexpr Y raw(const bu::quantity<Unit, Y>& quantity) noexcept {
    return quantity.value();
  }
};

// The dimensions the step relies on, checked once here: the policies' equations produce
// exactly these types, so a policy that got a dimension wrong fails to compile.
static_assert(std::is_same_v<decltype(velocity<double>{} * time<double>{}), length<double>>);
static_assert(std::is_same_v<decltype(acceleration<double>{} * time<double>{}), velocity<double>>);
static_assert(
    std::is_same_v<decltype(force<double>{} * inverse_mass<double>{}), acceleration<double>>);

namespace detail {

/// The unit and the number type of a quantity (void and T itself for a plain T).
template <class T>
struct QuantityParts {
  using unit = void;
  using dimension = void;
  using real = T;
};
template <class Unit, class Y>
struct QuantityParts<bu::quantity<Unit, Y>> {
  using unit = Unit;
  using dimension = typename Unit::dimension_type;
  using real = Y;
};
template <class Given, class Expected>
inline constexpr bool same_unit_v =
    std::is_same_v<typename QuantityParts<Given>::unit, typename QuantityParts<Expected>::unit>;
template <class Given, class Expected>
inline constexpr bool same_real_v =
    std::is_same_v<typename QuantityParts<Given>::real, typename QuantityParts<Expected>::real>;
/// A quantity of the expected dimension and Real in another unit (milliseconds, kilometres):
/// converted to the expected SI quantity, as Boost.Units converts explicitly.
template <class Given, class Expected>
inline constexpr bool other_unit_v = !std::is_void_v<typename QuantityParts<Given>::dimension> &&
                                     std::is_same_v<typename QuantityParts<Given>::dimension,
                                                    typename QuantityParts<Expected>::dimension> &&
                                     same_real_v<Given, Expected>;
template <class Expected, class T>
constexpr Vector3<Expected> in_unit_of(const Vector3<T>& v) {
  return {Expected(v.x), Expected(v.y), Expected(v.z)};
}
/// False, but only once T is known: for a static_assert in a function that must fail when used.
template <class T>
inline constexpr bool always_false_v = false;

}  // namespace detail

// A wrong argument would otherwise fail with "cannot convert Vector3<quantity<unit<list<dim<
// length_base_dimension, ...>>>>>" and a page of template arguments. Each setter below has a
// catch-all overload that is chosen only for a wrong type and fails with one line that names
// the function, the quantity it expects and its unit. It also catches a scalar quantity of
// another Real, which Boost.Units would otherwise convert implicitly from float to double.
#define POINTMASS_UNITS_REJECT(function, Expected, given, what)                                \
  static_assert(detail::same_unit_v<given, Expected> || detail::other_unit_v<given, Expected>, \
                #function ": wrong dimension: the argument must be " what);                    \
  static_assert(!detail::same_unit_v<given, Expected> || detail::same_real_v<given, Expected>, \
                #function                                                                      \
                ": the argument's quantities are of another Real than the "                    \
                "particle's (float and double are not mixed)")

/// A particle whose every input and output is an SI quantity of R (see the file comment).
/// BasicParticle over SiQuantities<R>, plus one overload per setter that turns a wrong
/// argument type into a one-line error message. S is R or a Precision<R, Position>.
// clang-format off
template <class S, DampingPolicy D = damping::PerSecond, class P = position::Euler>
  requires(Real<S> || PrecisionChoice<S>)
class Particle : public BasicParticle<SiQuantities<canonical_precision_t<S>>, D, P> {
  // clang-format on
  using Base = BasicParticle<SiQuantities<canonical_precision_t<S>>, D, P>;
  using R = typename Base::real;

 public:
  using typename Base::acceleration_type;
  using typename Base::force_type;
  using typename Base::inverse_mass_type;
  using typename Base::length_type;
  using typename Base::mass_type;
  using typename Base::position_type;
  using typename Base::time_type;
  using typename Base::velocity_type;

  constexpr Particle() noexcept = default;

  using Base::add_force;
  using Base::integrate;
  using Base::set_acceleration;
  using Base::set_inverse_mass;
  using Base::set_mass;
  using Base::set_position;
  using Base::set_velocity;

  // Plain numbers, as a braced list `{0.0, 1.5, 0.0}` or a Vector3 of R (pointmass::gravity,
  // a converted glm or Eigen vector), have no unit: each of these says how to give one.
  void set_position(const Vector3<R>&) {
    static_assert(detail::always_false_v<R>,
                  "set_position: plain numbers have no unit; give metres, as in "
                  "pointmass::Vector3<double>{0, 1.5, 0} * si::meters");
  }
  void set_velocity(const Vector3<R>&) {
    static_assert(detail::always_false_v<R>,
                  "set_velocity: plain numbers have no unit; give metres per second, as in "
                  "pointmass::Vector3<double>{0, 30, 40} * si::meters_per_second");
  }
  void set_acceleration(const Vector3<R>&) {
    static_assert(detail::always_false_v<R>,
                  "set_acceleration: plain numbers have no unit; give metres per second squared, "
                  "as in pointmass::units::gravity<double>() or "
                  "pointmass::Vector3<double>{0, -20, 0} * si::meters_per_second_squared");
  }
  void add_force(const Vector3<R>&) {
    static_assert(detail::always_false_v<R>,
                  "add_force: plain numbers have no unit; give newtons, as in "
                  "pointmass::Vector3<double>{5, 0, 0} * si::newtons");
  }

  // The overloads below are chosen for an argument of another type: a quantity of the right
  // dimension in another unit is converted to SI; anything else fails with a static_assert
  // naming what was expected.
  template <class T>
    requires(!std::is_same_v<T, position_type>)
  void set_position(const Vector3<T>& position) {
    POINTMASS_UNITS_REJECT(set_position, position_type, T,
                           "a Vector3 of units::length<Real> (metres)");
    if constexpr (detail::other_unit_v<T, position_type>) {
      Base::set_position(detail::in_unit_of<position_type>(position));
    }
  }
  template <class T>
    requires(!std::is_same_v<T, velocity_type>)
  void set_velocity(const Vector3<T>& velocity) {
    POINTMASS_UNITS_REJECT(set_velocity, velocity_type, T,
                           "a Vector3 of units::velocity<Real> (metres per second)");
    if constexpr (detail::other_unit_v<T, velocity_type>) {
      Base::set_velocity(detail::in_unit_of<velocity_type>(velocity));
    }
  }
  template <class T>
    requires(!std::is_same_v<T, acceleration_type>)
  void set_acceleration(const Vector3<T>& acceleration) {
    POINTMASS_UNITS_REJECT(set_acceleration, acceleration_type, T,
                           "a Vector3 of units::acceleration<Real> (metres per second squared)");
    if constexpr (detail::other_unit_v<T, acceleration_type>) {
      Base::set_acceleration(detail::in_unit_of<acceleration_type>(acceleration));
    }
  }
  template <class T>
    requires(!std::is_same_v<T, force_type>)
  void add_force(const Vector3<T>& force) {
    POINTMASS_UNITS_REJECT(add_force, force_type, T, "a Vector3 of units::force<Real> (newtons)");
    if constexpr (detail::other_unit_v<T, force_type>) {
      Base::add_force(detail::in_unit_of<force_type>(force));
    }
  }
  template <class T>
    requires(!std::is_same_v<T, mass_type>)
  void set_mass(const T& mass) {
    POINTMASS_UNITS_REJECT(set_mass, mass_type, T, "a units::mass<Real> (kilograms)");
    if constexpr (detail::other_unit_v<T, mass_type>) Base::set_mass(mass_type(mass));
  }
  template <class T>
    requires(!std::is_same_v<T, inverse_mass_type>)
  void set_inverse_mass(const T& inverse_mass) {
    POINTMASS_UNITS_REJECT(set_inverse_mass, inverse_mass_type, T,
                           "a units::inverse_mass<Real> (per kilogram)");
    if constexpr (detail::other_unit_v<T, inverse_mass_type>) {
      Base::set_inverse_mass(inverse_mass_type(inverse_mass));
    }
  }
  template <class T>
    requires(!std::is_same_v<T, time_type>)
  void integrate(const T& duration) {
    POINTMASS_UNITS_REJECT(integrate, time_type, T, "a units::time<Real> (seconds)");
    if constexpr (detail::other_unit_v<T, time_type>) Base::integrate(time_type(duration));
  }
};

#undef POINTMASS_UNITS_REJECT

}  // namespace pointmass::units

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// A Vector3 of numbers times a unit is a Vector3 of quantities:
/// `Vector3<double>{0, 30, 40} * si::meters_per_second`. (More specialised than both
/// Boost.Units' `number * unit` and Vector3's `vector * scalar`, which would otherwise be
/// ambiguous.)
template <class T, class Dim, class System>
POINTMASS_HD constexpr Vector3<::boost::units::quantity<::boost::units::unit<Dim, System>, T>>
operator*(const Vector3<T>& v, const ::boost::units::unit<Dim, System>& unit) noexcept {
  return {v.x * unit, v.y * unit, v.z * unit};
}
template <class T, class Dim, class System>
POINTMASS_HD constexpr Vector3<::boost::units::quantity<::boost::units::unit<Dim, System>, T>>
operator*(const ::boost::units::unit<Dim, System>& unit, const Vector3<T>& v) noexcept {
  return {v.x * unit, v.y * unit, v.z * unit};
}

/// A quantity's number is its value type.
template <class Unit, class Y>
struct ScalarOf<::boost::units::quantity<Unit, Y>> {
  using type = Y;
};

/// A time quantity in seconds: t / (1 s), a dimensionless ratio, as a number (the exponent of
/// the per-second damping d^t).
template <class Y>
struct TimeTraits<::boost::units::quantity<::boost::units::si::time, Y>> {
  POINTMASS_HD static constexpr Y seconds(
      const ::boost::units::quantity<::boost::units::si::time, Y>& t) noexcept {
    const ::boost::units::quantity<::boost::units::si::dimensionless, Y> ratio =
        t / (Y(1) * ::boost::units::si::second);
    return ratio.value();
  }
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
