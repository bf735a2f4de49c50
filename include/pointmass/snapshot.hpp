// SPDX-License-Identifier: BSL-1.0
// pointmass/snapshot.hpp — a ParticleSystem's state saved, restored, hashed and sent as bytes,
// for replays, rollback and lockstep.
//
//   pointmass::Snapshot<System> saved(system);     // in memory: the copy of the arrays
//   saved.restore(system);                         // stepping on gives the same bits
//   std::uint64_t h = pointmass::state_hash(system);
//   std::vector<std::byte> bytes = pointmass::save_bytes(system);
//   pointmass::load_bytes(other, bytes);           // another machine, same configuration
//
// Owns: Snapshot, state_hash, save_bytes and load_bytes, and the byte format (docs/replay.md).
//
// Must not include: parallel.hpp, kokkos.hpp, units.hpp.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "detail/hash64.hpp"
#include "particle_system.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

namespace detail {

// The bytes of a T that carry its value: x87's 80-bit long double holds 10 of its 12 or 16
// (the rest is padding whose bits are whatever was there, and never enter a hash or a file).
template <class T>
inline constexpr std::size_t value_bytes =
    std::is_floating_point_v<T>&& std::numeric_limits<T>::digits == 64 && sizeof(T) > 10
        ? 10
        : sizeof(T);

// Where a snapshot's content goes: into the hash, or appended to bytes.
struct HashSink {
  Hash64 hash;
  void put(const void* data, std::size_t size) noexcept {
    hash.update(static_cast<const std::byte*>(data), size);
  }
};
struct CountSink {
  std::size_t size = 0;
  void put(const void*, std::size_t bytes) noexcept { size += bytes; }
};
struct ByteSink {
  std::byte* at;
  void put(const void* data, std::size_t size) noexcept {
    if (size != 0) std::memcpy(at, data, size);
    at += size;
  }
};

// Reads a snapshot's bytes in order; `ok` turns false (and stays) at the first read past
// the end, which then reads zeros.
struct ByteSource {
  std::span<const std::byte> bytes;
  bool ok = true;
  void get(void* data, std::size_t size) noexcept {
    if (size > bytes.size()) {
      ok = false;
      std::memset(data, 0, size);
      return;
    }
    if (size != 0) std::memcpy(data, bytes.data(), size);
    bytes = bytes.subspan(size);
  }
};

template <class Sink, class T>
void put_values(Sink& sink, const T* values, std::size_t count) {
  if constexpr (value_bytes<T> == sizeof(T)) {
    if (count != 0) sink.put(values, count * sizeof(T));
  } else {
    for (std::size_t i = 0; i < count; ++i) sink.put(values + i, value_bytes<T>);
  }
}
template <class T>
void get_values(ByteSource& source, T* values, std::size_t count) noexcept {
  if constexpr (value_bytes<T> == sizeof(T)) {
    source.get(values, count * sizeof(T));
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      std::memset(values + i, 0, sizeof(T));
      source.get(values + i, value_bytes<T>);
    }
  }
}
template <class Sink, class T>
void put_value(Sink& sink, const T& value) {
  put_values(sink, &value, 1);
}
template <class T>
T get_value(ByteSource& source) noexcept {
  T value{};
  get_values(source, &value, 1);
  return value;
}

// The library's policies by name; a policy of the user's by its state's size only.
template <class Policy>
constexpr const char* policy_name() noexcept {
  using namespace pointmass;
  if constexpr (std::is_same_v<Policy, damping::None>) return "damping::None";
  else if constexpr (std::is_same_v<Policy, damping::PerFrame>) return "damping::PerFrame";
  else if constexpr (std::is_same_v<Policy, damping::PerSecond>) return "damping::PerSecond";
  else if constexpr (std::is_same_v<Policy, damping::Exact>) return "damping::Exact";
  else if constexpr (std::is_same_v<Policy, damping::AccelerateThenDamp>) return "damping::ATD";
  else if constexpr (std::is_same_v<Policy, position::Euler>) return "position::Euler";
  else if constexpr (std::is_same_v<Policy, position::ConstantAcceleration>) return "position::CA";
  else if constexpr (std::is_same_v<Policy, position::SemiImplicit>) return "position::SI";
  else if constexpr (std::is_same_v<Policy, position::VelocityVerlet>) return "position::VV";
  else if constexpr (std::is_same_v<Policy, position::Exact>) return "position::Exact";
  else return "user policy";
}

