// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/system_access.hpp — what the library's own steps (parallel.hpp,
// kokkos.hpp) and the tests reach of a ParticleSystem beyond its public API.
//
// Included by particle_system.hpp, after ParticleSystem (of which SystemAccess is a friend).
//
// Owns: detail::SystemAccess.
// Must not include: anything but particle_system.hpp.
#pragma once

#include <cstddef>
#include <utility>

#include "../particle_system.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

namespace detail {
/// What ParticleSystem::step does around its walk, for the steps of parallel.hpp and
/// kokkos.hpp, and what the tests inspect: the kernel and the table of a configuration, the
/// arrays, and the walk's direction. A library step keeps, before its walk, the uniform damping
/// factors for the step length, and after it the damping_retention column's d^t as this
/// duration's (finish_step, which cannot know what a loop of the caller's did, forgets it).
/// So the next step of the same length computes no exponential, as after step.
struct SystemAccess {
  // A class template, not alias templates: an alias is checked for access where it is used.
  template <class System>
  struct TypesOf {
    using kernel = typename System::Kernel;
    using layout = typename System::Layout;
    using block = typename System::Block;
    using table = typename System::Table;
  };
  template <class System>
  using Kernel = typename TypesOf<System>::kernel;
  template <class System>
  using Layout = typename TypesOf<System>::layout;
  template <class System>
  static const typename System::Layout::Arrays& arrays(const System& system) noexcept {
    return system.State::arrays();
  }
  template <class System>
  static void arrays_changed(System& system) noexcept {
    system.forget_retention();
  }
  // A snapshot's reach (snapshot.hpp): the state whole, to read and to replace.
  template <class System>
  static void assign_state(System& to, const System& from) {
    to.State::assign_state(from);
  }
  template <class System>
  static const auto& handle_table(const System& system) noexcept {
    return system.handles_;
  }
  template <class System>
  static const auto& uniform_damping(const System& system) noexcept {
    return system.damping_;
  }
  template <class System>
  static const auto& uniform_acceleration(const System& system) noexcept {
    return system.acceleration_;
  }
  template <class System>
  static auto retention_duration(const System& system) noexcept {
    return system.retention_duration_;
  }
  template <class System, class Damping, class Acceleration, class R>
  static void install(System& system, typename TypesOf<System>::block&& block,
                      typename TypesOf<System>::table&& table, const Damping& damping,
                      const Acceleration& acceleration, R retention_duration) noexcept {
    system.block_ = std::move(block);
    system.handles_ = std::move(table);
    system.install_uniform(damping, acceleration, retention_duration);
  }
  template <class System>
  static bool next_step_backward(const System& system) noexcept {
    return system.backward_;
  }
  template <class System>
  static std::size_t handle_table_bytes(const System& system) noexcept {
    return system.Facets::handle_table_bytes();
  }
  template <class System, class R>
  static typename System::StepView begin_step(System& system, R duration) {
    return system.begin_view(duration, "step", true);
  }
  template <class System, class R>
  static typename System::Kernel::StepParameters step_parameters(const System& system,
                                                                 R duration) noexcept {
    return system.State::step_parameters(duration);
  }
  template <class System, class R>
  static typename System::Kernel::StepParameters keep_step_parameters(System& system, R duration) {
    return system.keep_step_parameters(duration);
  }
  template <class System, class OnExpire>
  static void finish_step(System& system, typename System::StepView&& view, OnExpire& on_expire) {
    const typename System::StepView finished(std::move(view));
    if (finished.size() == 0) return;
    system.record_retention(finished.parameters().duration);
    system.expire(on_expire);
  }
  template <class System>
  static void finish_step(System& system, typename System::StepView&& view) {
    NoExpiryCallback none;
    finish_step(system, std::move(view), none);
  }
};
}  // namespace detail

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
