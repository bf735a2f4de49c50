// SPDX-License-Identifier: BSL-1.0
// pointmass/extras/scenes.hpp — ready-made scenes (not in the umbrella header: include it
// explicitly): Cyclone's ballistic shots and a mass on a spring. The tests, examples and
// benchmarks all use these, so every accuracy and speed figure the project reports is about
// the same work.
//
// Owns: the scenes' data (the shots, the spring, the frame times) and launching a particle
// of any type with a shot.
// Must not include: particle.hpp or anything above it (a scene is data, not a simulation).
#pragma once

#include <array>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../real.hpp"
#include "../vector3.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::scenes {

/// One of Cyclone's ballistic shots: launched from `origin` with `velocity`,
/// under constant `acceleration` (its gravity), with per-second `damping`.
template <Real R>
struct BallisticShot {
  std::string_view name;
  R mass;
  Vector3<R> velocity;
  Vector3<R> acceleration;
  R damping;
};

/// Where every shot starts, in metres.
template <Real R>
inline constexpr Vector3<R> ballistic_origin{R(0), R(1.5), R(0)};

/// How long a round lasts at most, in seconds.
template <Real R>
inline constexpr R ballistic_duration = R(5);

/// The four shots: pistol, artillery, fireball, laser (mass in kg, SI units).
template <Real R>
inline constexpr std::array<BallisticShot<R>, 4> ballistic_shots{{
    {"pistol", R(2), {R(0), R(0), R(35)}, {R(0), R(-1), R(0)}, R(0.99)},
    {"artillery", R(200), {R(0), R(30), R(40)}, {R(0), R(-20), R(0)}, R(0.99)},
    {"fireball", R(1), {R(0), R(0), R(10)}, {R(0), R(0.6), R(0)}, R(0.9)},
    {"laser", R(0.1), {R(0), R(0), R(100)}, {R(0), R(0), R(0)}, R(0.99)},
}};

namespace detail {
/// The scene's vector v as a Vector3 of the particle's quantity T (through its QuantitySet),
/// converted to T's own number type (the position's may be wider than the arithmetic's).
template <class T, class Particle, Real R>
constexpr Vector3<T> as_quantities(const Vector3<R>& v) {
  using Q = typename Particle::quantities;
  using number = std::remove_cvref_t<decltype(Q::raw(std::declval<T>()))>;
  return {Q::template make<T>(number(v.x)), Q::template make<T>(number(v.y)),
          Q::template make<T>(number(v.z))};
}
}  // namespace detail

/// Puts a particle at the start of a shot: any BasicParticle, over plain numbers or SI
/// quantities (units.hpp), in any precision.
template <class Particle, Real R>
constexpr void launch(Particle& particle, const BallisticShot<R>& shot) {
  using P = Particle;
  particle.set_position(detail::as_quantities<typename P::position_type, P>(ballistic_origin<R>));
  particle.set_velocity(detail::as_quantities<typename P::velocity_type, P>(shot.velocity));
  particle.set_acceleration(
      detail::as_quantities<typename P::acceleration_type, P>(shot.acceleration));
  particle.set_mass(
      P::quantities::template make<typename P::mass_type>(typename P::real(shot.mass)));
  if constexpr (P::stores_damping) particle.set_damping(typename P::real(shot.damping));
}

/// A mass on a spring to a fixed anchor at the origin: force -stiffness * position -
/// friction * velocity, added each step with add_force. Stiffness 4 pi^2 with mass 1 gives a
/// period of 1 s (angular frequency 2 pi).
template <Real R>
struct SpringScene {
  R mass = R(1);
  R stiffness = R(39.47841760435743);  // (2 pi)^2
  R friction = R(0);                   // N s/m; 0 undamped
  Vector3<R> start{R(1), R(0), R(0)};  // released from rest
  R duration = R(10);                  // seconds: ten periods
};

/// The frame times the accuracy figures use, in seconds.
inline constexpr std::array<double, 4> standard_frame_times{1.0 / 30, 1.0 / 60, 1.0 / 120,
                                                            1.0 / 240};

}  // namespace pointmass::scenes
