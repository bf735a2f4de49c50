// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/generators.hpp — the force generators over a body's own state, the
// springs between bodies, and apply_links for springs between the bodies of a batch.
//
// Owns: Gravity, Drag, SpringParameters, AnchoredSpring / AnchoredBungee, Spring / Bungee,
// Buoyancy, LinkSprings / LinkBungees, Link, apply_links, apply_link, detail::spring_force.
// Each field generator's `force(p, v, inverse_mass, t)` is what update_force and apply call.
// Must not include: particle.hpp, particle_system.hpp (a spring between particles is a
// template over the body type), oscillator.hpp or registry.hpp.
#pragma once

#include <cstddef>
#include <span>
#include <type_traits>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "bodies.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces {
namespace detail {
/// The separation p - q as a unit direction and a length in units of `scale`: the length
/// |p - q| = length * scale, scale 1 unless p - q or its length overflows (then 4).
template <Real R>
struct Separation {
  Vector3<R> direction;
  R length;
  R scale;
};

template <Real R>
[[nodiscard]] constexpr Separation<R> separation(const Vector3<R>& p,
                                                 const Vector3<R>& q) noexcept {
  Vector3<R> d = p - q;
  R length = magnitude(d);
  R scale = R(1);
  if (!real_isfinite(length)) {  // |p - q| beyond the largest R: a quarter of it is not
    d = p * R(0.25) - q * R(0.25);
    length = magnitude(d);
    scale = R(4);
  }
  return {normalized(d), length, scale};
}

/// The force of a spring of stiffness k and rest length L on the end at p from the end at
/// q: -k (|d| - L) d / |d| with d = p - q. Zero for k = 0 and for d = 0 (no direction). With
/// `bungee`, zero while |d| <= L. Finite whenever k (|d| + L) is below the largest R.
template <Real R>
constexpr Vector3<R> spring_force(const Vector3<R>& p, const Vector3<R>& q, R k, R L,
                                  bool bungee) noexcept {
  if (!(k > R(0))) return {};
  const Separation<R> s = separation(p, q);
  if (!(s.length > R(0))) return {};
  const R extension = s.length - L / s.scale;  // signed: negative when compressed
  if (bungee && !(extension > R(0))) return {};
  return s.direction * (-k * extension * s.scale);
}

}  // namespace detail

/// Gravity as a force, f = m g, for use through a registry (a particle's own acceleration is
/// the cheaper way to give every particle the same g). An immovable body gets nothing (its
/// mass is infinite: m g would be infinite or NaN). Range: m |g| below the largest R.
template <Real R>
class Gravity {
 public:
  using real = R;
  constexpr Gravity() noexcept = default;
  /// A rejected `g` leaves the generator inert (g = 0), not at the default's Earth gravity.
  constexpr explicit Gravity(const Vector3<R>& g) {
    g_ = pointmass::detail::check_finite("Gravity::set_gravity", "gravity", g) ? g : Vector3<R>{};
  }

  [[nodiscard]] constexpr Vector3<R> gravity() const noexcept { return g_; }
  constexpr void set_gravity(const Vector3<R>& g) {
    if (pointmass::detail::check_finite("Gravity::set_gravity", "gravity", g)) g_ = g;
  }

  [[nodiscard]] constexpr Vector3<R> force(const Vector3<R>&, const Vector3<R>&, R inverse_mass,
                                           R) const noexcept {
    if (!(inverse_mass > R(0))) return {};
    return g_ / inverse_mass;
  }

 private:
  Vector3<R> g_{R(0), R(-9.807), R(0)};
};

/// Drag against the velocity: magnitude k1 |v| + k2 |v|^2, so f = -v (k1 + k2 |v|). No force
/// at rest (no direction, no NaN). Range: |v| (k1 + k2 |v|) below the largest R.
template <Real R>
class Drag {
 public:
  using real = R;
  constexpr Drag() noexcept = default;
  /// Both are checked (each rejected one is reported); one rejected leaves both 0: no force.
  constexpr Drag(R k1, R k2) {
    const bool k1_valid = pointmass::detail::check_non_negative("Drag::set_k1", "k1", k1);
    const bool k2_valid = pointmass::detail::check_non_negative("Drag::set_k2", "k2", k2);
    if (k1_valid && k2_valid) {
      k1_ = k1;
      k2_ = k2;
    }
  }

  [[nodiscard]] constexpr R k1() const noexcept { return k1_; }
  [[nodiscard]] constexpr R k2() const noexcept { return k2_; }
  constexpr void set_k1(R k1) {
    pointmass::detail::assign_non_negative("Drag::set_k1", "k1", k1, k1_);
  }
  constexpr void set_k2(R k2) {
    pointmass::detail::assign_non_negative("Drag::set_k2", "k2", k2, k2_);
  }

