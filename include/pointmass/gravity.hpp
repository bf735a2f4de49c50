// SPDX-License-Identifier: BSL-1.0
// pointmass/gravity.hpp — gravity as an acceleration.
//
// Near the Earth f = m g (eq. 3.4), so p'' = g for any mass: gravity is set as the particle's
// acceleration (0, -g, 0), positive Y up, and g is tunable per particle. Millington's values:
// 9.807 m/s^2 (the scientific mean), and what games use for a livelier feel: 15 (shooters)
// and 20 (driving games).
//
// Owns: gravity(g) and Millington's values of g.
// Must not include: anything but config.hpp, real.hpp and vector3.hpp.
#pragma once

#include "config.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

template <Real R>
inline constexpr R earth_gravity = R(9.807);  ///< m/s^2, the scientific mean
template <Real R>
inline constexpr R shooter_gravity = R(15);  ///< m/s^2, typical of shooters
template <Real R>
inline constexpr R driving_gravity = R(20);  ///< m/s^2, typical of driving games

/// The acceleration of gravity g pointing down (-Y): (0, -g, 0).
template <Real R>
[[nodiscard]] POINTMASS_HD constexpr Vector3<R> gravity(R g = earth_gravity<R>) noexcept {
  return {R(0), -g, R(0)};
}

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