/// The byte format and the hash of one configuration (docs/replay.md).
template <class System>
class SnapshotFormat {
  using Access = SystemAccess;
  using Layout = Access::Layout<System>;
  using Block = typename Access::TypesOf<System>::block;
  using Table = typename Access::TypesOf<System>::table;
  using R = typename System::real;
  using damping_state = typename System::damping_policy::template State<R>;
  static constexpr bool uniform_acceleration = !Layout::per_particle_acceleration;
  static constexpr bool uniform_damping =
      !std::is_empty_v<damping_state> && !Layout::per_particle_damping;
  template <class T>
  struct SlotOf {
    struct type {
      std::uint32_t index;
      std::uint8_t generation;
    };
  };
  template <class G>
  struct SlotOf<HandleTable<G>> {
    using type = typename HandleTable<G>::Slot;
  };
  using Slot = typename SlotOf<Table>::type;
  static_assert(std::endian::native == std::endian::little,
                "pointmass snapshots are little-endian: this host is not");
  static_assert(std::is_trivially_copyable_v<damping_state>,
                "a snapshot stores a damping policy's state as its bytes: make it trivially "
                "copyable");

 public:
  static constexpr std::uint64_t magic = 0x0A0D50414E534D50u;  // "PMSNAP\r\n"
  static constexpr std::uint32_t version = 1;
  static constexpr std::size_t header_bytes = 32;  // magic, version, 0, configuration, length

  /// The configuration's fingerprint: its numbers' sizes and digits, its policies, and each
  /// column it stores with its element's size.
  static std::uint64_t configuration() noexcept {
    HashSink sink;
    const auto real = [&](auto x) {
      using T = decltype(x);
      put_value(sink, std::uint32_t{sizeof(T)});
      put_value(sink, std::uint32_t{std::numeric_limits<T>::digits});
    };
    real(R{});
    real(typename Layout::position_element{});
    for (const char* name : {policy_name<typename System::damping_policy>(),
                             policy_name<typename System::position_policy>()}) {
      sink.put(name, std::strlen(name) + 1);
    }
    put_value(sink, std::uint32_t{sizeof(damping_state)});
    std::apply(
        [&](auto... entry) {
          (put_value(sink, std::uint32_t{decltype(entry)::stored
                                             ? sizeof(decltype(element_of(decltype(entry)::member)))
                                             : 0u}),
           ...);
        },
        Layout::columns);
    typename Layout::Arrays none{};
    Layout::for_each_array(none,
                           [&](auto* array) { put_value(sink, std::uint32_t{sizeof(*array)}); });
    if constexpr (Layout::has_handles) {
      put_value(sink, std::uint32_t{sizeof(typename Layout::handles::generation_type)});
    }
    return sink.hash.digest();
  }

  /// What the hash covers, in order: the count, the uniform values, each stored column's
  /// live values in block order, and each handle slot's generation.
  template <class Sink>
  static void write_state(const System& system, Sink& sink) {
    const std::size_t n = system.size();
    put_value(sink, std::uint64_t{n});
    if constexpr (uniform_acceleration) {
      const auto& a = Access::uniform_acceleration(system);
      put_value(sink, a.x);
      put_value(sink, a.y);
      put_value(sink, a.z);
    }
    if constexpr (uniform_damping) {
      if constexpr (Layout::value_damping_state) {  // d alone: its state is made from d
        put_value(sink, Access::uniform_damping(system).value());
      } else {
        put_value(sink, Access::uniform_damping(system));
      }
    }
    Layout::for_each_array(Access::arrays(system),
                           [&](const auto* array) { put_values(sink, array, n); });
    if constexpr (Layout::has_handles) {
      const auto& slots = Access::handle_table(system).slots();
      put_value(sink, std::uint64_t{slots.size()});
      for (const auto& slot : slots) put_value(sink, slot.generation);
    }
  }

  static void save(const System& system, std::vector<std::byte>& out) {
    CountSink body;
    write_body(system, body);
    out.resize(header_bytes + body.size + 8);
    ByteSink sink{out.data()};
    put_value(sink, magic);
    put_value(sink, version);
    put_value(sink, std::uint32_t{0});
    put_value(sink, configuration());
    put_value(sink, std::uint64_t{body.size});
    write_body(system, sink);
    HashSink check;
    check.put(out.data(), out.size() - 8);
    put_value(sink, check.hash.digest());
  }