  [[nodiscard]] constexpr Vector3<R> force(const Vector3<R>&, const Vector3<R>& v, R,
                                           R) const noexcept {
    // k2 = 0 never multiplies the speed (which may be infinite for |v| beyond the largest R).
    const R per_speed = k2_ > R(0) ? k1_ + k2_ * magnitude(v) : k1_;
    if (real_isfinite(per_speed)) return v * -per_speed;
    // k1 + k2 ||v|| beyond the range: below a speed of 1 the force itself may not be, so its
    // two terms are formed apart (each, and their sum, within the range whenever it is).
    // ||v|| itself may be beyond it (finite components, a tiny k2): then k2 ||v|| is formed
    // as (k2 s) ||v / s|| with s the largest component.
    R k2_speed = k2_ * magnitude(v);
    if (!real_isfinite(k2_speed)) {
      const R s = pointmass::detail::largest_component(v);
      k2_speed = (k2_ * s) * magnitude(v / s);
    }
    return v * -k1_ - v * k2_speed;
  }

 private:
  R k1_ = R(0);
  R k2_ = R(0);
};

/// What springs and bungees share: stiffness k >= 0 and rest length L >= 0, validated, and
/// the force between the two ends (a bungee's, with IsBungee).
template <Real R, bool IsBungee = false>
class SpringParameters {
 public:
  using real = R;
  constexpr SpringParameters() noexcept = default;
  /// Both are checked (each rejected one is reported); one rejected leaves both 0: no force.
  constexpr SpringParameters(R stiffness, R rest_length) {
    const bool k_valid =
        pointmass::detail::check_non_negative("set_stiffness", "stiffness", stiffness);
    const bool length_valid =
        pointmass::detail::check_non_negative("set_rest_length", "rest_length", rest_length);
    if (k_valid && length_valid) {
      k_ = stiffness;
      rest_length_ = rest_length;
    }
  }
  [[nodiscard]] constexpr R stiffness() const noexcept { return k_; }
  [[nodiscard]] constexpr R rest_length() const noexcept { return rest_length_; }
  constexpr void set_stiffness(R stiffness) {
    pointmass::detail::assign_non_negative("set_stiffness", "stiffness", stiffness, k_);
  }
  constexpr void set_rest_length(R rest_length) {
    pointmass::detail::assign_non_negative("set_rest_length", "rest_length", rest_length,
                                           rest_length_);
  }

  /// The force on the end at p from the end at `other_position`.
  [[nodiscard]] constexpr Vector3<R> force_between(
      const Vector3<R>& p, const Vector3<R>& other_position) const noexcept {
    return detail::spring_force(p, other_position, k_, rest_length_, IsBungee);
  }

 protected:
  /// What a derived constructor that rejected an argument leaves: no force.
  constexpr void make_inert() noexcept {
    k_ = R(0);
    rest_length_ = R(0);
  }

  R k_ = R(0);
  R rest_length_ = R(0);
};

/// A spring (or with IsBungee, a bungee) from a body to a fixed anchor point.
/// Range: k (|p - anchor| + L) below the largest R.
template <Real R, bool IsBungee = false>
class BasicAnchoredSpring : public SpringParameters<R, IsBungee> {
 public:
  constexpr BasicAnchoredSpring() noexcept = default;
  /// Every argument is checked (each rejected one is reported); one rejected leaves the
  /// spring inert: stiffness and rest length 0.
  constexpr BasicAnchoredSpring(const Vector3<R>& anchor, R stiffness, R rest_length)
      : SpringParameters<R, IsBungee>(stiffness, rest_length) {
    if (pointmass::detail::check_finite("set_anchor", "anchor", anchor)) {
      anchor_ = anchor;
    } else {
      this->make_inert();
    }
  }
  [[nodiscard]] constexpr Vector3<R> anchor() const noexcept { return anchor_; }
  constexpr void set_anchor(const Vector3<R>& anchor) {
    if (pointmass::detail::check_finite("set_anchor", "anchor", anchor)) anchor_ = anchor;
  }

  [[nodiscard]] constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>&, R,
                                           R) const noexcept {
    return this->force_between(p, anchor_);
  }

 private:
  Vector3<R> anchor_{};
};

template <Real R>
using AnchoredSpring = BasicAnchoredSpring<R, false>;
template <Real R>
using AnchoredBungee = BasicAnchoredSpring<R, true>;

