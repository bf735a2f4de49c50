// pointmass/forces.hpp — force generators and the registry that applies them each step.
//
// A force generator computes a force from a body's state and adds it to the body's
// accumulator before the step integrates it. The generators (all in namespace
// pointmass::forces, each over one Real R):
//
//   generator            force on a body at p with velocity v, mass m       parameters
//   Gravity              m g  (nothing on an immovable body)                g (a vector)
//   Drag                 -v (k1 + k2 |v|), i.e. k1 |v| + k2 |v|^2 against v   k1, k2 >= 0
//   Spring<B>            -k (|d| - L) d/|d|, d = p - other.p                stiffness k >= 0, rest length L >= 0
//   AnchoredSpring       the same with d = p - anchor
//   Bungee<B>            the spring's force when |d| > L, nothing when |d| <= L (never pushes)
//   AnchoredBungee       the same with d = p - anchor
//   Buoyancy             +Y: rho V g s, s = clamp((h + D - y) / (2 D), 0, 1), the submerged
//                        fraction of a body of half-height D at height y, water surface at h
//   StiffSpring          a damped spring to an anchor, solved in closed form: the force that
//                        moves the body to the exact oscillator's position over the step
//
// Where the reference engine differs (its users' bug reports; each is pinned by a test):
//   * its spring takes |(|d| - L)|, so a compressed spring pulls instead of pushing;
//   * its bungee multiplies by -k (L - |d|), so a stretched bungee pushes the ends apart;
//   * its buoyancy omits g (it adds a mass, rho V, as a force), and when partly submerged
//     computes (y - D - h) / 2 * D, which is negative (pulls the body down) and has the wrong
//     scale (operator precedence: / 2 * D);
//   * its "fake" stiff spring takes sqrt(4 k - c^2), NaN when over-damped, and adds nothing
//     when critically damped;
//   * a generator that multiplies by the mass gives an immovable body (infinite mass) an
//     infinite force. Here gravity and the stiff spring skip immovable bodies, and no
//     generator produces NaN or infinity from finite, in-range input (a zero-length spring or
//     a body at rest under drag gets no force).
//
// Parameters are validated by the setters (and the constructors, which call them) through the
// contract mechanism of config.hpp: a negative stiffness, rest length or drag coefficient, a
// zero or negative volume or depth, a NaN anywhere is reported with the argument's name and
// value. The default handler throws, so construction fails; if an installed handler returns,
// the rejected value is not stored and the member keeps its previous (for a constructor, its
// harmless default: stiffness 0, volume 0, ... which add no force).
//
// Use with a Particle (any damping and position policy):
//   forces::AnchoredSpring<double> spring({0, 0, 0}, 40.0, 0.5);
//   spring.update_force(particle, dt);   // adds the force to the particle's accumulator
//   particle.integrate(dt);
//
// Use with a batch (any storage): `forces::apply(generator, bodies, dt)` adds each body's
// force for a `bodies` that satisfies the `Bodies` concept (size(), position(i), velocity(i),
// inverse_mass(i), add_force(i, f)). `SpanBodies` adapts arrays of Vector3s and `SoaBodies`
// structure-of-arrays storage (x, y, z arrays); springs between bodies of a batch are
// `forces::apply_links(generator, links, bodies)` over index pairs, adding equal and opposite
// forces. Every single-body generator has `force(p, v, inverse_mass, t)`, the pure function
// both paths call, so a batch and a particle get the same bits.
//
// Registries: `ForceRegistry<Particle, G...>` holds (particle, generator) pairs like the
// reference engine's registry, and `update_forces(t)` applies them. Generators of the listed
// types G... are stored in one vector per type and called directly (no virtual or indirect
// call); any other generator type (anything with `update_force(Particle&, real)`) is stored
// type-erased and called through one function pointer. add, remove and clear all work.
// Generators and particles are not owned: they must outlive their registration.
#pragma once

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "config.hpp"
#include "particle.hpp"
#include "real.hpp"
#include "vector3.hpp"

