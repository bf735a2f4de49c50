// pointmass/scenes.hpp — ready-made scenes: the reference engine's ballistic shots and a
// mass on a spring. The tests, examples and benchmarks all use these, so every accuracy and
// speed figure the project reports is about the same work.
#pragma once

#include <array>
#include <string_view>

#include "real.hpp"
#include "vector3.hpp"

namespace pointmass::scenes {

/// One of the reference engine's ballistic shots: launched from `origin` with `velocity`,
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

/// Puts a particle at the start of a shot (any particle type with the core setters).
template <class Particle, Real R>
constexpr void launch(Particle& particle, const BallisticShot<R>& shot) {
  using real = typename Particle::real;
  particle.set_position({real(ballistic_origin<R>.x), real(ballistic_origin<R>.y),
                         real(ballistic_origin<R>.z)});
  particle.set_velocity({real(shot.velocity.x), real(shot.velocity.y), real(shot.velocity.z)});
  particle.set_acceleration(
      {real(shot.acceleration.x), real(shot.acceleration.y), real(shot.acceleration.z)});
  particle.set_mass(real(shot.mass));
  if constexpr (Particle::stores_damping) particle.set_damping(real(shot.damping));
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