  static bool load(System& system, std::span<const std::byte> bytes) {
    const std::size_t size = bytes.size();
    if (size < header_bytes + 8) {
      return refuse("bytes.size()", ">= 40, a header and a check value (truncated)", size);
    }
    ByteSource header{bytes.first(header_bytes)};
    const auto found_magic = get_value<std::uint64_t>(header);
    const auto found_version = get_value<std::uint32_t>(header);
    static_cast<void>(get_value<std::uint32_t>(header));
    const auto found_configuration = get_value<std::uint64_t>(header);
    const auto body = get_value<std::uint64_t>(header);
    if (found_magic != magic)
      return refuse("magic", "PMSNAP, CR, LF (not a snapshot)", found_magic);
    if (found_version != version)
      return refuse("version", "1, the one this library reads", found_version);
    if (found_configuration != configuration()) {
      return refuse("configuration", "this system's (a snapshot of another configuration)",
                    found_configuration);
    }
    if (body != size - header_bytes - 8) {
      return refuse("bytes.size()", "the length the header gives (truncated or extended)", size);
    }
    HashSink check;
    check.put(bytes.data(), size - 8);
    ByteSource trailer{bytes.last(8)};
    if (get_value<std::uint64_t>(trailer) != check.hash.digest()) {
      return refuse("check value", "the hash of the bytes before it (corrupted)",
                    check.hash.digest());
    }
    return read_body(system, ByteSource{bytes.subspan(header_bytes, size - header_bytes - 8)});
  }

 private:
  // The state, then what restores it but is not hashed: the retention column's step length,
  // and the handle table's free list (its first slot, then each slot's link).
  template <class Sink>
  static void write_body(const System& system, Sink& sink) {
    write_state(system, sink);
    put_value(sink, Access::retention_duration(system));
    if constexpr (Layout::has_handles) {
      const auto& table = Access::handle_table(system);
      put_value(sink, table.free_head());
      for (const auto& slot : table.slots()) put_value(sink, slot.index);
    }
  }

  [[gnu::cold]] static bool refuse(const char* what, const char* requirement, std::uint64_t value) {
    report_scalar("load_bytes", what, requirement, value);
    return false;
  }

  // Reads the state into new memory, checks it, then installs it (nothing changes before).
  static bool read_body(System& system, ByteSource source) {
    const auto count = get_value<std::uint64_t>(source);
    if (count > System::max_size()) return refuse("size", "<= max_size()", count);
    const auto n = static_cast<std::size_t>(count);
    if (source.bytes.size() / written_per_particle() < n) {
      return refuse("size", "the particles the snapshot holds (a damaged count)", count);
    }
    Vector3<R> acceleration{};
    if constexpr (uniform_acceleration) {
      acceleration.x = get_value<R>(source);
      acceleration.y = get_value<R>(source);
      acceleration.z = get_value<R>(source);
    }
    damping_state damping{};
    if constexpr (uniform_damping) {
      if constexpr (Layout::value_damping_state) {
        damping = damping_state(get_value<R>(source));
      } else {
        damping = get_value<damping_state>(source);
      }
    }
    Block block = Block().with_capacity(n);
    block.arrays().size = n;
    Layout::for_each_array(block.arrays(), [&](auto* array) { get_values(source, array, n); });
    std::vector<Slot> slots;  // (none without handles)
    if constexpr (Layout::has_handles) {
      const auto slot_count = get_value<std::uint64_t>(source);
      if (slot_count > Table::max_slots ||
          source.bytes.size() / (sizeof(Slot::generation) + 4) < slot_count) {
        return refuse("slots", "<= the handle slots the snapshot holds (damaged)", slot_count);
      }
      slots.resize(static_cast<std::size_t>(slot_count));
      for (auto& slot : slots) slot.generation = get_value<decltype(slot.generation)>(source);
    }
    const R retention_duration = get_value<R>(source);
    [[maybe_unused]] std::uint32_t free = 0;
    if constexpr (Layout::has_handles) {
      free = get_value<std::uint32_t>(source);
      for (auto& slot : slots) slot.index = get_value<std::uint32_t>(source);
    }
    if (!source.ok || !source.bytes.empty()) {
      return refuse("size", "the particles the snapshot holds (a damaged count)", count);
    }
    Table table{};
    if constexpr (Layout::has_handles) {
      if (!consistent(block.arrays(), slots, free)) {
        return refuse("slots", "consistent with the particles (a damaged handle table)",
                      slots.size());
      }
      table = Table(std::move(slots), free);
    }
    Access::install(system, std::move(block), std::move(table), damping, acceleration,
                    retention_duration);
    return true;
  }