namespace pointmass::forces {

// --- what a generator acts on --------------------------------------------------------------

/// A particle over plain R numbers (Particle<R, D, P> for any policies D, P).
template <class B, class R>
concept PlainBody = requires(B& b, const B& cb, const Vector3<R>& f) {
  { cb.position() } -> std::same_as<Vector3<R>>;
  { cb.velocity() } -> std::same_as<Vector3<R>>;
  { cb.inverse_mass() } -> std::same_as<R>;
  { cb.has_finite_mass() } -> std::same_as<bool>;
  b.add_force(f);
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

namespace detail {

template <Real R>
constexpr bool check_non_negative(const char* function, const char* argument, R value) {
  if (real_isfinite(value) && value >= R(0)) return true;
  pointmass::detail::report_scalar(function, argument, ">= 0 and finite", value);
  return false;
}

template <Real R>
constexpr bool check_positive(const char* function, const char* argument, R value) {
  if (real_isfinite(value) && value > R(0)) return true;
  pointmass::detail::report_scalar(function, argument, "> 0 and finite", value);
  return false;
}

template <Real R>
constexpr bool check_finite(const char* function, const char* argument, const Vector3<R>& v) {
  if (is_finite(v)) return true;
  pointmass::detail::report_vector(function, argument, "finite", v);
  return false;
}

/// The force of a spring of stiffness k and rest length L on the end at d from the other
/// end: -k (|d| - L) d / |d|. Zero for d = 0 (no direction). With `slack_only_pulls` (a
/// bungee), zero while |d| <= L.
template <Real R>
constexpr Vector3<R> spring_force(const Vector3<R>& d, R k, R L, bool bungee) noexcept {
  const R length = magnitude(d);
  if (!(length > R(0))) return {};
  const R extension = length - L;  // signed: negative when compressed
  if (bungee && !(extension > R(0))) return {};
  return d * (-k * extension / length);
}

}  // namespace detail

/// Gravity as a force, f = m g, for use through a registry (a particle's own acceleration is
/// the cheaper way to give every particle the same g). An immovable body gets nothing (its
/// mass is infinite: m g would be infinite or NaN).
template <Real R>
class Gravity {
 public:
  using real = R;
  constexpr Gravity() noexcept = default;
  constexpr explicit Gravity(const Vector3<R>& g) { set_gravity(g); }

  constexpr Vector3<R> gravity() const noexcept { return g_; }
  constexpr void set_gravity(const Vector3<R>& g) {
    if (detail::check_finite("Gravity::set_gravity", "gravity", g)) g_ = g;
  }

  constexpr Vector3<R> force(const Vector3<R>&, const Vector3<R>&, R inverse_mass,
                             R) const noexcept {
    if (!(inverse_mass > R(0))) return {};
    return g_ / inverse_mass;
  }
  template <PlainBody<R> B>
  constexpr void update_force(B& body, R duration) const {
    if (!body.has_finite_mass()) return;
    body.add_force(force(body.position(), body.velocity(), body.inverse_mass(), duration));
  }

 private:
  Vector3<R> g_{R(0), R(-9.807), R(0)};
};

/// Drag against the velocity: magnitude k1 |v| + k2 |v|^2, so f = -v (k1 + k2 |v|). No force
/// at rest (no direction, no NaN).
template <Real R>
class Drag {
 public:
  using real = R;
  constexpr Drag() noexcept = default;
  constexpr Drag(R k1, R k2) {
    set_k1(k1);
    set_k2(k2);
  }

  constexpr R k1() const noexcept { return k1_; }
  constexpr R k2() const noexcept { return k2_; }
  constexpr void set_k1(R k1) {
    if (detail::check_non_negative("Drag::set_k1", "k1", k1)) k1_ = k1;
  }
  constexpr void set_k2(R k2) {
    if (detail::check_non_negative("Drag::set_k2", "k2", k2)) k2_ = k2;
  }

  constexpr Vector3<R> force(const Vector3<R>&, const Vector3<R>& v, R, R) const noexcept {
    const R speed = magnitude(v);
    return v * -(k1_ + k2_ * speed);
  }
  template <PlainBody<R> B>
  constexpr void update_force(B& body, R duration) const {
    body.add_force(force(body.position(), body.velocity(), body.inverse_mass(), duration));
  }

 private:
  R k1_ = R(0);
  R k2_ = R(0);
};

/// What springs and bungees share: stiffness k >= 0 and rest length L >= 0, validated.
template <Real R>
class SpringParameters {
 public:
  using real = R;
  constexpr SpringParameters() noexcept = default;
  constexpr SpringParameters(R stiffness, R rest_length) {
    set_stiffness(stiffness);
    set_rest_length(rest_length);
  }
  constexpr R stiffness() const noexcept { return k_; }
  constexpr R rest_length() const noexcept { return rest_length_; }
  constexpr void set_stiffness(R stiffness) {
    if (detail::check_non_negative("set_stiffness", "stiffness", stiffness)) k_ = stiffness;
  }
  constexpr void set_rest_length(R rest_length) {
    if (detail::check_non_negative("set_rest_length", "rest_length", rest_length)) {
      rest_length_ = rest_length;
    }
  }

 protected:
  R k_ = R(0);
  R rest_length_ = R(0);
};

/// A spring (or with Bungee = true, a bungee) from a body to a fixed anchor point.
template <Real R, bool IsBungee = false>
class BasicAnchoredSpring : public SpringParameters<R> {
 public:
  constexpr BasicAnchoredSpring() noexcept = default;
  constexpr BasicAnchoredSpring(const Vector3<R>& anchor, R stiffness, R rest_length)
      : SpringParameters<R>(stiffness, rest_length) {
    set_anchor(anchor);
  }
  constexpr Vector3<R> anchor() const noexcept { return anchor_; }
  constexpr void set_anchor(const Vector3<R>& anchor) {
    if (detail::check_finite("set_anchor", "anchor", anchor)) anchor_ = anchor;
  }

  constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>&, R, R) const noexcept {
    return detail::spring_force(p - anchor_, this->k_, this->rest_length_, IsBungee);
  }
  template <PlainBody<R> B>
  constexpr void update_force(B& body, R duration) const {
    body.add_force(force(body.position(), body.velocity(), body.inverse_mass(), duration));
  }

 private:
  Vector3<R> anchor_{};
};

template <Real R>
using AnchoredSpring = BasicAnchoredSpring<R, false>;
template <Real R>
using AnchoredBungee = BasicAnchoredSpring<R, true>;

/// A spring (or bungee) between two bodies, as the reference engine has it: registered with
/// one body, it pulls that body towards `other`; register a second one, with the ends swapped,
/// for the other body. In a batch, `apply_links` does both ends at once.
template <class Body, bool IsBungee = false>
class BasicSpring : public SpringParameters<typename Body::real> {
 public:
  using real = typename Body::real;
  constexpr BasicSpring() noexcept = default;
  constexpr BasicSpring(const Body& other, real stiffness, real rest_length)
      : SpringParameters<real>(stiffness, rest_length), other_(&other) {}

