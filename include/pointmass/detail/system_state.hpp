// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/system_state.hpp — what a ParticleSystem holds, and the mechanics behind
// its public API.
//
// Owns: the system's data (the block of arrays, the uniform damping and acceleration, the
// handle table, the walk direction and the removal pass under way), its copy, move and swap;
// capacity and growth; appending and swap-removing a particle (with its handle); reading and
// writing a particle's position in the configuration's precision (precision.hpp), and its
// previous position (features::Interpolation); the user columns at spawn. Above it,
// detail/system_passes.hpp: the step, the passes that call the user's code, the copy-out.
// particle_system.hpp is the public face and says what each call means; here is how.
//
// Must not include: particle_system.hpp, parallel.hpp, detail/system_passes.hpp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../damping.hpp"
#include "../features.hpp"
#include "../particle.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "handle_table.hpp"
#include "soa_block.hpp"
#include "system_substeps.hpp"
#include "validate.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {
// What parallel.hpp's step reaches beyond a system's public API (a friend of ParticleSystem).
struct SystemAccess;

template <class S, DampingPolicy D, class P, class... Features>
class SystemState {
 protected:
  using R = real_of_t<S>;
  using Layout = std::conditional_t<kicks_v<P>, SystemLayout<S, D, Features..., Kicks>,
                                    SystemLayout<S, D, Features...>>;
  using Kernel = SubstepKernel<R, D, P, Layout>;
  using Storage = typename Layout::position_storage;
  using Block = SoaBlock<Layout>;
  using Arrays = typename Layout::Arrays;
  using StepParameters = typename Kernel::StepParameters;
  using damping_state = typename D::template State<R>;
  // True when a step keeps its uniform damping factors and length (-1 before the first step
  // and after set_damping), so that the next step of the same length computes no exponential,
  // as a Particle does; with per-particle damping the damping_retention column holds each
  // particle's retention instead.
  static constexpr bool keeps_factors = !Layout::per_particle_damping && keeps_factors_v<D, R>;
  using position_value = typename Storage::value;
  using user_columns = typename Layout::user_columns;
  static constexpr std::size_t user_column_count = Layout::user_column_count;
  static constexpr bool has_handles = Layout::has_handles;
  static constexpr bool has_interpolation = Layout::has_interpolation;
  static constexpr bool compensated = Layout::compensated_positions;
  using Table = std::conditional_t<
      has_handles,
      HandleTable<typename handles_of<Features..., features::Handles>::type::generation_type>,
      NoHandleTable>;
  static_assert(((is_handles<Features>::value ? 1 : 0) + ... + 0) <= 1,
                "ParticleSystem: at most one features::Handles / BasicHandles<G>");
  template <std::size_t... I>
  static constexpr bool unique_tags(std::index_sequence<I...>) {
    return (
        (Layout::template user_index<typename std::tuple_element_t<I, user_columns>::tag> == I) &&
        ...);
  }
  static_assert(unique_tags(std::make_index_sequence<user_column_count>{}),
                "ParticleSystem: two features::Column<Tag, T> with the same Tag");

  // --- data, copy, move, swap ----------------------------------------------------------------

  SystemState() = default;
  // A copy has the same particles, capacity and uniform values, and starts walking forwards.
  SystemState(const SystemState& other)
      : block_(other.block_.with_capacity(other.capacity())),
        damping_(other.damping_),
        acceleration_(other.acceleration_),
        handles_(other.handles_),
        retention_duration_(other.retention_duration_),
        kept_(other.kept_) {}
  SystemState(SystemState&& other) noexcept
      : block_(std::move(other.block_)),
        backward_(std::exchange(other.backward_, false)),
        damping_(other.damping_),
        acceleration_(other.acceleration_),
        handles_(std::move(other.handles_)),
        retention_duration_(other.retention_duration_),
        kept_(other.kept_) {
    ++other.replacements_;  // its particles left with the move
  }

