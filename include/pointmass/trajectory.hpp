// SPDX-License-Identifier: BSL-1.0
// pointmass/trajectory.hpp — where a particle of the exact pair will be, without stepping it.
//
//   pointmass::Particle<double, damping::Exact, position::Exact> shell;   // ... launched
//   auto at = pointmass::state_at(shell, 2.0);                  // position and velocity at 2 s
//   auto hit = pointmass::time_to_reach(shell, Axis::y, 0.0);   // std::optional: the first time
//                                                               // y = 0, or nothing ("never")
//
// Owns: queries on the closed form of the exact pairs, Particle<R, damping::Exact,
// position::Exact> and Particle<R, damping::None, position::Exact>. For constant acceleration
// a and per-second damping d (k = ln d <= 0), each coordinate follows
//   v(t) = v0 e^{kt} + a t phi1(kt),   p(t) = p0 + v0 t phi1(kt) + a t^2 phi2(kt),
//   phi1(x) = (e^x - 1)/x, phi2(x) = (e^x - 1 - x)/x^2      (without damping: p0 + v0 t + a t^2/2)
// which is what one step of length t computes: state_at(particle, t) is particle.integrate(t)
// on a copy (bit for bit, when no force is accumulated: the queries use the particle's
// acceleration only; forces added for the next step are not part of a trajectory). It stays
// exact as d -> 1 (the factors' series near x = 0) and as d -> 0 (d = 0 stops the particle:
// it stays where it is).
//
// time_to_reach(particle, axis, value): the first t >= 0 at which the coordinate equals value.
// The velocity of a coordinate is monotone in t (it relaxes exponentially towards -a/k, or
// changes linearly without damping), so the coordinate has at most one turning point, at
//   t_turn = -(v0/a) ln(1 + x)/x,  x = k v0/a   (-v0/a without damping; only when v0 a < 0),
// computed with log1p so that it holds as k -> 0. Before and after t_turn the coordinate is
// monotone: the query brackets the value on the first of those pieces that contains it
// (doubling the end of the second piece), then bisects to adjacent numbers of R. "Never"
// (std::nullopt) when no piece reaches the value: the apex is below it, the coordinate
// approaches a limit short of it (no acceleration, with damping), or d = 0.
//
// Must not include: particle_system.hpp (a query is about one particle).
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>

#include "config.hpp"
#include "damping.hpp"
#include "detail/validate.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// A coordinate of a position.
enum class Axis : unsigned char { x, y, z };

/// A particle's position and velocity at some time.
template <Real R>
struct TrajectoryState {
  Vector3<R> position;
  Vector3<R> velocity;
};

namespace detail {

template <class D>
inline constexpr bool trajectory_damping_v =
    std::is_same_v<D, damping::Exact> || std::is_same_v<D, damping::None>;

template <Real R>
constexpr R component(const Vector3<R>& v, Axis axis) noexcept {
  return axis == Axis::x ? v.x : axis == Axis::y ? v.y : v.z;
}

/// One coordinate's closed form: p(t), through the library's own step of length t.
template <Real R, class D>
struct CoordinateFlight {
  typename D::template State<R> damping{};
  R p0{}, v0{}, a{};

