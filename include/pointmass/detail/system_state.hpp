// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/system_state.hpp — what a ParticleSystem holds, and the mechanics behind
// its public API.
//
// Owns: the system's data (the block of arrays, the uniform damping and acceleration, the
// handle table, the walk direction and the removal pass under way), its copy, move and swap;
// capacity and growth; appending and swap-removing a particle (with its handle); reading and
// writing a particle's position in the configuration's precision (precision.hpp), and its
// previous position (features::Interpolation); the user columns at spawn; the walk of a step
// and the removal passes (expiry, with and without a callback, and kill_if); the copy-out of
// positions into a caller's buffer. particle_system.hpp is the public face of this class and says what each call
// means; here is how.
//
// Must not include: particle_system.hpp, parallel.hpp (this is below the public API).
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
#include "system_kernel.hpp"
#include "validate.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

// What parallel.hpp's step reaches beyond a system's public API (a friend of ParticleSystem).
struct SystemAccess;

template <class S, DampingPolicy D, class P, class... Features>
class SystemState {
 protected:
  using R = real_of_t<S>;
  using Layout = SystemLayout<S, D, Features...>;
  using Kernel = SystemKernel<R, D, P, Layout>;
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

  // Appends a particle (input already validated): position, velocity, a default Particle's
  // per-particle values, a handle slot, default user columns. Returns its index.
  std::size_t append(const Vector3<position_value>& position, const Vector3<R>& velocity) {
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
      a.lifetime[i] = real_infinity<R>;
    }
    store_user_columns(i, std::make_index_sequence<user_column_count>{});
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
  }
  // Particle i's damping state, and its retention for retention_duration_ (the same
  // function and inputs as the step's refresh, so the same bits).
  void store_damping(std::size_t i, const damping_state& state) noexcept {
    Layout::store_damping(arrays(), i, state);
    if constexpr (Layout::per_particle_retention) {
      if (retention_duration_ >= R(0)) Kernel::refresh_retention(arrays(), i, retention_duration_);
    }
  }
  // The user columns of particle i: the values given, or T{} for each when none are.
  template <std::size_t... I, class... Values>
  void store_user_columns(std::size_t i, std::index_sequence<I...>, const Values&... values) {
    if constexpr (sizeof...(Values) == 0) {
      ((Layout::template user_pointer<I>(arrays())[i] =
            typename Layout::template user_element_t<I>{}),
       ...);
    } else {
      ((Layout::template user_pointer<I>(arrays())[i] = values), ...);
    }
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
  // kill_if: the predicate runs inside RemovalPass::predicate, where removals and steps are
  // refused; should it have replaced the particles whole (assigned, swapped or moved the
  // system), the pass ends there.
  template <class Predicate>
  std::size_t remove_if(Predicate& predicate) {
    std::size_t removed = 0;
    std::size_t i = 0;
    while (i < size()) {
      bool remove_it = false;
      const std::uint16_t replacements = replacements_;
      {
        const PassScope scope(removing_, RemovalPass::predicate);
        remove_it = static_cast<bool>(predicate(std::as_const(i)));
      }
      if (replacements_ != replacements) break;
      if (remove_it) {
        remove(i);
        ++removed;
      } else {
        ++i;
      }
    }
    return removed;
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

  // --- the step ------------------------------------------------------------------------------

  // The kept factors where the last step had this length, else computed (the scalar form, the
  // same bits): reads the system only, so loops of one's own may call it as before.
  [[nodiscard]] StepParameters step_parameters(R duration) const noexcept {
    if constexpr (keeps_factors) {
      if (same_bits(duration, kept_.duration)) return parameters_with(duration, kept_.factors);
    }
    if constexpr (Layout::per_particle_damping) {
      return parameters_with(duration, NoFactors{});
    } else {
      return parameters_with(duration, scalar_factors<D>(damping_, duration));
    }
  }
  // step_parameters for the library's steps (walk, and through SystemAccess the parallel and
  // Kokkos steps), which keep the factors of a new length.
  StepParameters keep_step_parameters(R duration) noexcept {
    if constexpr (keeps_factors) {
      if (!same_bits(duration, kept_.duration)) {
        kept_.factors = scalar_factors<D>(damping_, duration);
        kept_.duration = duration;
      }
      return parameters_with(duration, kept_.factors);
    } else {
      return step_parameters(duration);
    }
  }
  // The damping changed: the next step computes its factors.
  void forget_factors() noexcept {
    if constexpr (keeps_factors) kept_.duration = R(-1);
  }
  template <class Factors>
  [[nodiscard]] [[nodiscard]] StepParameters parameters_with(
      R duration, const Factors& factors) const noexcept {
    StepParameters parameters{};
    parameters.duration = duration;
    if constexpr (!Layout::per_particle_damping) parameters.factors = factors;
    parameters.acceleration = acceleration_;
    if constexpr (Layout::per_particle_retention) {
      parameters.refresh = !real_equal(duration, retention_duration_);
    }
    return parameters;
  }
  // `function`: the call a report names (step's own, or begin_step called by the user).
  bool begin_step(R duration, const char* function = "begin_step") const {
#if POINTMASS_HOST_CHECKS
    if (!check_duration(function, duration)) return false;
#endif
    if (!check_not_stepping(function, "duration", removing_, duration)) return false;
    return !real_equal(duration, R(0)) && size() != 0;
  }
  // The damping_retention column may no longer hold the retention for retention_duration_ (written
  // from outside, or stepped by a loop of the caller's): the next step recomputes it.
  void forget_retention() noexcept {
    if constexpr (Layout::per_particle_retention) retention_duration_ = R(-1);
  }
  // Every particle has just stepped through step_particle with step_parameters(duration):
  // the damping_retention column holds the retention for this duration.
  void record_retention(R duration) noexcept {
    if constexpr (Layout::per_particle_retention) retention_duration_ = duration;
  }
  // Steps every particle, walking in the direction due; false when there was nothing to do.
  bool walk(R duration) {
    if (!begin_step(duration, "step")) return false;
    const StepParameters parameters = keep_step_parameters(duration);
    if (backward_) {
      Kernel::step_range_backward(arrays(), 0, size(), parameters);
    } else {
      Kernel::step_range(arrays(), 0, size(), parameters);
    }
    backward_ = !backward_ && Kernel::alternates(size());
    record_retention(duration);
    return true;
  }

  // The expiry pass without a callback.
  struct NoCallback {
    void operator()(std::size_t) const noexcept {}
  };
  // Marks the system as inside a removal pass (an expiry callback, kill_if's predicate) while
  // it lives.
  struct PassScope {
    RemovalPass& flag;
    RemovalPass outer;
    PassScope(RemovalPass& pass, RemovalPass inner) noexcept : flag(pass), outer(pass) {
      flag = inner;
    }
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;
    ~PassScope() { flag = outer; }
  };
  POINTMASS_HD static constexpr bool expired(R age, R lifetime) noexcept {
    return (age >= lifetime) & (lifetime < real_infinity<R>);
  }
  // kill_if's order and result, but a step expires few particles: a block of vector_block
  // particles none of which has expired (a test that vectorises) is skipped whole; only a
  // block with an expiry is walked one particle at a time.
  template <class OnExpire>
  void expire(OnExpire& on_expire, const char* function = "step") {
    if constexpr (Layout::has_lifetime) {
      // (step refuses earlier, in begin_step; finish_step reaches here)
      if (!check_not_stepping(function, "particles", removing_, size())) return;
      constexpr std::size_t block = Kernel::vector_block;
      std::size_t i = 0;
      while (i < size()) {
        const R* age = arrays().age;
        const R* lifetime = arrays().lifetime;
        if (i % block == 0 && i + block <= size()) {
          // age >= lifetime is all an expiry needs (and a plain comparison vectorises); the
          // particle test below then leaves infinite lifetimes alone. The comparisons are
          // or-ed as unsigned, and the loop is not unrolled first: so g++ vectorises it too
          // (with a bool, or unrolled whole at -O3, it compared one particle at a time).
          unsigned expiring = 0;
#if defined(__GNUC__) && !defined(__CUDACC__)  // (nvcc's front end does not know it)
#pragma GCC unroll 1
#endif
          // the expiry scan (tests/system probes this line)
          for (std::size_t k = 0; k < block; ++k) {
            expiring |= static_cast<unsigned>(age[i + k] >= lifetime[i + k]);
          }
          if (expiring == 0) {
            i += block;
            continue;
          }
        }
        if (!expired(age[i], lifetime[i])) {
          ++i;
        } else if (!expire_one(i, on_expire)) {
          return;
        }
      }
    }
  }
  // Particle i, expired: on_expire(i), then its removal. False when the callback replaced the
  // particles whole (assigned, swapped or moved the system): the pass ends there.
  template <class OnExpire>
  POINTMASS_DETAIL_ALWAYS_INLINE bool expire_one(std::size_t i, OnExpire& on_expire) {
    if constexpr (!std::is_same_v<std::remove_cvref_t<OnExpire>, NoCallback>) {
      const std::uint16_t replacements = replacements_;
      {
        const PassScope scope(removing_, RemovalPass::expiry);
        on_expire(std::as_const(i));
      }
      // The callback may only spawn (which keeps i).
      if (replacements_ != replacements) return false;
    }
    remove(i);
    return true;
  }

  // --- copy-out ------------------------------------------------------------------------------

  // store(i, x, y, z) with load(i)'s x, y and z for particles [first, last): the loop of
  // for_each_output_position. Scattered: each particle's components go a stride apart
  // (copy_strided with a stride other than 3), and the loop is not vectorised under clang,
  // whose vectorised form scatters them (AVX-512's scatter stores), at about half the speed
  // of the plain stores (hand-off table, stride 6). Otherwise both compilers vectorise it.
  template <bool Scattered, class Load, class Store>
  POINTMASS_DETAIL_ALWAYS_INLINE static void output_loop(std::size_t first, std::size_t last,
                                                         const Load& load, Store& store) {
    if constexpr (Scattered) {
#if defined(__clang__)
#pragma clang loop vectorize(disable)
#endif
      for (std::size_t i = first; i < last; ++i) {
        const auto p = load(i);
        store(i, p.x, p.y, p.z);
      }
    } else {
      for (std::size_t i = first; i < last; ++i) {
        const auto p = load(i);
        store(i, p.x, p.y, p.z);
      }
    }
  }

  // Calls store(i, x, y, z) for particles [first, last) with the position at the fraction
  // alpha of the last step (alpha 1: the current position; without Interpolation always).
  // The choice of alpha is made once, outside the loop, so 0 and 1 copy bits.
  template <bool Scattered = false, class Store>
  void for_each_output_position(R alpha, std::size_t first, std::size_t last,
                                Store&& store_one) const {
    using E = typename Layout::position_element;
    const Arrays& a = arrays();
    bool current = true;
    if constexpr (has_interpolation) current = real_equal(alpha, R(1));
    if (current) {
      if constexpr (compensated) {  // hi + lo, in the wider type: the store rounds it once
        output_loop<Scattered>(
            first, last,
            [&](std::size_t i) {
              return Vector3<position_value>{
                  Storage::value_of(a.position_x[i], a.position_error_x[i]),
                  Storage::value_of(a.position_y[i], a.position_error_y[i]),
                  Storage::value_of(a.position_z[i], a.position_error_z[i])};
            },
            store_one);
      } else {
        output_loop<Scattered>(
            first, last,
            [&](std::size_t i) {
              return Vector3<E>{a.position_x[i], a.position_y[i], a.position_z[i]};
            },
            store_one);
      }
      return;
    }
    if constexpr (has_interpolation) {
      if (real_equal(alpha, R(0))) {
        output_loop<Scattered>(
            first, last,
            [&](std::size_t i) {
              return Vector3<E>{a.previous_position_x[i], a.previous_position_y[i],
                                a.previous_position_z[i]};
            },
            store_one);
        return;
      }
      const E fraction = static_cast<E>(alpha);
      output_loop<Scattered>(
          first, last,
          [&](std::size_t i) {
            const E px = a.previous_position_x[i];
            const E py = a.previous_position_y[i];
            const E pz = a.previous_position_z[i];
            return Vector3<E>{px + (a.position_x[i] - px) * fraction,
                              py + (a.position_y[i] - py) * fraction,
                              pz + (a.position_z[i] - pz) * fraction};
          },
          store_one);
    }
  }
  template <class T>
  void copy_strided(const char* function, R alpha, std::span<T> out, std::size_t stride) const {
    if (!check_at_least(function, "stride", stride, 3)) return;
    if (size() == 0) return;
    // (size() - 1) * stride + 3 elements, saturated: a stride too large for any buffer must
    // not wrap around to a small count.
    const std::size_t rows = size() - 1;
    constexpr auto most = static_cast<std::size_t>(-1);
    const std::size_t needed = rows != 0 && stride > (most - 3) / rows ? most : rows * stride + 3;
    if (!check_strided_buffer(function, out.size(), needed)) return;
    T* data = out.data();
    const auto store = [&](std::size_t i, auto x, auto y, auto z) {
      T* vertex = data + i * stride;
      vertex[0] = static_cast<T>(x);
      vertex[1] = static_cast<T>(y);
      vertex[2] = static_cast<T>(z);
    };
    // Packed (x, y, z of one particle after another's): vectorised; any other stride
    // scatters (output_loop).
    if (stride == 3) for_each_output_position(alpha, 0, size(), store);
    else for_each_output_position<true>(alpha, 0, size(), store);
  }
  template <class V>
  void copy_vectors(const char* function, R alpha, std::span<V> out) const {
    if (!check_buffer(function, "out", out.size(), size())) return;
    V* data = out.data();
    for_each_output_position(alpha, 0, size(), [&](std::size_t i, auto x, auto y, auto z) {
      using T = std::remove_cvref_t<decltype(data[i].x)>;
      data[i].x = static_cast<T>(x);
      data[i].y = static_cast<T>(y);
      data[i].z = static_cast<T>(z);
    });
  }
};

// The state at the bottom of ParticleSystem's facets (system/*.hpp): a protected base, so
// that its members reach the facets and the class above them, and a system does not convert
// to it outside them.
template <class S, DampingPolicy D, class P, class... Features>
class SystemStateBase : protected SystemState<S, D, P, Features...> {};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
