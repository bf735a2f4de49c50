// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/bodies.hpp — what a force generator acts on.
//
// Owns: the body concepts (PlainBody: one particle over plain numbers; SteppableBody: a
// PlainBody whose state a closed-form step may set; Bodies: a batch indexed 0 .. size() - 1;
// WideBody and WideBodies: a particle or batch whose positions are stored wider than its
// arithmetic, precision.hpp), the batch adapters SpanBodies (arrays of Vector3s) and SoaBodies
// (one array per component), and relative_to (RelativeBody, RelativeBodies): a wide particle or
// batch seen by generators from a local origin; detail::valid_bodies, the adapters' check of
// their spans that apply and apply_links make first.
// Must not include: particle.hpp, particle_system.hpp (the concepts are what those satisfy; a
// generator never needs the concrete types), or another forces header.
#pragma once

#include <concepts>
#include <cstddef>
#include <span>
#include <type_traits>

#include "../detail/validate.hpp"
#include "../real.hpp"
#include "../vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
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

/// A particle whose step a closed form may take over (StiffSpring::integrate): it also shows
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

/// An adapter or view that refers to bodies stored elsewhere (SpanBodies, SoaBodies and
/// relative_to's views declare `refers_to_bodies`): the forces added through it land in that
/// storage, so update_force and apply take a temporary one (apply.hpp).
template <class B>
concept BodyView = std::remove_cvref_t<B>::refers_to_bodies;

/// Bodies stored as arrays of Vector3s. `inverse_mass` may be empty: then every body has
/// `uniform_inverse_mass`. Forces are added to `force`, whose length is size(): every other
/// span needs at least that many elements, which apply and apply_links check first (valid).
template <Real R>
struct SpanBodies {
  using real = R;
  static constexpr bool refers_to_bodies = true;
  std::span<const Vector3<R>> positions;
  std::span<const Vector3<R>> velocities;
  std::span<const R> inverse_masses;
  std::span<Vector3<R>> forces;
  R uniform_inverse_mass = R(1);

  [[nodiscard]] std::size_t size() const noexcept { return forces.size(); }
  /// Whether every span has an element for each body; if not, reports the first that is
  /// shorter (naming `function`, the span and its length) and returns false.
  constexpr bool valid(const char* function) const {
    using pointmass::detail::check_span;
    const std::size_t n = size();
    return check_span(function, "positions", positions.size(), n) &&
           check_span(function, "velocities", velocities.size(), n) &&
           (inverse_masses.empty() ||
            check_span(function, "inverse_masses", inverse_masses.size(), n));
  }
  Vector3<R> position(std::size_t i) const noexcept { return positions[i]; }
  Vector3<R> velocity(std::size_t i) const noexcept { return velocities[i]; }
  R inverse_mass(std::size_t i) const noexcept {
    return inverse_masses.empty() ? uniform_inverse_mass : inverse_masses[i];
  }
  void add_force(std::size_t i, const Vector3<R>& f) noexcept { forces[i] += f; }
};

/// Bodies stored as structure of arrays: one array per component. `inverse_mass` may be
/// empty (then `uniform_inverse_mass`). Forces are added to fx, fy, fz; size() is fx's length,
/// and every other span needs at least that many elements, which apply and apply_links check
/// first (valid).
template <Real R>
struct SoaBodies {
  using real = R;
  static constexpr bool refers_to_bodies = true;
  std::span<const R> px, py, pz;
  std::span<const R> vx, vy, vz;
  std::span<const R> inverse_masses;
  std::span<R> fx, fy, fz;
  R uniform_inverse_mass = R(1);

