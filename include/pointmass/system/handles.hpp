// SPDX-License-Identifier: BSL-1.0
// pointmass/system/handles.hpp — a ParticleSystem's stable handles (features::Handles).
//
//   const auto h = system.handle(i);      i's name for as long as it lives
//   if (const auto i = system.find(h)) system.kill(*i);
//
// SystemHandles<Base> is a facet of ParticleSystem: a class template over the state below it
// that adds members and no data, so a system is no bigger for it; an implementation
// detail, whose public members ParticleSystem re-exports (a user never names it).
// Its members exist only with features::Handles (or BasicHandles<G>).
// spawn_handle is ParticleSystem's own, beside the other spawns.
//
// Owns: the Handle type and handle, find, contains and handle_table_bytes.
// Must not include: particle_system.hpp, detail/system_state.hpp or another facet (it uses
// only Base's arrays(), size(), valid_index() and handle table; the table is
// detail/handle_table.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "../config.hpp"
#include "../detail/handle_table.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemHandles : public Base {
 public:
  /// A particle's stable name (features::Handles): see handle() and find().
  using Handle = typename std::conditional_t<Base::Layout::has_handles, typename Base::Table,
                                             detail::HandleTable<std::uint32_t>>::Handle;

  /// The handle of particle i: it finds this particle for as long as it lives. O(1).
  [[nodiscard]] Handle handle(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) requires Base::Layout::has_handles {
    return this->valid_index("handle", i) ? this->handles_.handle(this->arrays().handle_slot[i])
                                          : Handle{};
  }
  /// The current index of the particle `handle` names, or nothing once it has died. O(1).
  /// A slot answers only for the particle that names it back: a free slot (which already
  /// holds its next particle's generation, and a free-list link where a live slot holds the
  /// index) matches a handle issued by a copy of this system, or by this system before it was
  /// assigned an earlier state, and must not answer for it.
  [[nodiscard]] std::optional<std::size_t> find(
      const Handle& handle) const noexcept requires Base::Layout::has_handles {
    const std::optional<std::size_t> i = this->handles_.find(handle);
    if (i && *i < this->size() && this->arrays().handle_slot[*i] == handle.slot) return i;
    return std::nullopt;
  }
  /// True while the particle `handle` names is alive.
  [[nodiscard]] bool contains(
      const Handle& handle) const noexcept requires Base::Layout::has_handles {
    return find(handle).has_value();
  }
  /// Bytes of the slot table beside the block (8 a slot with std::uint32_t generations).
  [[nodiscard]] std::size_t handle_table_bytes() const noexcept requires Base::Layout::has_handles {
    return this->handles_.bytes();
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