  R position(R t) const noexcept {
    R p = p0;
    R v = v0;
    integrate<D, position::Exact>(p, v, a, t, D::factors(damping, t));
    return p;
  }
};

/// First t in [lo, hi] where position(t) - value changes sign (it does between lo and hi, or
/// is 0 at hi); bisection to adjacent numbers of R.
template <Real R, class Flight>
R bisect(const Flight& flight, R value, R lo, R hi) noexcept {
  const bool rising = flight.position(lo) < value;  // the coordinate passes value upwards
  for (int iteration = 0; iteration < 20000; ++iteration) {
    const R mid = lo + (hi - lo) / R(2);
    if (!(mid > lo && mid < hi)) break;
    const R p = flight.position(mid);
    if (rising ? p < value : p > value) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  const R error_lo = flight.position(lo) - value;
  const R error_hi = flight.position(hi) - value;
  return (error_lo < R(0) ? -error_lo : error_lo) < (error_hi < R(0) ? -error_hi : error_hi) ? lo
                                                                                             : hi;
}

/// The turning point of the flight, where its velocity passes 0; 0 unless v0 and a have
/// opposite signs.
template <Real R, class D>
R turning_time(const CoordinateFlight<R, D>& flight) {
  if (!((flight.v0 > R(0) && flight.a < R(0)) || (flight.v0 < R(0) && flight.a > R(0)))) {
    return R(0);
  }
  R k = R(0);
  if constexpr (std::is_same_v<D, damping::Exact>) k = flight.damping.log_value();
  const R ratio = flight.v0 / flight.a;                             // < 0
  const R x = k * ratio;                                            // >= 0
  const R shrink = real_equal(x, R(0)) ? R(1) : std::log1p(x) / x;  // ln(1 + x)/x in (0, 1]
  return real_isfinite(x) && real_isfinite(ratio) ? -ratio * shrink : R(0);
}

}  // namespace detail

/// The particle's position and velocity `time` seconds from now (time finite and >= 0), under
/// its acceleration and damping, without stepping it: particle.integrate(time) on a copy.
template <Real R, class D>
  requires(detail::trajectory_damping_v<D>)
[[nodiscard]] TrajectoryState<R> state_at(const Particle<R, D, position::Exact>& particle, R time) {
  if (!detail::check_duration("state_at", "time", time)) {
    return {particle.position(), particle.velocity()};
  }
  typename D::template State<R> state{};
  if constexpr (std::is_same_v<D, damping::Exact>)
    state = typename D::template State<R>(particle.damping());
  Vector3<R> p = particle.position();
  Vector3<R> v = particle.velocity();
  integrate<D, position::Exact>(p, v, particle.acceleration(), time, D::factors(state, time));
  return {p, v};
}
template <Real R, class D>
  requires(detail::trajectory_damping_v<D>)
[[nodiscard]] Vector3<R> position_at(const Particle<R, D, position::Exact>& particle, R time) {
  return state_at(particle, time).position;
}
template <Real R, class D>
  requires(detail::trajectory_damping_v<D>)
[[nodiscard]] Vector3<R> velocity_at(const Particle<R, D, position::Exact>& particle, R time) {
  return state_at(particle, time).velocity;
}

/// The first time t >= 0 at which the particle's coordinate `axis` equals `value` (finite),
/// or std::nullopt when it never does (see the header's comment). 0 when it is there now.
template <Real R, class D>
  requires(detail::trajectory_damping_v<D>)
[[nodiscard]] std::optional<R> time_to_reach(const Particle<R, D, position::Exact>& particle,
                                             Axis axis, R value) {
  if (!detail::check_finite("time_to_reach", "value", value)) return std::nullopt;
  detail::CoordinateFlight<R, D> flight;
  if constexpr (std::is_same_v<D, damping::Exact>) {
    flight.damping = typename D::template State<R>(particle.damping());
  }
  flight.p0 = detail::component(particle.position(), axis);
  flight.v0 = detail::component(particle.velocity(), axis);
  flight.a = detail::component(particle.acceleration(), axis);
  const R gap = value - flight.p0;
  if (real_equal(gap, R(0))) return R(0);
  if (!(particle.damping() > R(0))) return std::nullopt;  // d = 0: it stays where it is

  const R turn = detail::turning_time(flight);
  // The first piece, [0, turn]: monotone from p0 to p(turn).
  if (turn > R(0)) {
    const R at_turn = flight.position(turn);
    if ((gap > R(0) && at_turn >= value) || (gap < R(0) && at_turn <= value)) {
      return detail::bisect(flight, value, R(0), turn);
    }
  }
  // The second piece, [turn, infinity): monotone; double its end until it passes value.
  const R start = flight.position(turn);
  const bool below = start < value;
  R lo = turn;
  R hi = turn + R(1);
  for (int doubling = 0; doubling < 20000 && real_isfinite(hi); ++doubling) {
    const R p = flight.position(hi);
    if (real_isnan(p)) return std::nullopt;
    if (below ? p >= value : p <= value) return detail::bisect(flight, value, lo, hi);
    lo = hi;
    hi = hi * R(2);
  }
  return std::nullopt;
}

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
