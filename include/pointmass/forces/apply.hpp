// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/apply.hpp — how a generator reaches one body or a batch.
//
// Owns: the FieldGenerator concept (a generator whose force depends on one body's own state:
// `force(p, v, inverse_mass, t)`), the free `update_force(generator, body, t)` that adds a
// generator's force to one body, and `apply(generator, bodies, t)` for a batch; for a body or
// batch with wide positions (bodies.hpp: WideBody, WideBodies) and a field generator, the
// one-sentence error that points to relative_to (a generator's own update_force member is
// called on any body it accepts).
// Must not include: particle.hpp, particle_system.hpp, a generator's header (every generator
// reaches bodies through these two functions; none needs them to be declared first).
#pragma once

#include <cstddef>
#include <type_traits>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "bodies.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces {

/// A generator that computes a body's force from its own state alone.
template <class G, class R>
concept FieldGenerator = requires(const G& g, const Vector3<R>& p, R x) {
  { g.force(p, p, x, x) } -> std::same_as<Vector3<R>>;
};

/// A generator with its own `update_force(body, t)` member (a spring between two particles,
/// or a user's generator type).
template <class G, class B>
concept HasUpdateForce = requires(G& g, B& body, typename B::real t) {
  g.update_force(body, t);
};

/// Adds `generator`'s force on `body` for a step of `duration` to the body's accumulator.
/// A field generator's force is computed by its `force(p, v, inverse_mass, t)`, so a particle
/// and a batch (`apply`) get the same bits; a force beyond the range of the number type
/// (docs/forces.md, "Ranges") is reported through the contract and not added. A generator
/// with its own `update_force` member is called through it.
// clang-format off
template <class G, class B>
  requires(HasUpdateForce<G, B> ||
           (PlainBody<B, typename B::real> && FieldGenerator<G, typename B::real>))
constexpr void update_force(G& generator, B& body, typename B::real duration) {
// clang-format on
#if POINTMASS_CHECKS
  if (!pointmass::detail::check_duration("forces::update_force", duration)) return;
#endif
  if constexpr (HasUpdateForce<G, B>) {
    generator.update_force(body, duration);
  } else {
    const auto f = generator.force(body.position(), body.velocity(), body.inverse_mass(), duration);
    if (pointmass::detail::check_force("forces::update_force", f)) body.add_force(f);
  }
}

/// Adds `generator`'s force to every body of the batch. An adapter with a span shorter than
/// its size() (SpanBodies, SoaBodies: valid) is reported, always, and no body gets a force.
/// With POINTMASS_CHECKS on, every force is computed and checked first, so a force beyond the
/// range of the number type is reported and no body gets a force; with checks off, the forces
/// are added unchecked.
template <Bodies B, FieldGenerator<typename B::real> G>
constexpr void apply(const G& generator, B& bodies, typename B::real duration) {
#if POINTMASS_CHECKS
  if (!pointmass::detail::check_duration("forces::apply", duration)) return;
#endif
  if (!detail::valid_bodies(bodies, "forces::apply")) return;
  const std::size_t n = bodies.size();
  const auto force_on = [&](std::size_t i) {
    return generator.force(bodies.position(i), bodies.velocity(i), bodies.inverse_mass(i),
                           duration);
  };
#if POINTMASS_CHECKS
  for (std::size_t i = 0; i < n; ++i) {
    if (!pointmass::detail::check_force("forces::apply", force_on(i))) return;
  }
#endif
  for (std::size_t i = 0; i < n; ++i) bodies.add_force(i, force_on(i));
}

/// A temporary adapter or view (`apply(drag, forces::relative_to(debris, camera), t)`,
/// `apply(drag, SoaBodies<float>{...}, t)`): the forces land in the storage it refers to.
template <class G, BodyView B>
  requires(!std::is_lvalue_reference_v<B>)
constexpr void update_force(G& generator, B&& body,
                            typename std::remove_cvref_t<B>::real duration) {
  update_force(generator, body, duration);
}
template <class G, BodyView B>
  requires(!std::is_lvalue_reference_v<B>)
constexpr void apply(const G& generator, B&& bodies,
                     typename std::remove_cvref_t<B>::real duration) {
  apply(generator, bodies, duration);
}
/// A temporary particle or system would take the force and be gone with it: one sentence.
// clang-format off
template <class G, class B>
  requires(!std::is_lvalue_reference_v<B> && !BodyView<B>)
void update_force(G&, B&&, typename std::remove_cvref_t<B>::real) {
  // clang-format on
  static_assert(sizeof(B) == 0,
                "forces::update_force: this body is a temporary, so the force added to it would "
                "be lost; pass the particle itself (a named object)");
}
// clang-format off
template <class G, class B>
  requires(!std::is_lvalue_reference_v<B> && !BodyView<B>)
void apply(const G&, B&&, typename std::remove_cvref_t<B>::real) {
  // clang-format on
  static_assert(sizeof(B) == 0,
                "forces::apply: these bodies are a temporary, so the forces added to them would "
                "be lost; pass the system itself (a named object)");
}

/// A particle or batch with positions stored wider than its arithmetic (Precision<float,
/// double>, ...) reaches the field generators through relative_to(body, origin) (bodies.hpp);
/// passed as it is, it gets this sentence rather than a list of unmet requirements. A
/// generator with its own update_force member for it is the user's code, which handles the
/// wide position itself: the first update_force above calls it.
template <class G, WideBody B>
  requires(!HasUpdateForce<G, B>)
void update_force(G&, B&, typename B::real) {
  static_assert(sizeof(B) == 0,
                "forces::update_force: this particle stores its position wider than its "
                "arithmetic; pass forces::relative_to(particle, origin), with an origin near the "
                "forces' anchors (docs/large-worlds.md, forces on wide positions)");
}
template <class G, WideBodies B>
void apply(const G&, B&, typename B::real) {
  static_assert(sizeof(B) == 0,
                "forces::apply: these bodies store their positions wider than their arithmetic; "
                "pass forces::relative_to(bodies, origin), with an origin near the forces' "
                "anchors (docs/large-worlds.md, forces on wide positions)");
}

}  // namespace pointmass::forces
POINTMASS_DETAIL_UNFUSED_END
