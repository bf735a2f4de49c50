// SPDX-License-Identifier: BSL-1.0
// pointmass/system/lifetime.hpp — a ParticleSystem's per-particle age and lifetime
// (features::Lifetime).
//
//   system.set_lifetime(i, 2.0f);         // removed by the step after which its age reaches 2 s
//
// SystemLifetime<Base> is a facet of ParticleSystem: a class template over the state below it
// that adds members and no data, so a system is no bigger for it; an implementation
// detail, whose public members ParticleSystem re-exports (a user never names it).
// Its members exist only with features::Lifetime. The step ages the particles
// (detail/system_kernel.hpp) and expires them (ParticleSystem::step, finish_step, with an
// optional callback: particle_system.hpp).
//
// Owns: age, lifetime and set_lifetime.
// Must not include: particle_system.hpp, detail/system_state.hpp or another facet (it uses
// only Base's arrays(), size() and valid_index()).
#pragma once

#include <cstddef>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemLifetime : public Base {
 protected:
  using R = typename Base::R;

 public:
  [[nodiscard]] R age(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) requires Base::Layout::has_lifetime {
    if (!this->valid_index("age", i)) return R(0);
    const R age = this->arrays().age[i] + this->arrays().age_error[i];
    return real_isnan(age) ? real_infinity<R> : age;  // NaN: the count overflowed (count_age)
  }
  [[nodiscard]] R lifetime(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) requires Base::Layout::has_lifetime {
    return this->valid_index("lifetime", i) ? this->arrays().lifetime[i] : R(0);
  }
  /// Seconds particle i lives (> 0; infinity for ever: an infinite lifetime never expires).
  /// It is removed by the step after which its age reaches this. Ages count the steps'
  /// exact sum (the age column and the rounding it dropped, age_error), in float as in double.
  void set_lifetime(std::size_t i, R seconds) requires Base::Layout::has_lifetime {
    if (detail::check_index("set_lifetime", i, this->size()) &&
        detail::check_lifetime("set_lifetime", seconds)) {
      this->arrays().lifetime[i] = seconds;
    }
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
