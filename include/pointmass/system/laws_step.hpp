// SPDX-License-Identifier: BSL-1.0
// pointmass/system/laws_step.hpp — a ParticleSystem's step with force laws fused into it
// (features::ForceAccumulator).
//
//   system.step(dt, forces::laws(gravity, drag, spring));               // one step
//   system.step(dt, forces::laws(drag, spring), Substeps{8});           // 8 of dt / 8
//
// SystemLawsStep<Base> is a facet of ParticleSystem (see system/lifetime.hpp): members and no
// data, which ParticleSystem re-exports.
//
// Owns: step(duration, laws), with Substeps and an expiry callback.
// Must not include: particle_system.hpp, detail/system_state.hpp or another facet (it uses
// only Base's walk() and expire()).
#pragma once

#include <cstddef>
#include <type_traits>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../forces/laws.hpp"
#include "../real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemLawsStep : public Base {
 protected:
  using R = typename Base::R;
  using Layout = typename Base::Layout;

 public:
  /// As step(duration), with each law's force on each particle added after its accumulated
  /// force, in the order given, chunk by chunk just before the chunk's step (no pass over
  /// memory of its own: detail/law_pass.hpp): the bits of forces::apply(law, system,
  /// duration) for each law in turn, then step(duration). A law's force beyond the range of
  /// the number type (docs/forces.md, Ranges) is not added to that particle, and the law is
  /// reported, once, after the step (with POINTMASS_CHECKS on; else added unchecked).
  /// With Substeps{k}: k steps of duration / k in one pass over the particles, each
  /// particle's bits those of k calls of step(duration / k, laws). The accumulated forces
  /// act in the first; a particle whose lifetime ends at a sub-step takes no more; expiry
  /// (and on_expire, in the particles' order) follows the pass; the previous position
  /// (features::Interpolation) is the one before it. k = 0 is a contract violation.
  template <class... G>
  void step(R duration, const forces::Laws<G...>& laws, Substeps substeps = {}) {
    typename Base::NoCallback none;
    step_with(duration, laws, substeps, none);
  }
  // clang-format off
  template <class... G, class OnExpire>
    requires(Layout::has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  void step(R duration, const forces::Laws<G...>& laws, OnExpire&& on_expire) {
    step_with(duration, laws, Substeps{}, on_expire);
  }
  template <class... G, class OnExpire>
    requires(Layout::has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  void step(R duration, const forces::Laws<G...>& laws, Substeps substeps,
            OnExpire&& on_expire) {
    // clang-format on
    step_with(duration, laws, substeps, on_expire);
  }

 private:
  template <class... G, class OnExpire>
  void step_with(R duration, const forces::Laws<G...>& laws, Substeps substeps,
                 OnExpire& on_expire) {
    constexpr bool plain =
        std::is_same_v<typename Layout::position_element, R> && !Layout::compensated_positions;
    constexpr bool laws_valid =
        forces::detail::all_laws<R>(static_cast<const forces::Laws<G...>*>(nullptr));
    static_assert(Layout::has_forces,
                  "ParticleSystem::step(duration, laws): laws need each particle's mass; "
                  "add features::ForceAccumulator to the system's features");
    static_assert(plain,
                  "ParticleSystem::step(duration, laws): this system stores its positions wider "
                  "than its arithmetic; apply the forces with forces::apply(law, "
                  "forces::relative_to(system, origin), t) before step(t)");
    static_assert(laws_valid,
                  "ParticleSystem::step(duration, laws): every law must be a force of one "
                  "particle's own state, force(p, v, inverse_mass, t) returning Vector3<real> "
                  "(a spring between particles goes through the "
                  "accumulator: apply_links before the step)");
    if constexpr (Layout::has_forces && plain && laws_valid && Base::Kernel::steppable) {
      if (!check_at_least("step", "substeps", substeps.count, std::size_t{1})) return;
      unsigned beyond = 0;
      if (this->walk(duration, laws, substeps.count, &beyond)) this->expire(on_expire);
      if (beyond != 0) forces::report_beyond("step", beyond);
    }
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
