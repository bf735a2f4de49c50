// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/movable_step.hpp — a component's step kept only for a movable particle.
//
// Owns: integrate_if_movable and integrate_stored_if (for positions stored wider or
// compensated): both outcomes computed, one kept (inverse_mass > 0: movable), a select the
// vectoriser can do where a branch is not. The mask comes from sign bits
// (detail::select_if_less): g++ -O2 has no SSE2 pattern for a 64-bit mask from a double
// comparison, so a `bool` made into a mask left double systems with forces scalar there.
// Must not include: system_kernel.hpp and above (the kernel's step calls these).
#pragma once

#include <cstddef>

#include "../config.hpp"
#include "../damping.hpp"
#include "../particle.hpp"
#include "../real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <DampingPolicy D, class P, class Layout, Real R, class F>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr void integrate_if_movable(
    R inverse_mass, R& p, R& v, R& kick, R a, R t, R last_half, const F& factors) noexcept {
  R p1 = p;
  R v1 = v;
  R kick1 = kick;
  integrate_component<D, P>(p1, v1, kick1, a, t, last_half, factors);
  p = select_if_less(R(0), inverse_mass, p1, p);
  v = select_if_less(R(0), inverse_mass, v1, v);
  if constexpr (Layout::has_kicks) kick = select_if_less(R(0), inverse_mass, kick1, kick);
}

// integrate_if_movable for a position stored wider or compensated; `error` is the error
// column (nullptr unless compensated).
template <DampingPolicy D, class P, class Layout, Real R, class F>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr void integrate_stored_if(
    bool movable, typename Layout::position_element& p, R* error, std::size_t i, R& v, R& kick, R a,
    R t, R last_half, const F& factors) noexcept {
  if constexpr (!Layout::has_forces) {
    // Every particle is movable: stepped in place, so that integrate stores the velocity
    // before it computes the displacement from v0, which then cannot be loaded from memory
    // a second time (integrate in particle.hpp says why that matters). Same bits.
    static_cast<void>(movable);
    R no_error = R(0);
    R& lo = [&]() -> R& {
      if constexpr (Layout::compensated_positions) return error[i];
      else return no_error;
    }();
    integrate_stored<D, P, typename Layout::position_storage>(p, lo, v, kick, a, t, last_half,
                                                              factors);
    return;
  }
  typename Layout::position_element p1 = p;
  R v1 = v;
  R kick1 = kick;
  R lo = R(0);
  if constexpr (Layout::compensated_positions) lo = error[i];
  R lo1 = lo;
  integrate_stored<D, P, typename Layout::position_storage>(p1, lo1, v1, kick1, a, t, last_half,
                                                            factors);
  p = select_if(movable, p1, p);
  v = select_if(movable, v1, v);
  if constexpr (Layout::has_kicks) kick = select_if(movable, kick1, kick);
  if constexpr (Layout::compensated_positions) error[i] = select_if(movable, lo1, lo);
}

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END