 public:
  SystemState& operator=(const SystemState&) = delete;  // the system assigns by swap
  SystemState& operator=(SystemState&&) = delete;

 protected:
  ~SystemState() = default;

  void swap_state(SystemState& other) noexcept {
    block_.swap(other.block_);
    std::swap(backward_, other.backward_);
    std::swap(damping_, other.damping_);
    std::swap(acceleration_, other.acceleration_);
    std::swap(handles_, other.handles_);
    std::swap(retention_duration_, other.retention_duration_);
    std::swap(kept_, other.kept_);
    ++replacements_;
    ++other.replacements_;
  }

  // This system takes other's state (a snapshot's save and restore), in its own memory where
  // that has room. All or nothing: what may allocate comes first (the table's slots are
  // trivially copyable, so their assignment changes nothing when it throws).
  void assign_state(const SystemState& other) {
    if (this == &other) return;
    Block grown = capacity() < other.size() ? other.block_.with_capacity(other.size()) : Block{};
    handles_ = other.handles_;
    if (grown.capacity() != 0) block_ = std::move(grown);
    else block_.copy_particles(other.block_);
    install_uniform(other.damping_, other.acceleration_, other.retention_duration_);
    kept_ = other.kept_;
  }
  // The uniform values a snapshot holds; the kept factors are recomputed (the same bits).
  void install_uniform(const damping_state& damping, const Vector3<R>& acceleration,
                       R retention_duration) noexcept {
    damping_ = damping;
    acceleration_ = acceleration;
    retention_duration_ = retention_duration;
    kept_ = {};
    ++replacements_;  // as a swap: a removal pass under way ends
  }

  Block block_;
  bool backward_ = false;  // the next step walks backwards (see Kernel::alternates)
  RemovalPass removing_ = RemovalPass::none;  // inside a pass that removes particles
  // Counts (modulo 2^16: it fits beside the two flags) the times the particles were replaced
  // whole (swap, and so assignment; moved from), so that a removal pass whose callback did so
  // ends there.
  std::uint16_t replacements_ = 0;
  [[no_unique_address]] damping_state damping_{};
  Vector3<R> acceleration_{};
  [[no_unique_address]] Table handles_{};
  // The step length the damping_retention column holds the retention for (features.hpp);
  // -1: none.
  R retention_duration_ = R(-1);
  [[no_unique_address]] std::conditional_t<keeps_factors, KeptFactors<D, R>, NoKeptFactors> kept_{};

  // --- size and capacity ---------------------------------------------------------------------

  [[nodiscard]] std::size_t size() const noexcept { return block_.size(); }
  [[nodiscard]] std::size_t capacity() const noexcept { return block_.capacity(); }
  [[nodiscard]] const Arrays& arrays() const noexcept { return block_.arrays(); }
  void set_size(std::size_t size) noexcept { block_.arrays().size = size; }

