// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/laws.hpp — force laws evaluated inside the step.
//
//   system.step(dt, forces::laws(drag, spring));           // the forces fused into the step
//   system.step(dt, forces::laws(drag, spring), Substeps{8});  // 8 steps of dt / 8, one pass
//   forces::integrate(particle, dt, forces::laws(drag));   // the same for one Particle
//
// Owns: the ForceLaw concept (a generator whose force depends on one body's own state and on
// values shared by all: `force(p, v, inverse_mass, t)`, the shape of FieldGenerator), Laws and
// laws(...), law(callable) for a user's law written as a lambda, Substeps, and integrate for
// one body. A law's force is added as update_force then integrate add it, in the order the
// laws are given, after the body's accumulated force: the same bits.
// Must not include: particle.hpp, particle_system.hpp (the system includes this header).
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "fused.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// k steps of t / k in one pass over the particles (ParticleSystem::step(t, laws, Substeps{k})).
struct Substeps {
  std::size_t count = 1;
};

namespace forces {

/// A force that depends on one body's position, velocity and inverse mass, the step's
/// duration, and values the law holds: `force(p, v, inverse_mass, t)` returning Vector3<R>.
template <class G, class R>
concept ForceLaw = Real<R> && std::is_nothrow_copy_constructible_v<G> &&
    requires(const G& g, const Vector3<R>& p, R x) {
  { g.force(p, p, x, x) } -> std::same_as<Vector3<R>>;
};

/// A user's law written as a callable `f(p, v, inverse_mass, t) -> Vector3<R>`: law(f) is a
/// ForceLaw, for laws(...) as for apply and update_force.
template <class F>
class Law {
 public:
  constexpr explicit Law(const F& f) noexcept(std::is_nothrow_copy_constructible_v<F>) : f_(f) {}
  template <Real R>
  [[nodiscard]] constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>& v, R inverse_mass,
                                           R t) const noexcept {
    return f_(p, v, inverse_mass, t);
  }

 private:
  F f_;
};
template <class F>
[[nodiscard]] constexpr Law<F> law(const F& f) noexcept(std::is_nothrow_copy_constructible_v<F>) {
  return Law<F>(f);
}

/// The laws a step evaluates for each particle, held by value (copied when made: a law
/// changed afterwards is not seen).
template <class... G>
class Laws {
 public:
  static_assert(sizeof...(G) <= 32, "forces::laws: at most 32 laws in one step");
  constexpr explicit Laws(const G&... laws) noexcept : laws_(laws...) {}

  /// The laws' fused forms, for a step's law pass (forces/fused.hpp).
  [[nodiscard]] constexpr auto fused() const noexcept {
    return std::apply([](const G&... law) { return std::tuple{detail::fused_form(law)...}; },
                      laws_);
  }

  /// Adds each law's force() at (p, v, inverse_mass, t) to (fx, fy, fz), in order; returns the
  /// laws whose force was beyond the range of R, one bit each (law 0 the lowest): with
  /// POINTMASS_CHECKS on those are not added, as update_force and apply do not add them.
  /// (forces::integrate's sum, and the law pass's where a fused form was unsure.)

  template <Real R>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr unsigned add(const Vector3<R>& p,
                                                                     const Vector3<R>& v,
                                                                     R inverse_mass, R t, R& fx,
                                                                     R& fy, R& fz) const noexcept {
    return add_each(p, v, inverse_mass, t, fx, fy, fz, std::index_sequence_for<G...>{});
  }

 private:
  template <Real R, std::size_t... I>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr unsigned add_each(
      const Vector3<R>& p, const Vector3<R>& v, R w, R t, R& fx, R& fy, R& fz,
      std::index_sequence<I...>) const noexcept {
    unsigned beyond = 0;
    ((beyond |= add_one<I>(p, v, w, t, fx, fy, fz)), ...);
    return beyond;
  }
  template <std::size_t I, Real R>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr unsigned add_one(const Vector3<R>& p,
                                                                         const Vector3<R>& v, R w,
                                                                         R t, R& fx, R& fy,
                                                                         R& fz) const noexcept {
    const Vector3<R> f = std::get<I>(laws_).force(p, v, w, t);
#if POINTMASS_CHECKS
    // is_finite's && would be three branches; the three tests and-ed are one value.
    const bool finite =
        (static_cast<int>(real_isfinite(f.x)) & static_cast<int>(real_isfinite(f.y)) &
         static_cast<int>(real_isfinite(f.z))) != 0;
    fx = finite ? fx + f.x : fx;  // selects, not a branch: kept as it was when not added
    fy = finite ? fy + f.y : fy;
    fz = finite ? fz + f.z : fz;
    return static_cast<unsigned>(!finite) << I;
#else
    fx = fx + f.x;
    fy = fy + f.y;
    fz = fz + f.z;
    return 0;
#endif
  }

  std::tuple<G...> laws_;
};

/// The laws, copied, for a step: `system.step(dt, forces::laws(gravity, drag, spring))`.
template <class... G>
[[nodiscard]] constexpr Laws<G...> laws(const G&... laws) noexcept {
  return Laws<G...>(laws...);
}

namespace detail {
/// Every law of L is a ForceLaw for R; else the one-sentence error (a law that reads another
/// body, such as a Spring, or anything not a law of one body's own state).
template <class R, class... G>
constexpr bool all_laws(const Laws<G...>*) noexcept {
  return (ForceLaw<G, R> && ...);
}
}  // namespace detail

/// Reports each law of `beyond` (Laws::add's bits) through the contract, naming its index.
inline void report_beyond(const char* function, unsigned beyond) {
  for (unsigned i = 0; beyond != 0; ++i, beyond >>= 1u) {
    if ((beyond & 1u) != 0) pointmass::detail::report_law_range(function, i);
  }
}

/// Adds each law's force on `body` for a step of `duration`, then integrates the body: as
/// update_force(law, body, duration) for each law in turn, then body.integrate(duration),
/// bit for bit. A force beyond the range of R is reported and not added.
template <class B, class... G>
constexpr void integrate(B& body, typename B::real duration, const Laws<G...>& laws) {
  using R = typename B::real;
  static_assert(detail::all_laws<R>(static_cast<const Laws<G...>*>(nullptr)),
                "forces::integrate: every law must be a force of one body's own state, "
                "force(p, v, inverse_mass, t) returning Vector3<real> (a spring between two "
                "bodies is applied before the step, with update_force or apply_links)");
#if POINTMASS_CHECKS
  if (!pointmass::detail::check_duration("forces::integrate", duration)) return;
#endif
  Vector3<R> f = body.force_accumulator();
  const unsigned beyond =
      laws.add(body.position(), body.velocity(), body.inverse_mass(), duration, f.x, f.y, f.z);
  body.clear_accumulator();
  body.add_force(f);
  body.integrate(duration);
  if (beyond != 0) report_beyond("forces::integrate", beyond);  // after: the step is whole
}

}  // namespace forces
}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