/// A spring (or bungee) between two bodies, as Cyclone has it: registered with
/// one body, it pulls that body towards `other`; register a second one, with the ends swapped,
/// for the other body. In a batch, `apply_links` does both ends at once. The other body is
/// not owned: it must outlive the spring's use, and a temporary (a particle returned by value,
/// a relative_to view made in the call) is refused at compile time with one sentence.
template <class Body, bool IsBungee = false>
class BasicSpring : public SpringParameters<typename Body::real, IsBungee> {
  /// A temporary body (a Body, or a class derived from it, as an rvalue): `const Body&` would
  /// bind to it. A wrapper that refers to a body elsewhere (std::ref) is not one.
  template <class Other>
  static constexpr bool temporary_other =
      !std::is_lvalue_reference_v<Other> && (std::is_same_v<std::remove_cvref_t<Other>, Body> ||
                                             std::is_base_of_v<Body, std::remove_cvref_t<Other>>);

 public:
  using real = typename Body::real;
  constexpr BasicSpring() noexcept = default;
  constexpr BasicSpring(const Body& other, real stiffness, real rest_length)
      : SpringParameters<real, IsBungee>(stiffness, rest_length), other_(&other) {}
  template <class Other>
    requires(temporary_other<Other>)
  BasicSpring(Other&&, real, real) {
    static_assert(!temporary_other<Other>,
                  "Spring keeps the address of the other body, and the other body is a "
                  "temporary: pass a named body (or view) that outlives the spring.");
  }

  [[nodiscard]] constexpr const Body* other() const noexcept { return other_; }
  constexpr void set_other(const Body& other) noexcept { other_ = &other; }
  template <class Other>
    requires(temporary_other<Other>)
  void set_other(Other&&) {
    static_assert(!temporary_other<Other>,
                  "Spring::set_other keeps the address of the other body, and the other body "
                  "is a temporary: pass a named body (or view) that outlives the spring.");
  }

  /// Adds the force from the other end (nothing without one); a force beyond the range of
  /// the number type is reported, as by forces::update_force.
  template <PlainBody<real> B>
  constexpr void update_force(B& body, real) const {
    if (other_ == nullptr) return;
    const auto f = this->force_between(body.position(), other_->position());
    if (pointmass::detail::check_force("Spring::update_force", f)) body.add_force(f);
  }

 private:
  const Body* other_ = nullptr;
};

template <class Body>
using Spring = BasicSpring<Body, false>;
template <class Body>
using Bungee = BasicSpring<Body, true>;

/// Buoyancy of a body of half-height D (`max_depth`) and volume V in a liquid of density rho
/// whose surface is the plane y = h, under gravity g: the body is out of the liquid for
/// y >= h + D, fully submerged for y <= h - D, and in between the submerged fraction s varies
/// linearly. The force is +Y, rho V g s, never downwards (Archimedes: the weight of the
/// displaced liquid). Defaults: water (1000 kg/m^3), g = 9.807 m/s^2. Range: rho V g below
/// the largest R.
template <Real R>
class Buoyancy {
 public:
  using real = R;
  constexpr Buoyancy() noexcept = default;
  /// Every argument is checked (each rejected one is reported); one rejected leaves every
  /// parameter at its default, volume 0: no force.
  constexpr Buoyancy(R max_depth, R volume, R water_height, R liquid_density = R(1000),
                     R g = R(9.807)) {
    using pointmass::detail::check_finite;
    using pointmass::detail::check_non_negative;
    using pointmass::detail::check_positive;
    const bool valid[] = {
        check_positive("Buoyancy::set_max_depth", "max_depth", max_depth),
        check_positive("Buoyancy::set_volume", "volume", volume),
        check_finite("Buoyancy::set_water_height", "water_height", water_height),
        check_non_negative("Buoyancy::set_liquid_density", "liquid_density", liquid_density),
        check_non_negative("Buoyancy::set_gravity", "g", g)};
    for (const bool v : valid) {
      if (!v) return;
    }
    max_depth_ = max_depth;
    volume_ = volume;
    water_height_ = water_height;
    density_ = liquid_density;
    g_ = g;
  }

  constexpr R max_depth() const noexcept { return max_depth_; }
  constexpr R volume() const noexcept { return volume_; }
  constexpr R water_height() const noexcept { return water_height_; }
  constexpr R liquid_density() const noexcept { return density_; }
  constexpr R gravity() const noexcept { return g_; }
  constexpr void set_max_depth(R max_depth) {
    if (pointmass::detail::check_positive("Buoyancy::set_max_depth", "max_depth", max_depth)) {
      max_depth_ = max_depth;
    }
  }
  constexpr void set_volume(R volume) {
    if (pointmass::detail::check_positive("Buoyancy::set_volume", "volume", volume))
      volume_ = volume;
  }
  constexpr void set_water_height(R water_height) {
    if (pointmass::detail::check_finite("Buoyancy::set_water_height", "water_height",
                                        water_height)) {
      water_height_ = water_height;
    }
  }
  constexpr void set_liquid_density(R density) {
    pointmass::detail::assign_non_negative("Buoyancy::set_liquid_density", "liquid_density",
                                           density, density_);
  }
  constexpr void set_gravity(R g) {
    pointmass::detail::assign_non_negative("Buoyancy::set_gravity", "g", g, g_);
  }