  constexpr const Body* other() const noexcept { return other_; }
  constexpr void set_other(const Body& other) noexcept { other_ = &other; }

  /// The force on a body at p from the other end at `other_position`.
  constexpr Vector3<real> force_between(const Vector3<real>& p,
                                        const Vector3<real>& other_position) const noexcept {
    return detail::spring_force(p - other_position, this->k_, this->rest_length_, IsBungee);
  }
  template <PlainBody<real> B>
  constexpr void update_force(B& body, real) const {
    if (other_ == nullptr) return;
    body.add_force(force_between(body.position(), other_->position()));
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
/// displaced liquid). Defaults: water (1000 kg/m^3), g = 9.807 m/s^2.
template <Real R>
class Buoyancy {
 public:
  using real = R;
  constexpr Buoyancy() noexcept = default;
  constexpr Buoyancy(R max_depth, R volume, R water_height, R liquid_density = R(1000),
                     R g = R(9.807)) {
    set_max_depth(max_depth);
    set_volume(volume);
    set_water_height(water_height);
    set_liquid_density(liquid_density);
    set_gravity(g);
  }

  constexpr R max_depth() const noexcept { return max_depth_; }
  constexpr R volume() const noexcept { return volume_; }
  constexpr R water_height() const noexcept { return water_height_; }
  constexpr R liquid_density() const noexcept { return density_; }
  constexpr R gravity() const noexcept { return g_; }
  constexpr void set_max_depth(R max_depth) {
    if (detail::check_positive("Buoyancy::set_max_depth", "max_depth", max_depth)) {
      max_depth_ = max_depth;
    }
  }
  constexpr void set_volume(R volume) {
    if (detail::check_positive("Buoyancy::set_volume", "volume", volume)) volume_ = volume;
  }
  constexpr void set_water_height(R water_height) {
    if (real_isfinite(water_height)) {
      water_height_ = water_height;
    } else {
      pointmass::detail::report_scalar("Buoyancy::set_water_height", "water_height", "finite",
                                       water_height);
    }
  }
  constexpr void set_liquid_density(R density) {
    if (detail::check_non_negative("Buoyancy::set_liquid_density", "liquid_density", density)) {
      density_ = density;
    }
  }
  constexpr void set_gravity(R g) {
    if (detail::check_non_negative("Buoyancy::set_gravity", "g", g)) g_ = g;
  }

  /// The submerged fraction s in [0, 1] at height y.
  constexpr R submerged_fraction(R y) const noexcept {
    const R s = (water_height_ + max_depth_ - y) / (R(2) * max_depth_);
    return s > R(1) ? R(1) : (s > R(0) ? s : R(0));
  }
  constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>&, R, R) const noexcept {
    return {R(0), density_ * volume_ * g_ * submerged_fraction(p.y), R(0)};
  }
  template <PlainBody<R> B>
  constexpr void update_force(B& body, R duration) const {
    body.add_force(force(body.position(), body.velocity(), body.inverse_mass(), duration));
  }

 private:
  R max_depth_ = R(1);
  R volume_ = R(0);
  R water_height_ = R(0);
  R density_ = R(1000);
  R g_ = R(9.807);
};

// --- the damped harmonic oscillator in closed form -----------------------------------------

/// A position and velocity (relative to the oscillator's rest point).
template <Real R>
struct OscillatorState {
  Vector3<R> position;
  Vector3<R> velocity;
};

/// The exact solution after time t >= 0 of x'' = -w0^2 x - 2 gamma x' from (x0, v0), with
/// w0^2 = k / m >= 0 and gamma = c / (2 m) >= 0. Writing Omega^2 = w0^2 - gamma^2 and
/// y = e^(gamma t) x (so y'' = -Omega^2 y):
///   x(t) = e^(-gamma t) [ x0 C + (v0 + gamma x0) S ]
///   v(t) = e^(-gamma t) [ v0 C - (w0^2 x0 + gamma v0) S ]
/// with C = cos(Omega t), S = sin(Omega t) / Omega        (under-damped, Omega^2 > 0),
///      C = 1,            S = t                           (critically damped, Omega = 0),
///      C = cosh(lambda t), S = sinh(lambda t) / lambda   (over-damped, lambda^2 = -Omega^2).
/// The factors e^(-gamma t) C and e^(-gamma t) S are computed together so that nothing
/// overflows for large t: e^(-gamma t) cosh(lambda t) = (e^(-(gamma - lambda) t) +
/// e^(-(gamma + lambda) t)) / 2 with gamma - lambda = w0^2 / (gamma + lambda) (no
/// cancellation), and sinh(lambda t) / lambda through expm1 when lambda t is small. No NaN for
/// any finite, in-range input and any t >= 0.
template <Real R>
constexpr OscillatorState<R> damped_oscillator(R w0_squared, R gamma, const Vector3<R>& x0,
                                               const Vector3<R>& v0, R t) noexcept {
  const R omega_squared = w0_squared - gamma * gamma;
  R ec;  // e^(-gamma t) C
  R es;  // e^(-gamma t) S
  if (omega_squared > R(0)) {
    const R omega = real_sqrt(omega_squared);
    const R decay = real_exp(-gamma * t);
    ec = decay * real_cos(omega * t);
    es = decay * real_sin(omega * t) / omega;
  } else if (omega_squared < R(0)) {
    const R lambda = real_sqrt(-omega_squared);
    const R slow = w0_squared / (gamma + lambda);  // gamma - lambda, without cancellation
    const R fast = gamma + lambda;
    const R e_slow = real_exp(-slow * t);
    const R e_fast = real_exp(-fast * t);
    ec = (e_slow + e_fast) / R(2);
    if (lambda * t < R(0.5)) {
      // sinh(lambda t) / lambda = e^(lambda t) (1 - e^(-2 lambda t)) / (2 lambda)
      es = -e_slow * real_expm1(R(-2) * lambda * t) / (R(2) * lambda);
    } else {
      es = (e_slow - e_fast) / (R(2) * lambda);
    }
  } else {
    const R decay = real_exp(-gamma * t);
    ec = decay;
    es = decay * t;
  }
  return {x0 * ec + (v0 + x0 * gamma) * es, v0 * ec - (x0 * w0_squared + v0 * gamma) * es};
}

/// A stiff damped spring from a body to a fixed anchor (rest length 0), solved in closed form
/// instead of integrated: for a body of mass m, x = p - anchor obeys m x'' = -k x - c x'.
/// For a step of duration t the generator takes the exact position x(t) from
/// `damped_oscillator` and adds the force that brings the body there:
///   f = m [ (x(t) - x0) / t - v0 ] / t,
/// so that a body with position::SemiImplicit and damping::None, feeling only this spring,
/// ends every step exactly where the closed form puts it (p1 = p0 + v1 t with v1 the mean
/// velocity over the step, (x(t) - x0) / t). This is what the reference engine's "fake"
/// spring intends, without its NaN (over-damped) and its silence (critically damped).
/// Stability, per step of angular frequency w0 = sqrt(k/m) (measured by the spectral radius
/// of the step's 2x2 map, see docs/forces.md): stable for w0 t <= pi whatever the damping, and
/// for every step (scanned to w0 t = 100) once the damping ratio c / (2 sqrt(k m)) >= 0.05;
/// an undamped stiff spring has windows beyond w0 t = pi where it grows (by at most 13% a
/// step). Integrating k x explicitly instead (AnchoredSpring, symplectic Euler) is stable only
/// for w0 t < 2. No NaN, nothing on an immovable body, nothing for t = 0.
template <Real R>
class StiffSpring {
 public:
  using real = R;
  constexpr StiffSpring() noexcept = default;
  constexpr StiffSpring(const Vector3<R>& anchor, R stiffness, R damping) {
    set_anchor(anchor);
    set_stiffness(stiffness);
    set_damping(damping);
  }

