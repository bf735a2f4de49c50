// SPDX-License-Identifier: BSL-1.0
// Keeping a benchmark's velocities out of the subnormal range. A system is stepped thousands
// to millions of times: damping alone (x and z, which gravity does not feed) would take its
// velocities into float's subnormal range, where arithmetic on many processors is tens of
// times slower (docs/performance.md, "Particles at rest"), and the loop would measure that
// instead. So every `refresh_interval` steps, outside the timing, the velocities are put back
// to where they started. Per-second damping 0.9 keeps 0.9^(4096/60) = 7.6e-4 of a velocity
// over 4,096 steps of 1/60 s; per-frame damping 0.9 keeps 0.9 a step (a float velocity of 10
// is subnormal after about 850 steps), so it is refreshed every 256 steps (0.9^256 = 2e-12).
#pragma once

#include <pointmass/damping.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace pointmass_benchmarks {

template <class D>
constexpr std::int64_t refresh_interval =
    std::is_same_v<D, pointmass::damping::PerFrame> ? 256 : 4096;

/// Counts a step; every refresh_interval<D> steps calls `restore` outside the timing.
template <class D = pointmass::damping::PerSecond, class Restore>
void refresh_now_and_then(benchmark::State& state, std::int64_t& steps, Restore&& restore) {
  if (++steps % refresh_interval<D> != 0) return;
  state.PauseTiming();
  restore();
  state.ResumeTiming();
}

/// The velocities of a system, to put back.
template <class System>
struct SavedVelocities {
  explicit SavedVelocities(System& system)
      : x(system.template column<pointmass::Column::velocity_x>().begin(),
          system.template column<pointmass::Column::velocity_x>().end()),
        y(system.template column<pointmass::Column::velocity_y>().begin(),
          system.template column<pointmass::Column::velocity_y>().end()),
        z(system.template column<pointmass::Column::velocity_z>().begin(),
          system.template column<pointmass::Column::velocity_z>().end()) {}
  void restore(System& system) const {
    std::copy(x.begin(), x.end(), system.template column<pointmass::Column::velocity_x>().begin());
    std::copy(y.begin(), y.end(), system.template column<pointmass::Column::velocity_y>().begin());
    std::copy(z.begin(), z.end(), system.template column<pointmass::Column::velocity_z>().begin());
  }
  std::vector<typename System::real> x, y, z;
};

}  // namespace pointmass_benchmarks
