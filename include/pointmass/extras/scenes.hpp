// SPDX-License-Identifier: BSL-1.0
// pointmass/extras/scenes.hpp — ready-made scenes (not in the umbrella header: include it
// explicitly): Cyclone's ballistic shots, a mass on a spring and a rope of springs with a
// buoy. The tests, examples and
// benchmarks all use these, so every accuracy and speed figure the project reports is about
// the same work.
//
// Owns: the scenes' data (the shots, the spring, the rope, the frame times), launching a
// particle of any type with a shot, and the rope's energy.
// Must not include: particle.hpp or anything above it (a scene is data, not a simulation).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../real.hpp"
#include "../vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
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

/// A rope of springs ending in a buoy, hung from an anchor over water: `count` particles of
/// `mass` (the last, the buoy, of `buoy_mass`), each joined to the next by a spring of
/// `link_stiffness` and rest `link_rest` (one generator each way: forces::Spring), the first
/// tied to `anchor` by a bungee of `bungee_stiffness`, rest `bungee_rest`
/// (forces::AnchoredBungee), the buoy held up by forces::Buoyancy(buoy_half_height,
/// buoy_volume, water_height), every particle under gravity g. Released from rest along +x at
/// the anchor's height, it swings down into the water: a stiff, force-driven scene, and no
/// damping, so its energy() is constant for the continuous model.
template <Real R>
struct RopeScene {
  static constexpr std::size_t count = 10;
  R mass = R(0.5);  // kg
  R buoy_mass = R(1);
  R link_stiffness = R(200);  // N/m
  R link_rest = R(0.5);       // m
  R bungee_stiffness = R(100);
  R bungee_rest = R(1);
  Vector3<R> anchor{R(0), R(10), R(0)};
  R water_height = R(3);
  R buoy_half_height = R(0.25);
  R buoy_volume = R(0.002);  // m^3 of water (1000 kg/m^3)
  R g = R(9.807);
  R duration = R(60);  // seconds

  [[nodiscard]] constexpr R mass_of(std::size_t i) const noexcept {
    return i + 1 == count ? buoy_mass : mass;
  }
  /// Particle i's starting position (at rest): along +x from the anchor, each link at rest.
  [[nodiscard]] constexpr Vector3<R> start(std::size_t i) const noexcept {
    return anchor + Vector3<R>{bungee_rest + link_rest * static_cast<R>(i), R(0), R(0)};
  }
  /// The mechanical energy of bodies[0, count) (anything with position() and velocity(), in
  /// the rope's order): kinetic, gravitational (from y = 0), the links', the bungee's (stretched
  /// only) and the buoyancy's potential, rho V g times the integral of the submerged fraction
  /// from y up to the surface plus the half-height.
  template <class Bodies>
  [[nodiscard]] R energy(const Bodies& bodies) const {
    R e = R(0);
    const auto stretch = [](const Vector3<R>& a, const Vector3<R>& b, R rest) {
      const Vector3<R> d = a - b;
      return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) - rest;
    };
    for (std::size_t i = 0; i < count; ++i) {
      const Vector3<R> p = bodies[i].position();
      const Vector3<R> v = bodies[i].velocity();
      e += mass_of(i) * ((v.x * v.x + v.y * v.y + v.z * v.z) / R(2) + g * p.y);
      if (i + 1 < count) {
        const R x = stretch(bodies[i + 1].position(), p, link_rest);
        e += link_stiffness * x * x / R(2);
      }
    }
    const R bungee = stretch(bodies[0].position(), anchor, bungee_rest);
    if (bungee > R(0)) e += bungee_stiffness * bungee * bungee / R(2);
    const R y = bodies[count - 1].position().y;
    const R top = water_height + buoy_half_height;  // above it, out of the water
    const R depth = y >= top ? R(0)
                    : y >= water_height - buoy_half_height
                        ? (top - y) * (top - y) / (R(4) * buoy_half_height)
                        : buoy_half_height + (water_height - buoy_half_height - y);
    return e + R(1000) * buoy_volume * g * depth;
  }
};

/// The frame times the accuracy figures use, in seconds.
inline constexpr std::array<double, 4> standard_frame_times{1.0 / 30, 1.0 / 60, 1.0 / 120,
                                                            1.0 / 240};

}  // namespace pointmass::scenes
POINTMASS_DETAIL_UNFUSED_END
