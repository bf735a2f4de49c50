// SPDX-License-Identifier: BSL-1.0
// pointmass/system/interpolation.hpp — a ParticleSystem's positions between two fixed steps
// (features::Interpolation).
//
//   system.copy_interpolated_positions(clock.alpha(), std::span(vertices));  // what to draw
//
// SystemInterpolation<Base> is a facet of ParticleSystem: a class template over the state below it
// that adds members and no data, so a system is no bigger for it; an implementation
// detail, whose public members ParticleSystem re-exports (a user never names it).
// Its members exist only with features::Interpolation. The previous
// positions are kept by the step (detail/system_kernel.hpp) and moved with a jump
// (set_position); fixed_step.hpp's FixedStep gives the fraction alpha.
//
// Owns: previous_position, interpolated_position and both copy_interpolated_positions.
// Must not include: particle_system.hpp, detail/system_state.hpp or another facet (it uses
// only Base's arrays(), size(), valid_index() and its copy-out of positions).
#pragma once

#include <concepts>
#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemInterpolation : public Base {
 protected:
  using R = typename Base::R;
  using position_element = typename Base::Layout::position_element;

 public:
  /// Particle i's position column before the last step (its spawn or set_position position
  /// if it has not stepped since; for Compensated positions, the float part).
  [[nodiscard]] Vector3<position_element> previous_position(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) requires Base::Layout::has_interpolation {
    if (!this->valid_index("previous_position", i)) return {};
    const auto& a = this->arrays();
    return Base::load(a.previous_position_x, a.previous_position_y, a.previous_position_z, i);
  }
  /// Particle i's position at the fraction `alpha` in [0, 1] of the last step: alpha 0 gives
  /// the previous position and 1 the current one, bit for bit; between them
  /// previous + (current - previous) alpha, in the position columns' element type.
  [[nodiscard]] Vector3<position_element> interpolated_position(
      std::size_t i, R alpha) const requires Base::Layout::has_interpolation {
    if (!detail::check_index("interpolated_position", i, this->size()) ||
        !detail::check_fraction("interpolated_position", "alpha", alpha)) {
      return {};
    }
    Vector3<position_element> out{};
    // (compensated positions at alpha 1: hi + lo rounded to the element)
    this->for_each_output_position(alpha, i, i + 1, [&](std::size_t, auto x, auto y, auto z) {
      out = {static_cast<position_element>(x), static_cast<position_element>(y),
             static_cast<position_element>(z)};
    });
    return out;
  }
  /// As copy_positions (system/hand_off.hpp), with the positions at the fraction alpha of
  /// the last step.
  // clang-format off
  template <class T>
    requires(Base::Layout::has_interpolation && std::floating_point<T>)
  void copy_interpolated_positions(R alpha, std::span<T> out, std::size_t stride = 3) const {
    // clang-format on
    if (detail::check_fraction("copy_interpolated_positions", "alpha", alpha)) {
      this->copy_strided("copy_interpolated_positions", alpha, out, stride);
    }
  }
  // clang-format off
  template <class V>
    requires(Base::Layout::has_interpolation && !std::is_arithmetic_v<V> &&
             requires(V& v) { v.x = v.y = v.z; } &&
             std::floating_point<std::remove_cvref_t<decltype(std::declval<V&>().x)>>)
  void copy_interpolated_positions(R alpha, std::span<V> out) const {
    // clang-format on
    if (detail::check_fraction("copy_interpolated_positions", "alpha", alpha)) {
      this->copy_vectors("copy_interpolated_positions", alpha, out);
    }
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
