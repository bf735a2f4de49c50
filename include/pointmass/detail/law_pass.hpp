// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/law_pass.hpp — the laws of a step (forces::Laws) added to a chunk of a
// ParticleSystem's particles, just before the chunk's step.
//
// The chunk (at most law_chunk particles) is then in the L1 cache for the step that follows:
// the forces take no pass over memory of their own. One loop, vectorised, computes each law's
// fused form (forces/fused.hpp: the plain formula, with a square root that vectorises) and
// adds it to the particle's accumulated force, in the laws' order; where a fused form cannot
// vouch for force()'s bits (an input beyond the plain formula's range), the particle keeps its
// accumulated force and a scalar loop adds the laws' force() after. Either way the sums are
// forces::apply's, bit for bit.
//
// Owns: law_chunk, law_pass, NoLaws, fused_of, forces_of.
// Must not include: system_kernel.hpp and above (the kernel calls law_pass).
#pragma once

#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../forces/fused.hpp"
#include "../real.hpp"
#include "../vector3.hpp"

#if defined(__clang__) && !defined(__arm__)
#define POINTMASS_DETAIL_LAW_ITERATIONS _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__) && !defined(__clang__)
#define POINTMASS_DETAIL_LAW_ITERATIONS _Pragma("GCC ivdep")
#else
#define POINTMASS_DETAIL_LAW_ITERATIONS
#endif

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

/// The most particles one law pass takes: their arrays stay in L1 for the step after it.
inline constexpr std::size_t law_chunk = 256;

// One fused law's force added to (gx, gy, gz) where finite; its bit in `beyond` where not.
// A function, not a lambda: always inlined (g++ left a lambda a call, and the loop scalar).
template <class Law, class R, class Flag>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr void add_law(
    const Law& law, const Vector3<R>& p, const Vector3<R>& v, R w, R t, unsigned bit, R& gx, R& gy,
    R& gz, Flag& sure, Flag& beyond) noexcept {
  const forces::detail::FusedForce<R> f = law.fused(p, v, w, t);
  sure &= f.sure;
#if POINTMASS_CHECKS
  const bool finite =
      (static_cast<int>(real_isfinite(f.force.x)) & static_cast<int>(real_isfinite(f.force.y)) &
       static_cast<int>(real_isfinite(f.force.z))) != 0;
  gx = select_if(finite, gx + f.force.x, gx);  // not added where beyond range
  gy = select_if(finite, gy + f.force.y, gy);
  gz = select_if(finite, gz + f.force.z, gz);
  beyond |= static_cast<Flag>(static_cast<Flag>(!finite) << bit);
#else
  static_cast<void>(bit);
  static_cast<void>(beyond);
  gx = gx + f.force.x;
  gy = gy + f.force.y;
  gz = gz + f.force.z;
#endif
}

// Particle i's sum, accumulated force then each fused law's, into the accumulator where every
// law vouched for it; returns the laws beyond range (bit I for law I, 0 where unsure) and
// sets `unsure`.
template <class Arrays, class R, class Fused, std::size_t... I>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr forces::detail::LaneFlag<R> add_fused(
    const Arrays& a, std::size_t i, R t, const Fused& fused, forces::detail::LaneFlag<R>& unsure,
    std::index_sequence<I...>) noexcept {
  using Flag = forces::detail::LaneFlag<R>;
  const Vector3<R> p{a.position_x[i], a.position_y[i], a.position_z[i]};
  const Vector3<R> v{a.velocity_x[i], a.velocity_y[i], a.velocity_z[i]};
  const R w = a.inverse_mass[i];
  const R fx = a.force_x[i];
  const R fy = a.force_y[i];
  const R fz = a.force_z[i];
  R gx = fx;
  R gy = fy;
  R gz = fz;
  Flag beyond = 0;
  Flag sure = 1;
  (add_law(std::get<I>(fused), p, v, w, t, static_cast<unsigned>(I), gx, gy, gz, sure, beyond),
   ...);
  const bool kept = sure != 0;
  a.force_x[i] = select_if(kept, gx, fx);  // unsure: the scalar loop adds force() to fx
  a.force_y[i] = select_if(kept, gy, fy);
  a.force_z[i] = select_if(kept, gz, fz);
  unsure = sure ^ Flag { 1 };
  return beyond & (Flag{0} - sure);  // none where unsure: the scalar loop reports those
}