  constexpr Vector3<R> anchor() const noexcept { return anchor_; }
  constexpr R stiffness() const noexcept { return k_; }
  constexpr R damping() const noexcept { return c_; }
  constexpr void set_anchor(const Vector3<R>& anchor) {
    if (detail::check_finite("StiffSpring::set_anchor", "anchor", anchor)) anchor_ = anchor;
  }
  constexpr void set_stiffness(R stiffness) {
    if (detail::check_non_negative("StiffSpring::set_stiffness", "stiffness", stiffness)) {
      k_ = stiffness;
    }
  }
  /// The damping coefficient c >= 0 (force -c v, in N s/m).
  constexpr void set_damping(R damping) {
    if (detail::check_non_negative("StiffSpring::set_damping", "damping", damping)) c_ = damping;
  }

  /// The exact state, relative to the world, after `duration` of this spring alone.
  constexpr OscillatorState<R> exact_state(const Vector3<R>& p, const Vector3<R>& v,
                                           R inverse_mass, R duration) const noexcept {
    OscillatorState<R> s = damped_oscillator(k_ * inverse_mass, c_ * inverse_mass / R(2),
                                             p - anchor_, v, duration);
    s.position += anchor_;
    return s;
  }

  constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>& v, R inverse_mass,
                             R duration) const noexcept {
    if (!(inverse_mass > R(0)) || !(duration > R(0))) return {};
    const OscillatorState<R> s = exact_state(p, v, inverse_mass, duration);
    const Vector3<R> mean_velocity = (s.position - p) / duration;
    return (mean_velocity - v) / (inverse_mass * duration);
  }
  template <PlainBody<R> B>
  constexpr void update_force(B& body, R duration) const {
    if (!body.has_finite_mass()) return;
    body.add_force(force(body.position(), body.velocity(), body.inverse_mass(), duration));
  }