  static constexpr std::size_t max_size() noexcept {
    if constexpr (has_handles) {  // slots and indices are 32-bit (handle_table.hpp)
      return std::min(Block::max_capacity, Table::max_slots);
    } else {
      return Block::max_capacity;
    }
  }
  // `argument` = value must be `requirement` ("<= max_size()"), whose bound is `limit`.
  [[noreturn]] static void throw_length_error(const char* function, const char* argument,
                                              std::size_t value, const char* requirement,
                                              std::size_t limit) {
#if POINTMASS_HAS_EXCEPTIONS
    throw std::length_error(std::string("pointmass: ") + function + ": argument '" + argument +
                            "' = " + std::to_string(value) + " must be " + requirement + " = " +
                            std::to_string(limit));
#else
    static_cast<void>(limit);
    report_scalar(function, argument, requirement, value);
    std::abort();
#endif
  }
  [[noreturn]] static void throw_length_error(const char* function, std::size_t capacity) {
    throw_length_error(function, "capacity", capacity, "<= max_size()", max_size());
  }
  // All or nothing: the new block is allocated before the handle table grows, so a failed
  // allocation of either leaves the system as it was.
  void reserve_checked(std::size_t capacity) {
    if (capacity <= this->capacity()) return;
    if (capacity > max_size()) throw_length_error("reserve", capacity);
    Block grown = block_.with_capacity(capacity);
    if constexpr (has_handles) handles_.reserve(capacity);
    block_ = std::move(grown);
  }
  // Full: doubles the capacity (at least 16), up to max_size() (the first 16 too: a user
  // column of huge elements can make max_size() smaller).
  void grow() {
    const std::size_t current = capacity();
    if (current >= max_size()) throw_length_error("spawn", current + 1);
    const std::size_t doubled = current < 8                ? 16
                                : current > max_size() / 2 ? max_size()
                                                           : 2 * current;
    reserve_checked(std::min(doubled, max_size()));
  }
  // Room for `count` more particles at once (a burst): at least doubling, as grow() would.
  void make_room(std::size_t count) {
    if (count > max_size() - size()) {
      throw_length_error("spawn_burst", "count", count, "<= max_size() - size()",
                         max_size() - size());
    }
    if (size() + count > capacity()) {
      reserve_checked(std::max(size() + count, std::min(2 * capacity(), max_size())));
    }
  }

  bool valid_index([[maybe_unused]] const char* function, [[maybe_unused]] std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) {
#if POINTMASS_HOST_CHECKS
    return check_index(function, i, size());
#else
    return true;
#endif
  }

  // --- adding and removing -------------------------------------------------------------------

