// SPDX-License-Identifier: BSL-1.0
// pointmass/system/deprecated.hpp — ParticleSystem's names of 0.1, kept for one minor version.
//
// Each forwards to its replacement, which its deprecation message names (CHANGELOG.md lists
// them all); the next minor version removes this facet. SystemDeprecated<Base> is a facet of
// ParticleSystem: a class template over the facets below it that adds members and no data;
// an implementation detail, whose public members ParticleSystem re-exports.
//
// Owns: the deprecated members and traits of ParticleSystem.
// Must not include: particle_system.hpp or detail/system_state.hpp (it uses only Base's
// members: the state's and the other facets').
#pragma once

#include <cstddef>
#include <span>

#include "../config.hpp"
#include "../features.hpp"
#include "../vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemDeprecated : public Base {
 protected:
  using R = typename Base::R;
  using Layout = typename Base::Layout;
  using Kernel = typename Base::Kernel;
  using position_element = typename Layout::position_element;
  using position_value = typename Base::position_value;

 public:
#define POINTMASS_DETAIL_RENAMED(replacement) \
  [[deprecated("pointmass 0.2: use " replacement " (CHANGELOG.md)")]]
  using Arrays POINTMASS_DETAIL_RENAMED("StepView::Arrays") = typename Layout::Arrays;
  using StepParameters POINTMASS_DETAIL_RENAMED("StepView::Parameters") =
      typename Kernel::StepParameters;
  POINTMASS_DETAIL_RENAMED("has<features::PerParticleDamping>")
  static constexpr bool per_particle_damping = Layout::per_particle_damping;
  POINTMASS_DETAIL_RENAMED("has<features::PerParticleAcceleration>")
  static constexpr bool per_particle_acceleration = Layout::per_particle_acceleration;
  POINTMASS_DETAIL_RENAMED("has<features::ForceAccumulator>")
  static constexpr bool has_forces = Layout::has_forces;
  POINTMASS_DETAIL_RENAMED("has<features::Lifetime>")
  static constexpr bool has_lifetime = Layout::has_lifetime;
  POINTMASS_DETAIL_RENAMED("has<features::Interpolation>")
  static constexpr bool has_interpolation = Layout::has_interpolation;
  POINTMASS_DETAIL_RENAMED("has<features::Handles>")
  static constexpr bool has_handles = Layout::has_handles;
  POINTMASS_DETAIL_RENAMED("storage_bytes_per_particle, the bytes they take")
  static constexpr std::size_t array_count = Layout::array_count;

  POINTMASS_DETAIL_RENAMED("column<Column::position_x>()")
  std::span<position_element> position_x() noexcept {
    return this->template column<Column::position_x>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::position_y>()")
  std::span<position_element> position_y() noexcept {
    return this->template column<Column::position_y>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::position_z>()")
  std::span<position_element> position_z() noexcept {
    return this->template column<Column::position_z>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::velocity_x>()")
  std::span<R> velocity_x() noexcept { return this->template column<Column::velocity_x>(); }
  POINTMASS_DETAIL_RENAMED("column<Column::velocity_y>()")
  std::span<R> velocity_y() noexcept { return this->template column<Column::velocity_y>(); }
  POINTMASS_DETAIL_RENAMED("column<Column::velocity_z>()")
  std::span<R> velocity_z() noexcept { return this->template column<Column::velocity_z>(); }
  POINTMASS_DETAIL_RENAMED("column<Column::position_x>()")
  [[nodiscard]] std::span<const position_element> position_x() const noexcept {
    return this->template column<Column::position_x>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::position_y>()")
  [[nodiscard]] std::span<const position_element> position_y() const noexcept {
    return this->template column<Column::position_y>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::position_z>()")
  [[nodiscard]] std::span<const position_element> position_z() const noexcept {
    return this->template column<Column::position_z>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::velocity_x>()")
  [[nodiscard]] std::span<const R> velocity_x() const noexcept {
    return this->template column<Column::velocity_x>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::velocity_y>()")
  [[nodiscard]] std::span<const R> velocity_y() const noexcept {
    return this->template column<Column::velocity_y>();
  }
  POINTMASS_DETAIL_RENAMED("column<Column::velocity_z>()")
  [[nodiscard]] std::span<const R> velocity_z() const noexcept {
    return this->template column<Column::velocity_z>();
  }
  POINTMASS_DETAIL_RENAMED("copy_positions(buffer, origin)")
  void positions_relative_to(const Vector3<position_value>& origin,
                             std::span<Vector3<float>> buffer) const {
    this->copy_positions(buffer, origin);
  }

  POINTMASS_DETAIL_RENAMED("begin_step(duration) and StepView::arrays()")
  [[nodiscard]] const typename Layout::Arrays& arrays() const noexcept { return Base::arrays(); }
  POINTMASS_DETAIL_RENAMED("begin_step(duration) and StepView::parameters()")
  [[nodiscard]] typename Kernel::StepParameters step_parameters(R duration) const noexcept {
    return Base::step_parameters(duration);
  }
  POINTMASS_DETAIL_RENAMED("StepView::step_particle")
  POINTMASS_HD static constexpr void step_particle(
      const typename Layout::Arrays& arrays, std::size_t i,
      const typename Kernel::StepParameters& parameters) noexcept {
    Kernel::step_particle(arrays, i, parameters);
  }
  POINTMASS_DETAIL_RENAMED("StepView::step_range")
  static void step_range(const typename Layout::Arrays& arrays, std::size_t begin, std::size_t end,
                         const typename Kernel::StepParameters& parameters) {
    Kernel::step_range(arrays, begin, end, parameters);
  }
  POINTMASS_DETAIL_RENAMED("finish_step(std::move(view))")
  void arrays_changed() noexcept { Base::forget_retention(); }
  POINTMASS_DETAIL_RENAMED("finish_step(std::move(view))")
  void finish_step() {
    Base::forget_retention();
    typename Base::NoCallback none;
    Base::expire(none, "finish_step");
  }
  // clang-format off
  template <class OnExpire>
    requires(Layout::has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  POINTMASS_DETAIL_RENAMED("finish_step(std::move(view), on_expire)")
  void finish_step(OnExpire&& on_expire) {
    // clang-format on
    Base::forget_retention();
    Base::expire(on_expire, "finish_step");
  }
  POINTMASS_DETAIL_RENAMED("age >= lifetime (an infinite lifetime never expires)")
  POINTMASS_HD static constexpr bool expired(R age, R lifetime) noexcept {
    return Base::expired(age, lifetime);
  }
#undef POINTMASS_DETAIL_RENAMED
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