  /// The submerged fraction s = ((h - y) / D + 1) / 2, clamped to [0, 1], at height y. (Not
  /// (h + D - y) / (2 D): 2 D overflows for D beyond half the largest R, and s would be 0.)
  constexpr R submerged_fraction(R y) const noexcept {
    const R s = ((water_height_ - y) / max_depth_ + R(1)) / R(2);
    return s > R(1) ? R(1) : (s > R(0) ? s : R(0));
  }
  constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>&, R, R) const noexcept {
    return {R(0), lift() * submerged_fraction(p.y), R(0)};
  }
  /// rho V g, the force when fully submerged. Formed left to right; where that leaves the
  /// range (rho V overflowing, even with g = 0, which gave NaN), as the largest times the
  /// smallest, then the third: each partial product is then within the range whenever the
  /// whole is.
  constexpr R lift() const noexcept {
    const R usual = density_ * volume_ * g_;
    if (real_isfinite(usual)) return usual;
    R a = density_;
    R b = volume_;
    R c = g_;
    const auto order = [](R& larger, R& smaller) {
      if (larger < smaller) {
        const R t = larger;
        larger = smaller;
        smaller = t;
      }
    };
    order(a, b);
    order(b, c);
    order(a, b);  // a >= b >= c >= 0
    return a * c * b;
  }

 private:
  R max_depth_ = R(1);
  R volume_ = R(0);
  R water_height_ = R(0);
  R density_ = R(1000);
  R g_ = R(9.807);
};

// --- springs between the bodies of a batch --------------------------------------------------

/// A spring between bodies `first` and `second` of a batch.
struct Link {
  std::size_t first;
  std::size_t second;
};

/// Springs (or bungees) of one stiffness and rest length between pairs of bodies of a batch:
/// each link adds the force to `first` and its opposite to `second` (Newton's third law).
template <Real R, bool IsBungee = false>
class BasicLinkSprings : public SpringParameters<R, IsBungee> {
 public:
  using SpringParameters<R, IsBungee>::SpringParameters;
};
template <Real R>
using LinkSprings = BasicLinkSprings<R, false>;
template <Real R>
using LinkBungees = BasicLinkSprings<R, true>;

/// Adds every link's spring force to its two bodies. An adapter's spans (SpanBodies,
/// SoaBodies: valid) and every index are checked (always) before any force is added, and with
/// POINTMASS_CHECKS on every force too: a span shorter than size(), a bad link or a force
/// beyond the range of the number type is reported and no body gets a force.
template <Bodies B, bool IsBungee>
constexpr void apply_links(const BasicLinkSprings<typename B::real, IsBungee>& springs,
                           std::span<const Link> links, B& bodies) {
  if (!detail::valid_bodies(bodies, "forces::apply_links")) return;
  const std::size_t n = bodies.size();
  for (const Link& link : links) {
    if (!pointmass::detail::check_index("forces::apply_links", "link.first", link.first, n) ||
        !pointmass::detail::check_index("forces::apply_links", "link.second", link.second, n)) {
      return;
    }
  }
  const auto force_of = [&](const Link& link) {
    return springs.force_between(bodies.position(link.first), bodies.position(link.second));
  };
#if POINTMASS_CHECKS
  for (const Link& link : links) {
    if (!pointmass::detail::check_force("forces::apply_links", force_of(link))) return;
  }
#endif
  for (const Link& link : links) {
    const auto f = force_of(link);
    bodies.add_force(link.first, f);
    bodies.add_force(link.second, -f);
  }
}
/// A spring between two single bodies: the force on `first`, its opposite on `second` (where
/// Spring needs a registration at each end); a force beyond R's range is reported, none added.
template <Real R, bool IsBungee, PlainBody<R> First, PlainBody<R> Second>
constexpr void apply_link(const BasicLinkSprings<R, IsBungee>& spring, First& first,
                          Second& second) {
  const auto f = spring.force_between(first.position(), second.position());
  if (!pointmass::detail::check_force("forces::apply_link", f)) return;
  first.add_force(f);
  second.add_force(-f);
}

/// A temporary adapter or view (`forces::relative_to(chain, anchor)`): the forces land in the
/// storage it refers to.
// clang-format off
template <class B, bool IsBungee>
  requires(BodyView<B> && !std::is_lvalue_reference_v<B> && Bodies<std::remove_cvref_t<B>>)
constexpr void apply_links(
    const BasicLinkSprings<typename std::remove_cvref_t<B>::real, IsBungee>& springs,
    std::span<const Link> links, B&& bodies) {
  // clang-format on
  apply_links(springs, links, bodies);
}

}  // namespace pointmass::forces
POINTMASS_DETAIL_UNFUSED_END
