// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/system_substeps.hpp — sub-steps in one pass over a ParticleSystem's arrays.
//
// Owns: SubstepKernel, the step kernel (system_kernel.hpp) and step_range_substeps: k steps
// of t / k over each chunk of particles while its arrays are in the L1 cache, for
// ParticleSystem::step(t, laws, Substeps{k}).
// Must not include: particle_system.hpp, parallel.hpp (the kernel is below the public API).
#pragma once

#include <cstddef>
#include <limits>

#include "../config.hpp"
#include "../damping.hpp"
#include "../position.hpp"
#include "../real.hpp"
#include "system_kernel.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <Real R, DampingPolicy D, class P, class Layout>
class SubstepKernel : public SystemKernel<R, D, P, Layout> {
  using Base = SystemKernel<R, D, P, Layout>;

 public:
  using typename Base::Arrays;
  using typename Base::StepParameters;
  /// False for a pair of policies ParticleSystem refuses (with one sentence): then the steps
  /// that take laws are not instantiated either, so that the sentence stands alone.
  static constexpr bool steppable = PositionPolicyFor<P, D>;

  /// The particles a pass of sub-steps takes at a time: their arrays stay in the L1 cache
  /// across the sub-steps (256 particles: 10 KiB for float with forces, 20 KiB for double).
  static constexpr std::size_t substep_chunk = Base::backward_chunk;

  /// `substeps` steps of parameters.duration over particles [begin, end) in one pass, chunk
  /// by chunk: each particle's bits are those of `substeps` calls of step_range. With
  /// features::Lifetime, a particle whose lifetime ends at a sub-step takes no more (as the
  /// steps would have removed it); with features::Interpolation, the previous position is the
  /// one before the pass. Same precondition as step_range.
#if defined(__clang__)
#pragma clang diagnostic push
  // As for the kernel's step_range: a configuration that does not vectorise must not warn.
#pragma clang diagnostic ignored "-Wpass-failed"
#endif
  template <class Laws = NoLaws>
  static unsigned step_range_substeps(const Arrays& arrays_in, std::size_t begin, std::size_t end,
                                      const StepParameters& parameters_in, const Laws& laws_in,
                                      std::size_t substeps) noexcept(!POINTMASS_HOST_CHECKS) {
#if POINTMASS_HOST_CHECKS
    if (!check_range("step_range_substeps", begin, end, arrays_in.size)) return 0;
#endif
    const Arrays arrays = arrays_in;  // local copies, as in step_range
    const StepParameters first_step = parameters_in;
    StepParameters later = parameters_in;
    later.refresh = false;  // the first sub-step of each chunk refreshed the retention
    const Laws laws = laws_in;
    const auto fused = fused_of(laws);
    const R t = first_step.duration;
    unsigned beyond = 0;
    for (std::size_t first = begin; first < end; first += substep_chunk) {
      const std::size_t count = end - first < substep_chunk ? end - first : substep_chunk;
      if (may_expire(arrays, first, count, t * static_cast<R>(substeps))) {
        for (std::size_t i = first; i < first + count; ++i) {  // one particle at a time
          if constexpr (Layout::per_particle_retention) {
            if (first_step.refresh) Base::refresh_retention(arrays, i, t);
          }
          beyond |= forces_of(arrays, i, 1, t, fused, laws);
          Base::step_kept(arrays, i, first_step);
          for (std::size_t s = 1; s < substeps && !expired(arrays, i); ++s) {
            beyond |= forces_of(arrays, i, 1, t, fused, laws);
            Base::template step_kept<false, false>(arrays, i, later);
          }
        }
        continue;
      }
      beyond |= forces_of(arrays, first, count, t, fused, laws);
      Base::step_segment(arrays, first, count, first_step);
      for (std::size_t s = 1; s < substeps; ++s) {
        beyond |= forces_of(arrays, first, count, t, fused, laws);
        Base::template step_segment<false>(arrays, first, count, later);
      }
    }
    return beyond;
  }

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

 private:
  // Whether a particle of [first, first + count) may reach its lifetime within `total`
  // seconds: generously (twice the time, and the age's rounding), so that false is certain.
  POINTMASS_DETAIL_ALWAYS_INLINE static bool may_expire(const Arrays& arrays, std::size_t first,
                                                        std::size_t count, R total) noexcept {
    if constexpr (Layout::has_lifetime) {
      constexpr R rounding = R(64) * std::numeric_limits<R>::epsilon();
      unsigned may = 0;
      for (std::size_t i = first; i < first + count; ++i) {
        const R age = arrays.age[i] + arrays.age_error[i];
        may |= static_cast<unsigned>(
            !(age + R(2) * total + real_abs(age) * rounding < arrays.lifetime[i]));
      }
      return may != 0;
    } else {
      static_cast<void>(arrays);
      static_cast<void>(first);
      static_cast<void>(count);
      static_cast<void>(total);
      return false;
    }
  }
  POINTMASS_DETAIL_ALWAYS_INLINE static bool expired(const Arrays& arrays, std::size_t i) noexcept {
    if constexpr (Layout::has_lifetime) {
      return lifetime_expired(arrays.age[i], arrays.age_error[i], arrays.lifetime[i]);
    } else {
      static_cast<void>(arrays);
      static_cast<void>(i);
      return false;
    }
  }
};

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END
