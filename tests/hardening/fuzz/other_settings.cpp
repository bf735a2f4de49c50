// SPDX-License-Identifier: BSL-1.0
// The fuzz target's second translation unit, built with the other checks setting (hot-path
// checks off, as a released library's): the target runs some operations on its systems
// through these functions, so a type or behaviour that differs between the settings shows
// as a difference from the target's model (or a sanitizer report). Built optimised
// (CMakeLists.txt), so that the library's code inlined here is this setting's copy.
#define POINTMASS_DISABLE_CHECKS 1
#include "fuzz_shared.hpp"

#if POINTMASS_CHECKS
#error "other_settings.cpp must be built with the checks off"
#endif

namespace fuzz {

template <class System>
std::size_t OtherSettings<System>::spawn(System& system, const pm::Vector3<W>& p,
                                         const pm::Vector3<R>& v) {
  return system.spawn(p, v);
}
template <class System>
std::size_t OtherSettings<System>::spawn(System& system, const pm::Vector3<W>& p,
                                         const pm::Vector3<R>& v, int owner) {
  return system.spawn(p, v, Fuse(owner));
}
template <class System>
void OtherSettings<System>::kill(System& system, std::size_t i) {
  system.kill(i);
}
template <class System>
void OtherSettings<System>::set_velocity(System& system, std::size_t i, const pm::Vector3<R>& v) {
  system.set_velocity(i, v);
}
template <class System>
void OtherSettings<System>::set_column(System& system, std::size_t i, int owner) {
  system.template set_column<FuzzOwner>(i, Fuse(owner));
}
template <class System>
void OtherSettings<System>::step(System& system, R duration) {
  system.step(duration);
}
template <class System>
void OtherSettings<System>::step_particles(System& system, R duration) {
  if (auto view = system.begin_step(duration)) {
    for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);
    system.finish_step(std::move(view));
  }
}
template <class System>
Read<System> OtherSettings<System>::read(const System& system, std::size_t i) {
  return {system.position(i), system.velocity(i), system.template column<FuzzOwner>(i).value,
          system.handle(i)};
}
template <class System>
std::size_t OtherSettings<System>::size(const System& system) {
  return system.size();
}

template struct OtherSettings<FuseFloat>;
template struct OtherSettings<FuseDouble>;
template struct OtherSettings<FuseExact>;
template struct OtherSettings<FuseCompensated>;

}  // namespace fuzz