  [[nodiscard]] std::size_t size() const noexcept { return fx.size(); }
  /// Whether every span has an element for each body; if not, reports the first that is
  /// shorter (naming `function`, the span and its length) and returns false.
  constexpr bool valid(const char* function) const {
    using pointmass::detail::check_span;
    const std::size_t n = size();
    return check_span(function, "px", px.size(), n) && check_span(function, "py", py.size(), n) &&
           check_span(function, "pz", pz.size(), n) && check_span(function, "vx", vx.size(), n) &&
           check_span(function, "vy", vy.size(), n) && check_span(function, "vz", vz.size(), n) &&
           (inverse_masses.empty() ||
            check_span(function, "inverse_masses", inverse_masses.size(), n)) &&
           check_span(function, "fy", fy.size(), n) && check_span(function, "fz", fz.size(), n);
  }
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

// --- positions stored wider than the arithmetic (precision.hpp) ---------------------------------
//
// A Particle or ParticleSystem of Precision<float, double> (or Compensated positions) keeps its
// position in a wider type than the float its generators compute in, so it is not a PlainBody
// or Bodies: rounding its position to float for a generator would give back, far from the
// origin, the centimetres the wide storage keeps. relative_to(body, origin) shows it to the
// generators as positions relative to `origin`, computed from the whole stored position and
// rounded once to the arithmetic's type: exact wherever the offset is a number of that type,
// and within its rounding of the offset otherwise. Choose the origin near what the generators
// compare positions with (a spring's anchor, the water's surface, the camera) and give those
// in the same frame: a spring's anchor at 3 m from the origin is `{3, 0, 0}`. Velocities,
// masses and forces are the particle's own; forces go to its accumulator as from any body.
// A view rather than generators templated on the position type: every generator, apply,
// apply_links and update_force work unchanged, no generator has a second kind of anchor, and
// what they compute is a difference of nearby positions, which the offset keeps.

/// A particle whose position is stored wider than its arithmetic: Particle<Precision<float,
/// double>> or Particle<Precision<float, Compensated<float>>> (plain numbers).
template <class B>
concept WideBody = requires(B& b, const B& cb, const Vector3<typename B::position_type>& origin,
                            const Vector3<typename B::real>& f) {
  requires !std::same_as<typename B::position_type, typename B::real>;
  {
    cb.template position_relative_to<typename B::real>(origin)
    } -> std::same_as<Vector3<typename B::real>>;
  { cb.velocity() } -> std::same_as<Vector3<typename B::real>>;
  { cb.inverse_mass() } -> std::same_as<typename B::real>;
  { cb.has_finite_mass() } -> std::same_as<bool>;
  b.add_force(f);
};

/// A batch whose positions are stored wider than its arithmetic: a ParticleSystem of
/// Precision<float, double> or Precision<float, Compensated<float>> with a force accumulator.
template <class B>
concept WideBodies = requires(B& b, const B& cb, std::size_t i,
                              const Vector3<typename B::position_value>& origin) {
  requires !std::same_as<typename B::position_value, typename B::real>;
  { cb.size() } -> std::convertible_to<std::size_t>;
  {
    cb.template position_relative_to<typename B::real>(i, origin)
    } -> std::same_as<Vector3<typename B::real>>;
  { cb.velocity(i) } -> std::same_as<Vector3<typename B::real>>;
  { cb.inverse_mass(i) } -> std::same_as<typename B::real>;
  b.add_force(i, Vector3<typename B::real>{});
};

namespace detail {

/// Whether `bodies` may be indexed 0 .. size() - 1: an adapter's own check of its spans
/// (SpanBodies::valid, SoaBodies::valid), which reports a short one; true for other bodies.
/// apply and apply_links call it before reading any body, whatever POINTMASS_CHECKS.
template <class B>
constexpr bool valid_bodies(const B& bodies, const char* function) {
  if constexpr (requires {
                  { bodies.valid(function) } -> std::same_as<bool>;
                }) {
    return bodies.valid(function);
  } else {
    return true;
  }
}

/// What both views hold: the viewed particle or batch (not owned: it must outlive the view)
/// and a copy of the local origin.
template <class T, class Origin>
class OriginView {
 public:
  static constexpr bool refers_to_bodies = true;
  constexpr OriginView(T& viewed, const Vector3<Origin>& origin) noexcept
      : viewed_(&viewed), origin_(origin) {}
  constexpr const Vector3<Origin>& origin() const noexcept { return origin_; }

 protected:
  constexpr T& viewed() const noexcept { return *viewed_; }

 private:
  T* viewed_;
  Vector3<Origin> origin_;
};

}  // namespace detail

/// A wide particle seen from `origin`: a PlainBody whose position is the particle's relative to
/// the origin.
template <WideBody P>
class RelativeBody : public detail::OriginView<P, typename P::position_type> {
  using View = detail::OriginView<P, typename P::position_type>;

 public:
  using real = typename P::real;
  using position_type = typename P::position_type;
  using View::View;

  constexpr Vector3<real> position() const noexcept {
    return body().template position_relative_to<real>(this->origin());
  }
  constexpr Vector3<real> velocity() const noexcept { return body().velocity(); }
  constexpr real inverse_mass() const noexcept { return body().inverse_mass(); }
  [[nodiscard]] constexpr bool has_finite_mass() const noexcept { return body().has_finite_mass(); }
  constexpr void add_force(const Vector3<real>& f) { body().add_force(f); }
  constexpr P& body() const noexcept { return this->viewed(); }
};

/// A wide batch seen from `origin`: Bodies whose positions are the batch's relative to the
/// origin.
template <WideBodies B>
class RelativeBodies : public detail::OriginView<B, typename B::position_value> {
  using View = detail::OriginView<B, typename B::position_value>;

 public:
  using real = typename B::real;
  using position_value = typename B::position_value;
  using View::View;

  [[nodiscard]] std::size_t size() const noexcept {
    return static_cast<std::size_t>(bodies().size());
  }
  Vector3<real> position(std::size_t i) const {
    return bodies().template position_relative_to<real>(i, this->origin());
  }
  Vector3<real> velocity(std::size_t i) const { return bodies().velocity(i); }
  real inverse_mass(std::size_t i) const { return bodies().inverse_mass(i); }
  void add_force(std::size_t i, const Vector3<real>& f) { bodies().add_force(i, f); }
  constexpr B& bodies() const noexcept { return this->viewed(); }
};

/// `body` (a particle with wide positions) as generators see it from `origin`.
template <WideBody P>
[[nodiscard]] constexpr RelativeBody<P> relative_to(
    P& body, const Vector3<typename P::position_type>& origin) noexcept {
  return RelativeBody<P>(body, origin);
}
/// `bodies` (a batch with wide positions) as generators see them from `origin`.
template <WideBodies B>
[[nodiscard]] constexpr RelativeBodies<B> relative_to(
    B& bodies, const Vector3<typename B::position_value>& origin) noexcept {
  return RelativeBodies<B>(bodies, origin);
}

}  // namespace pointmass::forces
POINTMASS_DETAIL_UNFUSED_END
