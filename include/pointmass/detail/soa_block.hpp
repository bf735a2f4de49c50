// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/soa_block.hpp — the one allocation that holds a ParticleSystem's arrays.
//
// Owns: the block's memory (allocation, release, growth, copy), its placement of the arrays,
// and the checked arithmetic of its size. It knows the arrays only through a layout's table
// (features.hpp: SystemLayout), so a new column needs nothing here.
//
// Placement: one allocation of `capacity` particles per array, every array in the same block,
// 64-byte aligned, each starting a multiple of 448 bytes (less beyond 9 arrays) further into
// its 4 KiB page than the one before. (Arrays that share their offset within a page make the
// loads of one alias the stores of another in the processor's 4 KiB store-forwarding check;
// staggering them measured up to 1.9x faster.)
//
// Must not include: particle.hpp, particle_system.hpp, the kernel (storage knows no physics).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "../config.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Layout>
class SoaBlock {
 public:
  using Arrays = typename Layout::Arrays;

  static constexpr std::size_t page = 4096;
  static constexpr std::size_t alignment = 64;
  static constexpr std::size_t stagger = 448 < page / Layout::array_count / alignment * alignment
                                             ? 448
                                             : page / Layout::array_count / alignment * alignment;

  /// The largest capacity whose block size is representable: every size computation below
  /// stays under PTRDIFF_MAX for any capacity up to this.
  static constexpr std::size_t max_capacity =
      (static_cast<std::size_t>(PTRDIFF_MAX) / Layout::array_count - 2 * page) /
      Layout::largest_element;

  SoaBlock() = default;
  SoaBlock(const SoaBlock&) = delete;
  SoaBlock& operator=(const SoaBlock&) = delete;
  SoaBlock(SoaBlock&& other) noexcept
      : block_(std::exchange(other.block_, nullptr)),
        arrays_(std::exchange(other.arrays_, Arrays{})),
        capacity_(std::exchange(other.capacity_, 0)) {}
  SoaBlock& operator=(SoaBlock&& other) noexcept {
    SoaBlock moved(std::move(other));
    swap(moved);
    return *this;
  }
  ~SoaBlock() { release(); }

  void swap(SoaBlock& other) noexcept {
    std::swap(block_, other.block_);
    std::swap(arrays_, other.arrays_);
    std::swap(capacity_, other.capacity_);
  }

  Arrays& arrays() noexcept { return arrays_; }
  [[nodiscard]] const Arrays& arrays() const noexcept { return arrays_; }
  [[nodiscard]] std::size_t size() const noexcept { return arrays_.size; }
  [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }

  /// A block of `capacity` particles holding a copy of this one's particles. The caller has
  /// checked capacity <= max_capacity and capacity >= size().
  [[nodiscard]] SoaBlock with_capacity(std::size_t capacity) const {
    SoaBlock grown;
    if (capacity == 0) return grown;
    grown.allocate(capacity);
    grown.copy_from(arrays_);
    return grown;
  }

  /// Copies other's particles into this block, which has room for them (capacity() >=
  /// other.size()).
  void copy_particles(const SoaBlock& other) noexcept { copy_from(other.arrays_); }

  /// Moves particle `from` into slot `to` (swap-remove's move), in every stored array.
  static void move_particle(const Arrays& arrays, std::size_t from, std::size_t to) noexcept {
    Layout::for_each_array(arrays, [&](auto* array) { array[to] = array[from]; });
  }

 private:
  static std::size_t array_span_bytes(std::size_t bytes) noexcept {
    return (bytes + page - 1) / page * page + stagger;
  }

  void allocate(std::size_t capacity) {
    std::size_t total = 0;
    Layout::for_each_array(
        arrays_, [&](auto* array) { total += array_span_bytes(capacity * sizeof(*array)); });
    block_ = static_cast<std::byte*>(::operator new (total, std::align_val_t{alignment}));
    capacity_ = capacity;
    std::size_t offset = 0;
    Layout::for_each_array(arrays_, [&](auto*& array) {
      using T = std::remove_reference_t<decltype(*array)>;
      array = reinterpret_cast<T*>(block_ + offset);
      offset += array_span_bytes(capacity * sizeof(T));
    });
  }

  // Copies source's particles (its size) into this block's arrays.
  void copy_from(const Arrays& source) noexcept {
    const std::size_t count = source.size;
    arrays_.size = count;
    if (count == 0) return;
    Layout::for_each_array_pair(arrays_, source, [&](auto* to, const auto* from) {
      std::memcpy(to, from, count * sizeof(*to));
    });
  }

  void release() noexcept {
    if (block_ != nullptr) ::operator delete (block_, std::align_val_t{alignment});
    block_ = nullptr;
  }

  std::byte* block_ = nullptr;
  Arrays arrays_{};
  std::size_t capacity_ = 0;
};

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END
