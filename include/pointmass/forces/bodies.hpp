// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/bodies.hpp — what a force generator acts on.
//
// Owns: the body concepts (PlainBody: one particle over plain numbers; SteppableBody: a
// PlainBody whose state a closed-form step may set; Bodies: a batch indexed 0 .. size() - 1)
// and the batch adapters SpanBodies (arrays of Vector3s) and SoaBodies (one array per
// component).
// Must not include: particle.hpp, particle_system.hpp (the concepts are what those satisfy; a
// generator never needs the concrete types), or another forces header.
#pragma once

#include <concepts>
#include <cstddef>
#include <span>

#include "../real.hpp"
#include "../vector3.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces {

/// A particle over plain R numbers (Particle<R, D, P> for any policies D, P).
template <class B, class R>
concept PlainBody = requires(B& b, const B& cb, const Vector3<R>& f) {
  { cb.position() } -> std::same_as<Vector3<R>>;
  { cb.velocity() } -> std::same_as<Vector3<R>>;
  { cb.inverse_mass() } -> std::same_as<R>;
  { cb.has_finite_mass() } -> std::same_as<bool>;
  b.add_force(f);
};

/// A particle whose step a closed form may take over (StiffSpring::advance): it also shows
/// its own acceleration and accumulated force, and takes a new position and velocity.
template <class B, class R>
concept SteppableBody = PlainBody<B, R> && requires(B& b, const B& cb, const Vector3<R>& x) {
  { cb.acceleration() } -> std::same_as<Vector3<R>>;
  { cb.force_accumulator() } -> std::same_as<Vector3<R>>;
  b.set_position(x);
  b.set_velocity(x);
  b.clear_accumulator();
};

/// A batch of bodies, indexed 0 .. size() - 1.
template <class B>
concept Bodies = requires(B& b, const B& cb, std::size_t i) {
  typename B::real;
  { cb.size() } -> std::convertible_to<std::size_t>;
  { cb.position(i) } -> std::same_as<Vector3<typename B::real>>;
  { cb.velocity(i) } -> std::same_as<Vector3<typename B::real>>;
  { cb.inverse_mass(i) } -> std::same_as<typename B::real>;
  b.add_force(i, Vector3<typename B::real>{});
};

/// Bodies stored as arrays of Vector3s. `inverse_mass` may be empty: then every body has
/// `uniform_inverse_mass`. Forces are added to `force`.
template <Real R>
struct SpanBodies {
  using real = R;
  std::span<const Vector3<R>> positions;
  std::span<const Vector3<R>> velocities;
  std::span<const R> inverse_masses;
  std::span<Vector3<R>> forces;
  R uniform_inverse_mass = R(1);

  std::size_t size() const noexcept { return forces.size(); }
  Vector3<R> position(std::size_t i) const noexcept { return positions[i]; }
  Vector3<R> velocity(std::size_t i) const noexcept { return velocities[i]; }
  R inverse_mass(std::size_t i) const noexcept {
    return inverse_masses.empty() ? uniform_inverse_mass : inverse_masses[i];
  }
  void add_force(std::size_t i, const Vector3<R>& f) noexcept { forces[i] += f; }
};

/// Bodies stored as structure of arrays: one array per component. `inverse_mass` may be
/// empty (then `uniform_inverse_mass`). Forces are added to fx, fy, fz.
template <Real R>
struct SoaBodies {
  using real = R;
  std::span<const R> px, py, pz;
  std::span<const R> vx, vy, vz;
  std::span<const R> inverse_masses;
  std::span<R> fx, fy, fz;
  R uniform_inverse_mass = R(1);

  std::size_t size() const noexcept { return fx.size(); }
  Vector3<R> position(std::size_t i) const noexcept { return {px[i], py[i], pz[i]}; }
  Vector3<R> velocity(std::size_t i) const noexcept { return {vx[i], vy[i], vz[i]}; }
  R inverse_mass(std::size_t i) const noexcept {
    return inverse_masses.empty() ? uniform_inverse_mass : inverse_masses[i];
  }
  void add_force(std::size_t i, const Vector3<R>& f) noexcept {
    fx[i] += f.x;
    fy[i] += f.y;
    fz[i] += f.z;
  }
};

}  // namespace pointmass::forces
