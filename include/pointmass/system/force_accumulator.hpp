// SPDX-License-Identifier: BSL-1.0
// pointmass/system/force_accumulator.hpp — a ParticleSystem's per-particle mass and force
// (features::ForceAccumulator).
//
//   system.set_mass(i, 2.0f);
//   system.add_force(i, drag);            // for the next step only
//
// SystemForceAccumulator<Base> is a facet of ParticleSystem: a class template over the state
// below it that adds members and no data, so a system is no bigger for it; an implementation
// detail, whose public members ParticleSystem re-exports (a user never names it). Its members
// exist only with features::ForceAccumulator. The step (detail/system_kernel.hpp) turns the
// force into acceleration and clears it; force generators (forces/) write through add_force.
//
// Owns: inverse_mass, force_accumulator, set_mass, set_inverse_mass and add_force.
// Must not include: particle_system.hpp, detail/system_state.hpp or another facet (it uses
// only Base's arrays(), size() and valid_index()).
#pragma once

#include <cstddef>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemForceAccumulator : public Base {
 protected:
  using R = typename Base::R;

 public:
  [[nodiscard]] R inverse_mass(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) requires Base::Layout::has_forces {
    return this->valid_index("inverse_mass", i) ? this->arrays().inverse_mass[i] : R(0);
  }
  [[nodiscard]] Vector3<R> force_accumulator(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) requires Base::Layout::has_forces {
    if (!this->valid_index("force_accumulator", i)) return {};
    const typename Base::Arrays& a = this->arrays();
    return Base::load(a.force_x, a.force_y, a.force_z, i);
  }
  /// mass > 0 (infinity makes the particle immovable), with 1/mass finite and normal.
  void set_mass(std::size_t i, R mass) requires Base::Layout::has_forces {
    if (detail::check_index("set_mass", i, this->size()) && detail::check_mass("set_mass", mass)) {
      this->arrays().inverse_mass[i] = R(1) / mass;
    }
  }
  /// inverse mass 0 (immovable) or finite, normal and > 0.
  void set_inverse_mass(std::size_t i, R inverse_mass) requires Base::Layout::has_forces {
    if (detail::check_index("set_inverse_mass", i, this->size()) &&
        detail::check_inverse_mass("set_inverse_mass", inverse_mass)) {
      this->arrays().inverse_mass[i] = inverse_mass;
    }
  }
  /// Adds a force to particle i for the next step only. As Particle::add_force: a hot-path
  /// call, so its preconditions (i < size(), a finite force) are checked when
  /// POINTMASS_CHECKS is on.
  void add_force(std::size_t i, const Vector3<R>& force) noexcept(
      !POINTMASS_HOST_CHECKS) requires Base::Layout::has_forces {
#if POINTMASS_HOST_CHECKS
    if (!detail::check_index("add_force", i, this->size()) ||
        !detail::check_finite("add_force", "force", force)) {
      return;
    }
#endif
    const typename Base::Arrays& a = this->arrays();
    a.force_x[i] += force.x;
    a.force_y[i] += force.y;
    a.force_z[i] += force.z;
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
