// SPDX-License-Identifier: BSL-1.0
// pointmass/system/step_view.hpp — ParticleSystem::StepView, a step of one's own.
//
//   auto view = system.begin_step(dt);
//   for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);  // any thread
//   system.finish_step(std::move(view));
//
// Included by particle_system.hpp, after the class it is nested in.
//
// Owns: ParticleSystem::StepView.
// Must not include: anything but particle_system.hpp.
#pragma once

#include <cstddef>
#include <utility>

#include "../particle_system.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// The step that ParticleSystem::begin_step(duration) began: the arrays, the step's
/// parameters, and the step of one particle. Obtained only from begin_step, handed back once
/// to finish_step (it moves, and does not copy); valid while the system's particles do not
/// change (no spawn, kill, step or move until finish_step).
// clang-format off
template <class S, DampingPolicy D, class P, class... Features>
  requires((Real<S> || PrecisionChoice<S>) && (detail::is_feature_v<Features> && ...))
class ParticleSystem<S, D, P, Features...>::StepView {
  // clang-format on
 public:
  /// Raw pointers to the arrays (nullptr for those not stored) and the particle count: what a
  /// device copies.
  using Arrays = typename Layout::Arrays;
  /// What every particle's step shares (duration, uniform damping factors and acceleration):
  /// trivially copyable, for a device.
  using Parameters = typename Kernel::StepParameters;

  StepView(StepView&& other) noexcept
      : owner_(std::exchange(other.owner_, nullptr)),
        arrays_(other.arrays_),
        parameters_(other.parameters_) {}
  StepView(const StepView&) = delete;
  StepView& operator=(const StepView&) = delete;
  StepView& operator=(StepView&&) = delete;
  ~StepView() = default;

  /// The particles to step, [0, size()); 0 when the step has nothing to do.
  [[nodiscard]] std::size_t size() const noexcept { return arrays_.size; }
  explicit operator bool() const noexcept { return size() != 0; }
  [[nodiscard]] const Arrays& arrays() const noexcept { return arrays_; }
  [[nodiscard]] const Parameters& parameters() const noexcept { return parameters_; }
  /// Particle i's step (i < size(): checked when POINTMASS_CHECKS is on). Particles are
  /// independent: any order, any thread.
  void step_particle(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (detail::check_index("StepView::step_particle", i, size())) {
      Kernel::step_particle(arrays_, i, parameters_);
    }
  }
  /// Particles [first, last) through the vectorised loop (first <= last <= size(), checked
  /// when POINTMASS_CHECKS is on).
  void step_range(std::size_t first, std::size_t last) const noexcept(!POINTMASS_HOST_CHECKS) {
    Kernel::step_range(arrays_, first, last, parameters_);
  }
  /// Particle i's step on a copy of the arrays (a device's), with the view's parameters.
  POINTMASS_HD static constexpr void step_particle(const Arrays& arrays, std::size_t i,
                                                   const Parameters& parameters) noexcept {
    Kernel::step_particle(arrays, i, parameters);
  }

 private:
  friend class ParticleSystem;
  StepView(const ParticleSystem* owner, const Arrays& arrays, const Parameters& parameters)
      : owner_(owner), arrays_(arrays), parameters_(parameters) {}
  const ParticleSystem* owner_;
  Arrays arrays_;
  Parameters parameters_;
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