 private:
  Vector3<R> anchor_{};
  R k_ = R(0);
  R c_ = R(0);
};

// --- applying generators to a batch --------------------------------------------------------

/// A generator that computes a body's force from its own state alone.
template <class G, class R>
concept FieldGenerator = requires(const G& g, const Vector3<R>& p, R x) {
  { g.force(p, p, x, x) } -> std::same_as<Vector3<R>>;
};

/// Adds `generator`'s force to every body of the batch.
template <Bodies B, FieldGenerator<typename B::real> G>
constexpr void apply(const G& generator, B& bodies, typename B::real duration) {
  const std::size_t n = bodies.size();
  for (std::size_t i = 0; i < n; ++i) {
    bodies.add_force(i, generator.force(bodies.position(i), bodies.velocity(i),
                                        bodies.inverse_mass(i), duration));
  }
}

/// A spring between bodies `first` and `second` of a batch.
struct Link {
  std::size_t first;
  std::size_t second;
};

/// Springs (or bungees) of one stiffness and rest length between pairs of bodies of a batch:
/// each link adds the force to `first` and its opposite to `second` (Newton's third law).
template <Real R, bool IsBungee = false>
class BasicLinkSprings : public SpringParameters<R> {
 public:
  using SpringParameters<R>::SpringParameters;
  constexpr Vector3<R> force_between(const Vector3<R>& p,
                                     const Vector3<R>& other_position) const noexcept {
    return detail::spring_force(p - other_position, this->k_, this->rest_length_, IsBungee);
  }
};
template <Real R>
using LinkSprings = BasicLinkSprings<R, false>;
template <Real R>
using LinkBungees = BasicLinkSprings<R, true>;

template <Bodies B, bool IsBungee>
constexpr void apply_links(const BasicLinkSprings<typename B::real, IsBungee>& springs,
                           std::span<const Link> links, B& bodies) {
  for (const Link& link : links) {
    const auto f = springs.force_between(bodies.position(link.first),
                                         bodies.position(link.second));
    bodies.add_force(link.first, f);
    bodies.add_force(link.second, -f);
  }
}

// --- the registry ---------------------------------------------------------------------------

/// What a registry can hold for particles of type P.
template <class G, class P>
concept GeneratorFor = requires(G& g, P& p, typename P::real t) { g.update_force(p, t); };

template <class P, class... Known>
  requires(GeneratorFor<Known, P> && ...)
class ForceRegistry {
 public:
  using particle_type = P;
  using real = typename P::real;