/// Adds the laws' forces to particles [first, first + count) of `arrays` (count <=
/// law_chunk) for a step of t: `fused` is laws.fused() (forces/fused.hpp), `laws` the laws
/// whose force() the scalar loop calls where a fused form was unsure. Returns the laws whose
/// force was beyond range on some particle (bit I for law I).
#if defined(__clang__)
#pragma clang diagnostic push
// As for the kernel's step loop: where the law loop does not vectorise (clang -O1, a user's
// law with a call), clang's report must not fail a -Werror build of the user's code.
#pragma clang diagnostic ignored "-Wpass-failed"
#endif
template <class Arrays, class R, class Fused, class Laws>
inline unsigned law_pass(const Arrays& arrays_in, std::size_t first, std::size_t count, R t,
                         const Fused& fused_in, const Laws& laws) noexcept {
  // Local copies: the loop's stores cannot alias them (as the step's loop, system_kernel.hpp).
  const Arrays arrays = arrays_in;
  const Fused fused = fused_in;
  constexpr auto indices = std::make_index_sequence<std::tuple_size_v<Fused>>{};
  using Flag = forces::detail::LaneFlag<R>;
  Flag unsure[law_chunk];
  Flag any_unsure = 0;
  Flag beyond = 0;
  const std::size_t blocked = count & ~std::size_t{15};  // as the step loop: no remainder loop
  POINTMASS_DETAIL_LAW_ITERATIONS  // the law loop (tests/system probes this line)
      for (std::size_t k = 0; k < blocked; ++k) {
    beyond |= add_fused(arrays, first + k, t, fused, unsure[k], indices);
    any_unsure |= unsure[k];
  }
  for (std::size_t k = blocked; k < count; ++k) {
    beyond |= add_fused(arrays, first + k, t, fused, unsure[k], indices);
    any_unsure |= unsure[k];
  }
  if (any_unsure == 0) return static_cast<unsigned>(beyond);
  for (std::size_t k = 0; k < count; ++k) {  // rare: inputs beyond the plain formulas' range
    if (unsure[k] == 0) continue;
    const std::size_t i = first + k;
    R fx = arrays.force_x[i];
    R fy = arrays.force_y[i];
    R fz = arrays.force_z[i];
    beyond |= laws.add(Vector3<R>{arrays.position_x[i], arrays.position_y[i], arrays.position_z[i]},
                       Vector3<R>{arrays.velocity_x[i], arrays.velocity_y[i], arrays.velocity_z[i]},
                       arrays.inverse_mass[i], t, fx, fy, fz);
    arrays.force_x[i] = fx;
    arrays.force_y[i] = fy;
    arrays.force_z[i] = fz;
  }
  return static_cast<unsigned>(beyond);
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

struct NoLaws {};  // a step whose forces are the accumulator's alone

/// The laws' fused forms (forces/fused.hpp), made once a walk; none without laws.
constexpr NoLaws fused_of(const NoLaws&) noexcept { return {}; }
template <class Laws>
constexpr auto fused_of(const Laws& laws) noexcept {
  return laws.fused();
}

/// The laws' forces added to particles [first, first + count) (law_pass); 0 without laws.
template <class Arrays, class R, class Fused, class Laws>
POINTMASS_DETAIL_ALWAYS_INLINE inline unsigned forces_of(const Arrays& arrays, std::size_t first,
                                                         std::size_t count, R t, const Fused& fused,
                                                         const Laws& laws) noexcept {
  constexpr bool none = [] {  // no laws, or forces::laws() (sub-steps alone)
    if constexpr (std::is_same_v<Laws, NoLaws>) {
      return true;
    } else {
      return std::tuple_size_v<Fused> == 0;
    }
  }();
  if constexpr (none) {
    return 0;
  } else {
    return law_pass(arrays, first, count, t, fused, laws);
  }
}

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END

#undef POINTMASS_DETAIL_LAW_ITERATIONS