  // A spawn's position and velocity: finite (and within a compensated position's range).
  static bool valid_spawn(const Vector3<position_value>& position, const Vector3<R>& velocity) {
    return valid_position("spawn", position) && check_finite("spawn", "velocity", velocity);
  }
  // Appends a particle (input already validated): position, velocity, a default Particle's
  // per-particle values, a handle slot, and the user columns' values (T{} for each when none
  // are given). Returns its index. All or nothing: the user columns' values are made first
  // (a constructor may throw), then the room and the slot; storing cannot throw.
  template <class... Values>
  std::size_t append(const Vector3<position_value>& position, const Vector3<R>& velocity,
                     const Values&... values) {
    const UserValues columns(values...);
    if (size() == capacity()) grow();
    const std::size_t i = size();
    std::uint32_t slot = 0;
    if constexpr (has_handles) {
      slot = handles_.acquire(i);
      if (slot == Table::none) throw_length_error("spawn", Table::max_slots + 1);
    }
    set_size(i + 1);
    const Arrays& a = arrays();
    store_position(i, position);
    if constexpr (has_handles) a.handle_slot[i] = slot;
    store(a.velocity_x, a.velocity_y, a.velocity_z, i, velocity);
    if constexpr (Layout::per_particle_acceleration) {
      store(a.acceleration_x, a.acceleration_y, a.acceleration_z, i, {});
    }
    if constexpr (Layout::has_forces) {
      a.inverse_mass[i] = R(1);
      store(a.force_x, a.force_y, a.force_z, i, {});
    }
    if constexpr (Layout::per_particle_damping) store_damping(i, damping_state{});
    if constexpr (Layout::has_lifetime) {
      a.age[i] = R(0);
      a.age_error[i] = R(0);
      a.lifetime[i] = real_infinity<R>;
    }
    if constexpr (Layout::has_kicks) {
      store(a.kick_x, a.kick_y, a.kick_z, i, {});
      a.kick_half_step[i] = R(0);
    }
    store_user_columns(i, columns, std::make_index_sequence<user_column_count>{});
    return i;
  }
  // Particle i takes what `particle` has and the system stores per particle: its stored
  // position bits (wide or compensated), acceleration, inverse mass, force and damping.
  void store_particle(std::size_t i, const Particle<S, D, P>& particle) {
    const Arrays& a = arrays();
    if constexpr (!std::is_same_v<position_precision_of_t<S>, R>) {  // the stored numbers
      store(a.position_x, a.position_y, a.position_z, i, particle.stored_position());
      if constexpr (compensated) {
        store(a.position_error_x, a.position_error_y, a.position_error_z, i,
              particle.stored_position_error());
      }
      store_previous_position(i);
    }
    if constexpr (Layout::per_particle_acceleration) {
      store(a.acceleration_x, a.acceleration_y, a.acceleration_z, i, particle.acceleration());
    }
    if constexpr (Layout::has_forces) {
      a.inverse_mass[i] = particle.inverse_mass();
      store(a.force_x, a.force_y, a.force_z, i, particle.force_accumulator());
    }
    if constexpr (Layout::per_particle_damping) store_damping(i, damping_state(particle.damping()));
    if constexpr (Layout::has_kicks) {
      store(a.kick_x, a.kick_y, a.kick_z, i, particle.credited_kick());
      a.kick_half_step[i] = particle.credited_half_step();
    }
  }
  // Particle i's damping state, and its retention for retention_duration_ (the same
  // function and inputs as the step's refresh, so the same bits).
  void store_damping(std::size_t i, const damping_state& state) noexcept {
    const Arrays& a = arrays();
    if constexpr (Layout::value_damping_state) {
      a.damping[i] = state.value();
    } else {
      a.damping[i] = state;
    }
    if constexpr (Layout::log_damping_state) {
      a.damping_log_hi[i] = state.split_log().hi;
      a.damping_log_lo[i] = state.split_log().lo;
    }
    if constexpr (Layout::per_particle_retention) {
      if (retention_duration_ >= R(0)) Kernel::refresh_retention(arrays(), i, retention_duration_);
    }
  }
  // One value for each user column (a tuple: value-initialised, T{}, when none is given).
  template <std::size_t... I>
  static auto user_values(std::index_sequence<I...>)
      -> std::tuple<typename Layout::template user_element_t<I>...>;
  using UserValues = decltype(user_values(std::make_index_sequence<user_column_count>{}));
  // The user columns of particle i (trivially copyable: the assignments cannot throw).
  template <std::size_t... I>
  void store_user_columns([[maybe_unused]] std::size_t i, [[maybe_unused]] const UserValues& values,
                          std::index_sequence<I...>) {
    ((Layout::template user_pointer<I>(arrays())[i] = std::get<I>(values)), ...);
  }

  // Swap-remove: the last particle (and its handle slot) moves into `index`.
  void remove(std::size_t index) noexcept {
    const std::size_t last = size() - 1;
    if constexpr (has_handles) handles_.release(arrays().handle_slot[index]);
    if (index != last) {
      Block::move_particle(arrays(), last, index);
      if constexpr (has_handles) handles_.relocate(arrays().handle_slot[index], index);
    }
    set_size(last);
  }
  void remove_all() noexcept {
    if constexpr (has_handles) {
      for (std::size_t i = 0; i < size(); ++i) handles_.release(arrays().handle_slot[i]);
    }
    set_size(0);
  }
  // --- values by index -----------------------------------------------------------------------

  template <class T>
  static void store(T* x, T* y, T* z, std::size_t i, const Vector3<T>& value) noexcept {
    x[i] = value.x;
    y[i] = value.y;
    z[i] = value.z;
  }
  template <class T>
  static Vector3<T> load(const T* x, const T* y, const T* z, std::size_t i) noexcept {
    return {x[i], y[i], z[i]};
  }

