// SPDX-License-Identifier: BSL-1.0
// pointmass/quantities.hpp — the types a particle's values have.
//
// A QuantitySet names the type of each physical value: length, velocity, acceleration,
// time, mass, inverse mass and force, all made of one Real. PlainQuantities<R> uses R for
// all of them; units.hpp provides one of Boost.Units SI quantities. A particle stores raw
// Real numbers and converts at its public boundary with `make` and `raw`; its step is
// written over the set's types, so with SI quantities the integrator's equations themselves
// are checked for dimensions at compile time.
//
// A set may also name the precision of the stored position (precision.hpp):
// `position_precision` (a Real or Compensated<R>) and `position`, the type a position is read
// and set as. Without them the position is a `length`, stored as `real`.
//
// Owns: the QuantitySet concept and PlainQuantities (the types of length, velocity, ...).
// Must not include: damping.hpp, position.hpp, particle.hpp (it is below them).
#pragma once

#include <concepts>

#include "config.hpp"
#include "precision.hpp"
#include "real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// S is a Real (every value a number of S) or a Precision<R, Position> (precision.hpp):
/// every value a number of R but the position, stored as Position.
template <PrecisionChoice S>
struct PlainQuantities {
  using R = real_of_t<S>;
  using real = R;
  using position_precision = position_precision_of_t<S>;
  using position = position_value_t<S>;
  using length = R;
  using velocity = R;
  using acceleration = R;
  using time = R;
  using mass = R;
  using inverse_mass = R;
  using force = R;

  /// The quantity of type Q whose number is `raw` (identity here).
  template <class Q>
  POINTMASS_HD static constexpr Q make(Q raw) noexcept {
    return raw;
  }
  /// The number a quantity holds (identity here).
  template <Real T>
  POINTMASS_HD static constexpr T raw(T quantity) noexcept {
    return quantity;
  }
};

template <class Q>
concept QuantitySet = Real<typename Q::real> && requires {
  typename Q::length;
  typename Q::velocity;
  typename Q::acceleration;
  typename Q::time;
  typename Q::mass;
  typename Q::inverse_mass;
  typename Q::force;
  {
    Q::raw(Q::template make<typename Q::length>(typename Q::real{}))
    } -> std::same_as<typename Q::real>;
};

namespace detail {

/// The stored position of a QuantitySet: its precision (a Real or Compensated<R>) and the
/// type it is read and set as; a set that names neither stores a `length` as `real`.
template <class Q>
struct QuantityPositions {
  using precision = typename Q::real;
  using type = typename Q::length;
};
// clang-format off
template <class Q>
  requires requires {
    typename Q::position_precision;
    typename Q::position;
  }
struct QuantityPositions<Q> {
  // clang-format on
  using precision = typename Q::position_precision;
  using type = typename Q::position;
};

}  // namespace detail

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