  // The bytes a particle's columns take in the format.
  static std::size_t written_per_particle() noexcept {
    std::size_t bytes = 0;
    typename Layout::Arrays none{};
    Layout::for_each_array(
        none, [&](auto* array) { bytes += value_bytes<std::remove_cvref_t<decltype(*array)>>; });
    return bytes;
  }

  // True when each slot is exactly one of: a live particle's (whose index names it back), on
  // the free list (reached once), retired (its generation the largest); only a retired slot
  // has the largest generation.
  static bool consistent(const typename Layout::Arrays& arrays, const std::vector<Slot>& slots,
                         std::uint32_t free) {
    using G = decltype(Slot::generation);
    enum class Seen : unsigned char { no, live, listed };
    std::vector<Seen> seen(slots.size(), Seen::no);
    const auto usable = [&](std::size_t s) {
      return s < slots.size() && seen[s] == Seen::no &&
             slots[s].generation != std::numeric_limits<G>::max();
    };
    for (std::size_t i = 0; i < arrays.size; ++i) {
      const std::uint32_t s = arrays.handle_slot[i];
      if (!usable(s) || slots[s].index != i) return false;
      seen[s] = Seen::live;
    }
    for (std::uint32_t s = free; s != Table::none; s = slots[s].index) {
      if (!usable(s)) return false;
      seen[s] = Seen::listed;
    }
    for (std::size_t s = 0; s < slots.size(); ++s) {
      if (seen[s] == Seen::no && slots[s].generation != std::numeric_limits<G>::max()) {
        return false;
      }
    }
    return true;
  }
};

}  // namespace detail

/// 64-bit hash of `system`'s state: XXH64 (seed 0) of its live particles' columns, its
/// uniform values and its handles' generations, in the order docs/replay.md gives; not its
/// capacity nor the order of its free handle slots. The same on every platform for the same
/// bits.
template <class S, class D, class P, class... Features>
[[nodiscard]] std::uint64_t state_hash(const ParticleSystem<S, D, P, Features...>& system) {
  detail::HashSink sink;
  detail::SnapshotFormat<ParticleSystem<S, D, P, Features...>>::write_state(system, sink);
  return sink.hash.digest();
}

/// `system`'s state as bytes (docs/replay.md), into `out` (its memory reused).
template <class S, class D, class P, class... Features>
void save_bytes(const ParticleSystem<S, D, P, Features...>& system, std::vector<std::byte>& out) {
  detail::SnapshotFormat<ParticleSystem<S, D, P, Features...>>::save(system, out);
}
/// `system`'s state as bytes (docs/replay.md).
template <class S, class D, class P, class... Features>
[[nodiscard]] std::vector<std::byte> save_bytes(
    const ParticleSystem<S, D, P, Features...>& system) {
  std::vector<std::byte> out;
  save_bytes(system, out);
  return out;
}

/// Replaces `system`'s state with the one `bytes` hold (save_bytes of a system of the same
/// configuration, on any machine). Bad bytes (truncated, another configuration or version,
/// a check value that does not match, a damaged count or handle table) are reported through
/// the contract handler, naming what is wrong, and leave `system` as it was: false.
template <class S, class D, class P, class... Features>
bool load_bytes(ParticleSystem<S, D, P, Features...>& system, std::span<const std::byte> bytes) {
  return detail::SnapshotFormat<ParticleSystem<S, D, P, Features...>>::load(system, bytes);
}

/// A system's whole state held in memory (its arrays, uniform values and handle table):
/// restore() makes a system of the same configuration what it was at save(), so that it
/// steps on to the same bits. save and restore reuse the memory they have: after the first,
/// a save or restore of no more particles than before copies and allocates nothing more.
template <class System>
class Snapshot;

template <class S, class D, class P, class... Features>
class Snapshot<ParticleSystem<S, D, P, Features...>> {
 public:
  using system_type = ParticleSystem<S, D, P, Features...>;

  Snapshot() = default;
  explicit Snapshot(const system_type& system) { save(system); }

  /// Holds `system`'s state (all or nothing).
  void save(const system_type& system) { detail::SystemAccess::assign_state(state_, system); }
  /// Gives `system` the state saved (all or nothing; a removal pass under way ends, as after
  /// an assignment).
  void restore(system_type& system) const { detail::SystemAccess::assign_state(system, state_); }
  /// The number of particles saved.
  [[nodiscard]] std::size_t size() const noexcept { return state_.size(); }
  /// state_hash of the state saved.
  [[nodiscard]] std::uint64_t hash() const { return state_hash(state_); }

 private:
  system_type state_;
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