  // A finite position (for Compensated<R>, also within R's range).
  static bool valid_position(const char* function, const Vector3<position_value>& position) {
    if (!check_finite(function, "position", position)) return false;
    if constexpr (compensated) {
      return check_representable(function, "position", position, hi_of(position));
    } else {
      return true;
    }
  }
  static Vector3<R> hi_of(const Vector3<position_value>& p) noexcept {
    return {Storage::element_of(p.x), Storage::element_of(p.y), Storage::element_of(p.z)};
  }
  void store_position(std::size_t i, const Vector3<position_value>& position) noexcept {
    const Arrays& a = arrays();
    if constexpr (compensated) {
      store(a.position_x, a.position_y, a.position_z, i, hi_of(position));
      store(a.position_error_x, a.position_error_y, a.position_error_z, i,
            Vector3<R>{Storage::error_of(position.x), Storage::error_of(position.y),
                       Storage::error_of(position.z)});
    } else {
      store(a.position_x, a.position_y, a.position_z, i, position);
    }
    store_previous_position(i);  // a jump, not a motion to draw
  }
  // The previous position (features::Interpolation) := the stored position column.
  void store_previous_position([[maybe_unused]] std::size_t i) noexcept {
    if constexpr (has_interpolation) {
      const Arrays& a = arrays();
      a.previous_position_x[i] = a.position_x[i];
      a.previous_position_y[i] = a.position_y[i];
      a.previous_position_z[i] = a.position_z[i];
    }
  }
  [[nodiscard]] Vector3<position_value> load_position(std::size_t i) const noexcept {
    const Arrays& a = arrays();
    if constexpr (compensated) {
      return {Storage::value_of(a.position_x[i], a.position_error_x[i]),
              Storage::value_of(a.position_y[i], a.position_error_y[i]),
              Storage::value_of(a.position_z[i], a.position_error_z[i])};
    } else {
      return load(a.position_x, a.position_y, a.position_z, i);
    }
  }
  /// Particle i's offset from origin, each component rounded once to T (precision.hpp's
  /// relative; relative_all below for a loop over every particle).
  template <Real T>
  static Vector3<T> relative(const Arrays& a, std::size_t i,
                             const Vector3<position_value>& origin) noexcept {
    if constexpr (compensated) {
      return {Storage::template relative<T>(a.position_x[i], a.position_error_x[i], origin.x),
              Storage::template relative<T>(a.position_y[i], a.position_error_y[i], origin.y),
              Storage::template relative<T>(a.position_z[i], a.position_error_z[i], origin.z)};
    } else {
      return {Storage::template relative<T>(a.position_x[i], origin.x),
              Storage::template relative<T>(a.position_y[i], origin.y),
              Storage::template relative<T>(a.position_z[i], origin.z)};
    }
  }

  /// Every particle's offset from origin into out[0, a.size), each component rounded once
  /// without a branch (round_via_odd; precision.hpp's BranchFree road). The column pointers
  /// are read once into locals: so clang vectorises the loop too (it checks at run time that
  /// out does not overlap them), where it kept the loop over relative(a, i, origin) scalar.
  /// The origin is taken by value: every offset is from the origin of the call, even one read
  /// from the buffer being written.
  template <Real T>
  static void relative_all(const Arrays& a, const Vector3<position_value> origin,
                           Vector3<T>* out) noexcept {
    using E = typename Layout::position_element;
    const std::size_t n = a.size;
    const E* const px = a.position_x;
    const E* const py = a.position_y;
    const E* const pz = a.position_z;
    if constexpr (compensated) {
      const E* const ex = a.position_error_x;
      const E* const ey = a.position_error_y;
      const E* const ez = a.position_error_z;
      for (std::size_t i = 0; i < n; ++i) {
        out[i] = {Storage::template relative<T, true>(px[i], ex[i], origin.x),
                  Storage::template relative<T, true>(py[i], ey[i], origin.y),
                  Storage::template relative<T, true>(pz[i], ez[i], origin.z)};
      }
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        out[i] = {Storage::template relative<T, true>(px[i], origin.x),
                  Storage::template relative<T, true>(py[i], origin.y),
                  Storage::template relative<T, true>(pz[i], origin.z)};
      }
    }
  }
};
}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