  /// Registers `generator` to act on `particle`. Both must outlive the registration.
  template <GeneratorFor<P> G>
  void add(P& particle, G& generator) {
    if constexpr (is_known<G>) {
      std::get<std::vector<Entry<G>>>(known_).push_back({&particle, &generator});
    } else {
      erased_.push_back({&particle, static_cast<void*>(&generator), &call<G>});
    }
  }

  /// Removes the registration of `generator` on `particle`; returns whether there was one.
  template <GeneratorFor<P> G>
  bool remove(const P& particle, const G& generator) {
    if constexpr (is_known<G>) {
      auto& entries = std::get<std::vector<Entry<G>>>(known_);
      return remove_first(entries, [&](const Entry<G>& e) {
        return e.particle == &particle && e.generator == &generator;
      });
    } else {
      return remove_first(erased_, [&](const ErasedEntry& e) {
        return e.particle == &particle &&
               e.generator == static_cast<const void*>(&generator) && e.update == &call<G>;
      });
    }
  }

  /// Removes every registration.
  void clear() noexcept {
    std::apply([](auto&... entries) { (entries.clear(), ...); }, known_);
    erased_.clear();
  }

  std::size_t size() const noexcept {
    return std::apply([](const auto&... entries) { return (entries.size() + ... + 0u); },
                      known_) +
           erased_.size();
  }
  bool empty() const noexcept { return size() == 0; }

  /// Asks every registered generator to add its force to its particle for a step of
  /// `duration`: the known types first (in the order of Known...), then the others, each in
  /// the order they were added.
  void update_forces(real duration) {
    std::apply(
        [duration](auto&... entries) {
          (update_all(entries, duration), ...);
        },
        known_);
    for (const ErasedEntry& e : erased_) e.update(e.generator, *e.particle, duration);
  }

 private:
  template <class G>
  static constexpr bool is_known = (std::is_same_v<G, Known> || ...);

  template <class G>
  struct Entry {
    P* particle;
    G* generator;
  };
  struct ErasedEntry {
    P* particle;
    void* generator;
    void (*update)(void*, P&, real);
  };

  template <class G>
  static void call(void* generator, P& particle, real duration) {
    static_cast<G*>(generator)->update_force(particle, duration);
  }
  template <class G>
  static void update_all(const std::vector<Entry<G>>& entries, real duration) {
    for (const Entry<G>& e : entries) e.generator->update_force(*e.particle, duration);
  }
  template <class Vec, class Pred>
  static bool remove_first(Vec& entries, Pred pred) {
    const auto it = std::find_if(entries.begin(), entries.end(), pred);
    if (it == entries.end()) return false;
    entries.erase(it);
    return true;
  }

  std::tuple<std::vector<Entry<Known>>...> known_;
  std::vector<ErasedEntry> erased_;
};

}  // namespace pointmass::forces
