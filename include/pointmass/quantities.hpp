// SPDX-License-Identifier: BSL-1.0
// pointmass/quantities.hpp — the types a particle's values have.
//
// A QuantitySet names the type of each physical value: length, velocity, acceleration,
// time, mass, inverse mass and force, all made of one Real. PlainQuantities<R> uses R for
// all of them; units.hpp provides one of Boost.Units SI quantities. A particle stores raw
// Real numbers and converts at its public boundary with `make` and `raw`; its step is
// written over the set's types, so with SI quantities the integrator's equations themselves
// are checked for dimensions at compile time.
#pragma once

#include <concepts>

#include "config.hpp"
#include "real.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

template <Real R>
struct PlainQuantities {
  using real = R;
  using length = R;
  using velocity = R;
  using acceleration = R;
  using time = R;
  using mass = R;
  using inverse_mass = R;
  using force = R;

  /// The quantity of type Q whose number is `raw` (identity here).
  template <class Q>
  POINTMASS_HD static constexpr Q make(R raw) noexcept {
    return raw;
  }
  /// The number a quantity holds (identity here).
  POINTMASS_HD static constexpr R raw(R quantity) noexcept { return quantity; }
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
  { Q::raw(Q::template make<typename Q::length>(typename Q::real{})) } -> std::same_as<typename Q::real>;
};

}  // namespace pointmass
