// SPDX-License-Identifier: BSL-1.0
// pointmass/system/hand_off.hpp — a ParticleSystem's positions handed to a renderer.
//
//   system.copy_positions(std::span(vertices), 8);               // interleaved vertices
//   system.copy_positions(std::span(offsets), camera);           // far from the origin
//
// SystemHandOff<Base> is a facet of ParticleSystem: a class template over the state below it
// that adds members and no data, so a system is no bigger for it; an implementation
// detail, whose public members ParticleSystem re-exports (a user never names it).
// With features::Interpolation, system/interpolation.hpp copies positions
// between two steps the same ways.
//
// Owns: copy_positions (strided numbers, vectors with x, y, z members, float offsets from an
// origin) and position_relative_to (the camera-relative float positions of precision.hpp).
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
class SystemHandOff : public Base {
 protected:
  using R = typename Base::R;
  using position_value = typename Base::position_value;

 public:
  /// Copies the positions into `out` as x, y, z at out[i * stride], out[i * stride + 1],
  /// out[i * stride + 2] (stride >= 3: 3 packed, more for interleaved vertices; pass
  /// buffer.subspan(offset) to start elsewhere), converted to T. `out` needs
  /// (size() - 1) * stride + 3 elements; a shorter one is reported and nothing is written.
  /// T is a floating-point type: an integer cannot hold every position, and converting one
  /// beyond its range is undefined, so such a buffer does not compile.
  // clang-format off
  template <class T>
    requires(std::floating_point<T>)
  void copy_positions(std::span<T> out, std::size_t stride = 3) const {
    // clang-format on
    this->copy_strided("copy_positions", R(1), out, stride);
  }
  /// Copies the positions into vectors with x, y, z members (glm::vec3, ...): out[i] for
  /// particle i; `out` needs size() elements. Their members are floating-point numbers.
  // clang-format off
  template <class V>
    requires(!std::is_arithmetic_v<V> && requires(V& v) { v.x = v.y = v.z; } &&
             std::floating_point<std::remove_cvref_t<decltype(std::declval<V&>().x)>>)
  void copy_positions(std::span<V> out) const {
    // clang-format on
    this->copy_vectors("copy_positions", R(1), out);
  }
  /// Particle i's position relative to `origin` (a camera), as float: from the whole
  /// stored position, exact wherever the true offset is a float (precision.hpp). T = R gives
  /// it in the arithmetic's own type, as a force generator sees it (forces::relative_to).
  /// An index out of range or a non-finite origin is a contract violation, checked when
  /// POINTMASS_CHECKS is on (then reported, and the result is zero).
  template <Real T = float>
  Vector3<T> position_relative_to(std::size_t i, const Vector3<position_value>& origin) const
      noexcept(!POINTMASS_HOST_CHECKS) {
    if (!this->valid_index("position_relative_to", i)) return {};
#if POINTMASS_HOST_CHECKS
    if (!detail::check_finite("position_relative_to", "origin", origin)) return {};
#endif
    return Base::template relative<T>(this->arrays(), i, origin);
  }
  /// Every particle's position relative to `origin` (a camera), as float, into `out` (at
  /// least size() elements; element i for particle i): what a renderer uploads when the
  /// world is large (precision.hpp). A non-finite origin or a buffer too small is reported
  /// and nothing is written.
  void copy_positions(std::span<Vector3<float>> out, const Vector3<position_value>& origin) const {
    if (!detail::check_finite("copy_positions", "origin", origin) ||
        !detail::check_buffer("copy_positions", "out", out.size(), this->size())) {
      return;
    }
    Base::template relative_all<float>(this->arrays(), origin, out.data());
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
