// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/hash64.hpp — the 64-bit hash of state_hash and of a snapshot's check value.
//
// Owns: Hash64, XXH64 with seed 0 fed in pieces: the same value as XXH64 of the pieces
// joined, on every platform (it reads bytes, little-endian, whatever the host's order).
//
// Must not include: anything of the library but config.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "../config.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

class Hash64 {
 public:
  /// Feeds `size` bytes at `data` (null when size is 0).
  void update(const std::byte* data, std::size_t size) noexcept {
    total_ += size;
    if (buffered_ + size < stripe_bytes) {
      if (size != 0) std::memcpy(buffer_ + buffered_, data, size);
      buffered_ += size;
      return;
    }
    if (buffered_ != 0) {
      const std::size_t fill = stripe_bytes - buffered_;
      std::memcpy(buffer_ + buffered_, data, fill);
      stripe(buffer_);
      data += fill;
      size -= fill;
      buffered_ = 0;
    }
    for (; size >= stripe_bytes; data += stripe_bytes, size -= stripe_bytes) stripe(data);
    if (size != 0) std::memcpy(buffer_, data, size);
    buffered_ = size;
  }
  /// The hash of every byte fed so far.
  [[nodiscard]] std::uint64_t digest() const noexcept {
    std::uint64_t h = 0;
    if (total_ >= stripe_bytes) {
      h = rotl(lane_[0], 1) + rotl(lane_[1], 7) + rotl(lane_[2], 12) + rotl(lane_[3], 18);
      for (const std::uint64_t lane : lane_) h = (h ^ round(0, lane)) * p1 + p4;
    } else {
      h = p5;  // the seed, 0, plus p5
    }
    h += total_;
    const std::byte* tail = buffer_;
    std::size_t left = buffered_;
    for (; left >= 8; tail += 8, left -= 8) h = rotl(h ^ round(0, load<8>(tail)), 27) * p1 + p4;
    if (left >= 4) {
      h = rotl(h ^ (load<4>(tail) * p1), 23) * p2 + p3;
      tail += 4;
      left -= 4;
    }
    for (; left != 0; ++tail, --left) {
      h = rotl(h ^ (std::uint64_t{std::to_integer<std::uint8_t>(*tail)} * p5), 11) * p1;
    }
    h = (h ^ (h >> 33)) * p2;
    h = (h ^ (h >> 29)) * p3;
    return h ^ (h >> 32);
  }

 private:
  static constexpr std::size_t stripe_bytes = 32;
  static constexpr std::uint64_t p1 = 0x9E3779B185EBCA87u;
  static constexpr std::uint64_t p2 = 0xC2B2AE3D27D4EB4Fu;
  static constexpr std::uint64_t p3 = 0x165667B19E3779F9u;
  static constexpr std::uint64_t p4 = 0x85EBCA77C2B2AE63u;
  static constexpr std::uint64_t p5 = 0x27D4EB2F165667C5u;

  static constexpr std::uint64_t rotl(std::uint64_t x, int r) noexcept {
    return (x << r) | (x >> (64 - r));
  }
  static constexpr std::uint64_t round(std::uint64_t lane, std::uint64_t input) noexcept {
    return rotl(lane + input * p2, 31) * p1;
  }
  // N little-endian bytes (the shifts compile to one load on a little-endian host).
  template <int N>
  static std::uint64_t load(const std::byte* bytes) noexcept {
    std::uint64_t value = 0;
    for (int i = 0; i < N; ++i) {
      value |= std::uint64_t{std::to_integer<std::uint8_t>(bytes[i])} << (8 * i);
    }
    return value;
  }
  void stripe(const std::byte* data) noexcept {
    for (std::size_t i = 0; i < 4; ++i) lane_[i] = round(lane_[i], load<8>(data + 8 * i));
  }

  std::uint64_t lane_[4] = {p1 + p2, p2, 0, 0 - p1};  // XXH64's lanes for seed 0
  std::byte buffer_[stripe_bytes] = {};
  std::size_t buffered_ = 0;
  std::uint64_t total_ = 0;
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
