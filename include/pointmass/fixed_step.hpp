// SPDX-License-Identifier: BSL-1.0
// pointmass/fixed_step.hpp — physics at a fixed rate, drawing in between ("fix your timestep").
//
//   pointmass::FixedStep<double> clock(1.0 / 60, 8);     // 60 Hz, at most 8 steps a frame
//   const auto frame = clock.advance(frame_seconds);     // each rendered frame
//   for (int s = 0; s < frame.steps; ++s) system.step(1.0f / 60);
//   system.copy_interpolated_positions(float(frame.alpha), vertices);   // features::Interpolation
//
// Owns: the accumulator (frame time in; the number of fixed steps to take and the fraction
// alpha of a step left over out) and `interpolate`, the blend of two positions that a lone
// Particle's loop uses (keep the position before the last step yourself; a ParticleSystem
// keeps it with features::Interpolation).
//
// The cap: a frame takes at most `max_steps` steps. When more time has accumulated than that
// (a slow frame, a pause in a debugger), the whole steps beyond the cap are dropped (reported
// in `dropped`): the simulation runs slower than the clock for that frame instead of spending
// ever longer frames catching up (the "spiral of death"). The leftover fraction is kept.
//
// Must not include: particle_system.hpp (the accumulator knows no particles).
#pragma once

#include <cmath>

#include "config.hpp"
#include "detail/validate.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// The position at the fraction alpha in [0, 1] between `previous` and `current`: alpha 0
/// gives previous and 1 gives current, bit for bit; between them previous + (current -
/// previous) alpha. An alpha outside [0, 1] (or NaN) is a contract violation, checked when
/// POINTMASS_CHECKS is on (as ParticleSystem::interpolated_position checks it): reported, and
/// `current` is returned.
template <Real R, class A>
[[nodiscard]] constexpr Vector3<R> interpolate(const Vector3<R>& previous,
                                               const Vector3<R>& current,
                                               A alpha) noexcept(!POINTMASS_HOST_CHECKS) {
  const R fraction = static_cast<R>(alpha);
#if POINTMASS_HOST_CHECKS
  if (!detail::check_fraction("interpolate", "alpha", fraction)) return current;
#endif
  if (real_equal(fraction, R(0))) return previous;
  if (real_equal(fraction, R(1))) return current;
  return previous + (current - previous) * fraction;
}

/// The fixed-step accumulator. R is the precision of the clock (double unless the game's
/// clock is float): the time accumulated is kept below one step, so rounding does not grow
/// with the game's age.
template <Real R = double>
class FixedStep {
 public:
  /// What a frame is to do.
  struct Frame {
    int steps = 0;     ///< fixed steps to take now
    R alpha = R(0);    ///< the fraction of a step left over, in [0, 1): draw at it
    R dropped = R(0);  ///< seconds dropped by the cap in this frame (0 normally)
  };

  /// 60 Hz, at most 8 steps a frame.
  constexpr FixedStep() = default;
  /// A step of `step` seconds (> 0, finite), at most `max_steps` (>= 1) a frame. A rejected
  /// argument is reported and its default (1/60 s, 8) kept.
  FixedStep(R step, int max_steps) {
    set_step(step);
    set_max_steps(max_steps);
  }

  [[nodiscard]] constexpr R step() const noexcept { return step_; }
  [[nodiscard]] constexpr int max_steps() const noexcept { return max_steps_; }
  /// The time accumulated and not yet stepped, in [0, step()).
  [[nodiscard]] constexpr R accumulated() const noexcept { return accumulated_; }

  void set_step(R step) {
    if (detail::check_positive("set_step", "step", step)) {
      step_ = step;
      accumulated_ = R(0);
    }
  }
  void set_max_steps(int max_steps) {
    if (detail::check_at_least("set_max_steps", "max_steps", max_steps, 1)) {
      max_steps_ = max_steps;
    }
  }
  /// Forgets the accumulated time.
  constexpr void reset() noexcept { accumulated_ = R(0); }

  /// Adds a frame of `frame_time` seconds (finite, >= 0): how many fixed steps to take now
  /// (at most max_steps()) and the alpha to draw at after them. A rejected frame time is
  /// reported and adds nothing.
  Frame advance(R frame_time) {
    Frame frame;
    if (!detail::check_duration("advance", "frame_time", frame_time)) {
      frame.alpha = accumulated_ / step_;
      return frame;
    }
    if (real_isfinite(accumulated_ + frame_time)) {
      accumulated_ += frame_time;
    } else {  // beyond R's range (a step near it): at least one step is due, so take it first
      accumulated_ = (frame_time - step_) + accumulated_;
      frame.steps = 1;
    }
    while (accumulated_ >= step_ && frame.steps < max_steps_) {
      accumulated_ -= step_;
      ++frame.steps;
    }
    if (accumulated_ >= step_) {  // the cap: drop the whole steps beyond it
      const R kept = std::fmod(accumulated_, step_);
      frame.dropped = accumulated_ - kept;
      accumulated_ = kept;
    }
    frame.alpha = accumulated_ / step_;  // accumulated < step: alpha < 1, also after rounding
    return frame;
  }

 private:
  R step_ = R(1) / R(60);
  int max_steps_ = 8;
  R accumulated_ = R(0);
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
