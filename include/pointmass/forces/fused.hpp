// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/fused.hpp — the library's field generators in the form a vectorised loop
// takes: the fused forms a step's law pass (detail/law_pass.hpp) evaluates.
//
// A fused form computes its generator's force() by the plain formula only, branch free, with
// a square root that vectorises under -fmath-errno (detail::square_root: IEEE's sqrt bit for
// bit; the hardware's with -fno-math-errno, the same bits), and says where it cannot vouch
// for force()'s bits (`sure` false: a square beyond the plain formula's range, a zero length):
// there the pass calls force() itself. A generator without a fused form (a user's law) is
// called through its force() in the loop, which vectorises when the law's arithmetic does.
// Constants (k2 > 0, Buoyancy's lift) are formed once, when the form is made.
//
// Owns: FusedForce, fused_form for Gravity, Drag, AnchoredSpring and AnchoredBungee, Buoyancy,
// and for any other law.
// Must not include: particle.hpp, particle_system.hpp.
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../detail/exponential.hpp"
#include "../detail/square_root.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "generators.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces::detail {

namespace pd = pointmass::detail;

/// An integer as wide as R: a loop's flags then take R's lanes (g++ -O2 vectorises a loop
/// with one width of lane only). Not bool: a bool member stays in memory.
template <Real R>
using LaneFlag = std::conditional_t<sizeof(R) == 8, std::uint64_t, std::uint32_t>;

template <Real R>
struct FusedForce {
  Vector3<R> force;
  LaneFlag<R> sure;  // 1: the bits of the generator's force()
};

/// sqrt(x) for a square magnitude the plain formula takes (square_is_exact_enough: positive
/// and normal): the hardware's where it sets no errno, else the library's; the same bits.
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr R plain_root(R x) noexcept {
  if constexpr (!pd::has_ieee_bits_v<R>) {
    return real_sqrt(x);
  } else {
#if defined(__NO_MATH_ERRNO__)
    if (!std::is_constant_evaluated()) {
      if constexpr (std::same_as<R, float>) return __builtin_sqrtf(x);
      else return __builtin_sqrt(x);
    }
#endif
    return pd::ordinary_root(x);
  }
}

// |v| by the plain formula and whether it is magnitude(v)'s: x^2 + y^2 + z^2 in range.
template <Real R>
struct PlainLength {
  R length;
  LaneFlag<R> sure;
};
template <Real R>
POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr PlainLength<R> plain_length(
    const Vector3<R>& v) noexcept {
  const R square = square_magnitude(v);
  // square_is_exact_enough's test, its two comparisons and-ed as values (&& is a branch).
  constexpr R least = std::numeric_limits<R>::min() / std::numeric_limits<R>::epsilon();
  const bool in_range = (static_cast<int>(square >= least) &
                         static_cast<int>(square <= std::numeric_limits<R>::max())) != 0;
  return {plain_root(pd::select_if(in_range, square, R(1))), static_cast<LaneFlag<R>>(in_range)};
}

/// Any law: its own force() (sure).
template <class G>
struct FusedAny {
  G law;
  template <Real R>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr FusedForce<R> fused(const Vector3<R>& p,
                                                                            const Vector3<R>& v,
                                                                            R w,
                                                                            R t) const noexcept {
    return {law.force(p, v, w, t), 1};
  }
};
template <class G>
constexpr FusedAny<G> fused_form(const G& law) noexcept {
  return {law};
}

/// Gravity::force: g / inverse_mass, none for an immovable body.
template <Real R>
struct FusedGravity {
  Vector3<R> g;
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr FusedForce<R> fused(const Vector3<R>&,
                                                                            const Vector3<R>&, R w,
                                                                            R) const noexcept {
    const bool movable = w > R(0);
    const R divisor = pd::select_if(movable, w, R(1));
    return {
        {pd::select_if(movable, g.x / divisor, R(0)), pd::select_if(movable, g.y / divisor, R(0)),
         pd::select_if(movable, g.z / divisor, R(0))},
        1};
  }
};
template <Real R>
constexpr FusedGravity<R> fused_form(const Gravity<R>& law) noexcept {
  return {law.gravity()};
}

/// Drag::force: -v (k1 + k2 |v|), where that is finite.
template <Real R>
struct FusedDrag {
  R k1;
  R k2;
  bool quadratic;  // k2 > 0: else the speed is not formed (as force() does not form it)
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr FusedForce<R> fused(const Vector3<R>&,
                                                                            const Vector3<R>& v, R,
                                                                            R) const noexcept {
    const PlainLength<R> speed = plain_length(v);
    const R per_speed = pd::select_if(quadratic, k1 + k2 * speed.length, k1);
    // | and &, not || and &&: a branch would keep the loop scalar.
    return {v * -per_speed, (speed.sure | static_cast<LaneFlag<R>>(!quadratic)) &
                                static_cast<LaneFlag<R>>(real_isfinite(per_speed))};
  }
};
template <Real R>
constexpr FusedDrag<R> fused_form(const Drag<R>& law) noexcept {
  return {law.k1(), law.k2(), law.k2() > R(0)};
}

/// BasicAnchoredSpring::force: -k (|d| - L) d / |d| with d = p - anchor (a bungee's only
/// while stretched), where |d|^2 is in range.
template <Real R, bool IsBungee>
struct FusedAnchoredSpring {
  Vector3<R> anchor;
  R k;
  R rest_length;
  bool stiff;  // k > 0: else no force
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr FusedForce<R> fused(const Vector3<R>& p,
                                                                            const Vector3<R>&, R,
                                                                            R) const noexcept {
    const Vector3<R> d = p - anchor;
    const PlainLength<R> s = plain_length(d);
    // force_between's arithmetic at scale 1: d / |d| (normalized), |d| - L / 1, -k e 1.
    const R length = s.length;
    const R extension = length - rest_length / R(1);
    const R magnitude = -k * extension * R(1);
    bool acts = stiff;
    if constexpr (IsBungee)
      acts = static_cast<bool>(static_cast<int>(acts) & static_cast<int>(extension > R(0)));
    return {{pd::select_if(acts, d.x / length * magnitude, R(0)),
             pd::select_if(acts, d.y / length * magnitude, R(0)),
             pd::select_if(acts, d.z / length * magnitude, R(0))},
            s.sure | static_cast<LaneFlag<R>>(!stiff)};
  }
};
template <Real R, bool IsBungee>
constexpr FusedAnchoredSpring<R, IsBungee> fused_form(
    const BasicAnchoredSpring<R, IsBungee>& law) noexcept {
  return {law.anchor(), law.stiffness(), law.rest_length(), law.stiffness() > R(0)};
}

/// Buoyancy::force: (0, lift s, 0), s the submerged fraction clamped to [0, 1].
template <Real R>
struct FusedBuoyancy {
  R lift;
  R water_height;
  R max_depth;
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD constexpr FusedForce<R> fused(const Vector3<R>& p,
                                                                            const Vector3<R>&, R,
                                                                            R) const noexcept {
    const R s = ((water_height - p.y) / max_depth + R(1)) / R(2);
    const R fraction = pd::select_if(s > R(1), R(1), pd::select_if(s > R(0), s, R(0)));
    return {{R(0), lift * fraction, R(0)}, 1};
  }
};
template <Real R>
constexpr FusedBuoyancy<R> fused_form(const Buoyancy<R>& law) noexcept {
  return {law.lift(), law.water_height(), law.max_depth()};
}

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces::detail
POINTMASS_DETAIL_UNFUSED_END
