// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/handle_table.hpp — the slot table behind a ParticleSystem's stable handles.
//
// Owns: the slots (slot -> particle index and generation), their free list, and the rule that
// makes an old handle never answer for a new particle. The particle side (particle -> slot) is
// the `handle_slot` column of the block (features.hpp), which swap-remove moves with its
// particle like any other column; the system tells the table where a moved particle went
// (relocate). Both directions are one array access: O(1).
//
// Generations: a slot's generation counts the deaths of the particles it has named, in G. A
// handle is {slot, generation at spawn}; find() answers only while the generation is still
// the same, so a handle goes dead with its particle and stays dead when the slot is reused.
// A slot whose generation reaches the largest G is retired: never put on the free list
// again, so no generation is ever issued twice for the same slot (with std::uint32_t after
// 4,294,967,295 lives of one slot, generations 0 to 2^32 - 2; a retired slot keeps its 8
// bytes in the table).
//
// Must not include: particle.hpp, particle_system.hpp (storage knows no physics).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "../config.hpp"
#include "../features.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

/// Stands in for the table when a configuration has no handles: stores nothing.
struct NoHandleTable {};

template <class G>
class HandleTable {
 public:
  using Handle = ParticleHandle<G>;
  /// No slot: the end of the free list, and the slot of a default handle.
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  /// Slot numbers and particle indices are 0 .. none - 1.
  static constexpr std::size_t max_slots = none;

  HandleTable() = default;
  HandleTable(const HandleTable&) = default;
  HandleTable& operator=(const HandleTable&) = default;
  /// A moved-from table is empty, free list included (a free list naming slots it no longer
  /// has would send its next acquire past the end of its slots).
  HandleTable(HandleTable&& other) noexcept
      : slots_(std::move(other.slots_)), free_(std::exchange(other.free_, none)) {
    other.slots_.clear();
  }
  HandleTable& operator=(HandleTable&& other) noexcept {
    slots_ = std::move(other.slots_);
    other.slots_.clear();
    free_ = std::exchange(other.free_, none);
    return *this;
  }
  ~HandleTable() = default;

  void reserve(std::size_t count) { slots_.reserve(count < max_slots ? count : max_slots); }
  [[nodiscard]] std::size_t slot_count() const noexcept { return slots_.size(); }
  /// Bytes the table holds (beside the block).
  [[nodiscard]] std::size_t bytes() const noexcept { return slots_.capacity() * sizeof(Slot); }

  /// A slot naming the particle at `index`: a freed slot if there is one, else a new one;
  /// `none` when every slot number is taken (the caller reports it). May allocate.
  std::uint32_t acquire(std::size_t index) {
    std::uint32_t slot = free_;
    if (slot != none) {
      free_ = slots_[slot].index;
    } else {
      if (slots_.size() >= max_slots) return none;
      slot = static_cast<std::uint32_t>(slots_.size());
      slots_.push_back(Slot{});
    }
    slots_[slot].index = static_cast<std::uint32_t>(index);
    return slot;
  }
  /// The particle of `slot` has died: every handle to it goes dead.
  void release(std::uint32_t slot) noexcept {
    Slot& s = slots_[slot];
    ++s.generation;
    if (s.generation == std::numeric_limits<G>::max()) return;  // retired: never reused
    s.index = free_;
    free_ = slot;
  }
  /// The particle of `slot` now lives at `index`.
  void relocate(std::uint32_t slot, std::size_t index) noexcept {
    slots_[slot].index = static_cast<std::uint32_t>(index);
  }
  [[nodiscard]] Handle handle(std::uint32_t slot) const noexcept {
    return {slot, slots_[slot].generation};
  }
  /// The index of the particle `handle` names, or nothing once it has died. A slot's
  /// generation changes at each death and no generation is issued twice, so an equal
  /// generation means the particle is alive.
  [[nodiscard]] std::optional<std::size_t> find(const Handle& handle) const noexcept {
    if (handle.slot >= slots_.size()) return std::nullopt;
    const Slot& s = slots_[handle.slot];
    if (s.generation != handle.generation) return std::nullopt;
    return std::size_t{s.index};
  }

  struct Slot {
    std::uint32_t index = 0;  // the particle's index while alive; the next free slot when free
    G generation = 0;
  };
  /// The slots and the free list's first slot, as a snapshot writes them and reads them back
  /// (snapshot.hpp checks that they agree with the particles before it installs them).
  [[nodiscard]] const std::vector<Slot>& slots() const noexcept { return slots_; }
  [[nodiscard]] std::uint32_t free_head() const noexcept { return free_; }
  HandleTable(std::vector<Slot> slots, std::uint32_t free) noexcept
      : slots_(std::move(slots)), free_(free) {}

 private:
  std::vector<Slot> slots_;
  std::uint32_t free_ = none;
};

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END
