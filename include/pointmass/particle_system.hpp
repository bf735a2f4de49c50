// SPDX-License-Identifier: BSL-1.0
// pointmass/particle_system.hpp — many particles in structure-of-arrays form: the public API.
//
//   pointmass::ParticleSystem<float>                                   sparks: per-second damping
//                                                                      and gravity for all, p + v t
//   pointmass::ParticleSystem<float, damping::None, position::Euler,
//                             features::Lifetime>                       fireworks that burn out
//   pointmass::ParticleSystem<double, damping::PerSecond, position::SemiImplicit,
//                             features::PerParticleDamping, features::ForceAccumulator>
//   pointmass::ParticleSystem<Precision<float, Compensated<float>>>     far from the origin
//                                                                      (precision.hpp)
//
// The first argument is a Real, or a Precision<Real, Position> (precision.hpp): positions
// stored as double (position columns of double) or Compensated<Real> (three more columns,
// position_error_x/y/z, hold the carried error); everything else stays in Real.
// `positions_relative_to(origin, buffer)` writes float positions relative to a camera.
//
// ParticleSystem<Real, DampingPolicy, PositionPolicy, Features...> steps many particles with
// the same policies as `Particle` and the same results: each particle's step is
// `advance<D, P>` (particle.hpp) applied to x, y and z apart, so a system and the
// equivalent `Particle`s agree bit for bit (tests/system/ proves it for every policy pair).
// docs/particle-system.md is the user's guide.
//
// Owns: the public API (construction, spawn and kill, per-particle values, spans, step).
// Below it: features.hpp (the tags and the table of arrays), detail/soa_block.hpp (the one
// allocation), detail/system_kernel.hpp (the step loop). parallel.hpp adds the parallel step.
// Must not include: <execution> or anything that starts threads (that is parallel.hpp's).
//
// "Skip what a scene doesn't need". Everything a scene may do without is a compile-time
// feature tag; what is not chosen is neither stored nor computed:
//
//   tag (namespace features)    stores per particle              without it
//   (always)                    position x, y, z; velocity x, y, z
//   PerParticleDamping          the damping policy's State       one damping for the system:
//                               (d; for PerSecond and Exact also D::factors (d^t, ...) is
//                               ln d as hi + lo, each a column); computed once per step
//                               factors computed per particle
//   PerParticleAcceleration     acceleration x, y, z             one acceleration (gravity)
//                                                                for the system
//   ForceAccumulator            inverse mass, force accumulator  every particle has mass 1
//                               x, y, z (cleared by each step)   and no force
//   Lifetime                    age, lifetime (seconds); a step  particles live until killed
//                               ages every particle and removes
//                               those with age >= lifetime
//   Interpolation               previous position x, y, z (the   no interpolated positions
//                               position before the last step)
//   Handles                     the particle's slot (4 bytes),   no stable names: an index
//                               and a slot table beside the      is the only name
//                               block (8 bytes a slot)
//   Column<Tag, T>              a T of the user's, moved with    nothing
//                               its particle, never stepped
//
// With uniform per-second damping a step computes d^t once, not once per particle. With
// PerParticleDamping, PerSecond and Exact compute it per particle with the library's
// branch-free exponential, inside the vectorised loop; AccelerateThenDamp calls powf / pow
// per particle (to reproduce the reference engine bit for bit), which stops vectorisation. Tags may come in any order; an unknown tag is a compile error.
// `storage_bytes_per_particle` tells what a configuration costs in memory.
//
// Capacity is reserved up front (constructor or `reserve`); `spawn` beyond it grows the block
// (doubling), `step` never allocates. A capacity beyond max_size() throws std::length_error
// and changes nothing.
//
// Invalidation. Killing is swap-remove: `kill(i)` moves the last particle into slot i. Order
// is not kept, and an index names a particle only until the next kill, expiry or step with
// Lifetime; a handle (features::Handles) names it for as long as it lives.
//
// Expiry callback: `step(t, on_expire)` calls on_expire(i) for each particle whose lifetime
// is over, once, after the step and before its removal, so that particle i still holds its
// final state (position, velocity, age, user columns). Spawning inside the callback is
// allowed and immediate: the new particles are appended, are not expired by this step and
// are stepped from the next step on (a spawn that grows the block moves the arrays, so read
// the parent through the system, not through a span taken before). Removing particles
// (kill, kill_if, clear) inside the callback is a contract violation and does nothing. Spans, `arrays()` and pointers into them are valid until the next spawn that
// grows the block, `reserve`, `shrink`, move or swap (a growing spawn moves every array).
//
// Access: `position_x()`, `velocity_y()`, ... (the six arrays every system has) and
// `column<Column::age>()` (any stored array) return std::span over the live particles, for a
// renderer to upload or another engine to compute on. Writing through them skips the
// setters' validation. Indices are checked when POINTMASS_CHECKS is on; otherwise an index
// >= size() is undefined behaviour, as for std::vector::operator[].
//
// Device loops: `arrays()` gives the raw pointers and `step_parameters(t)` the values a step
// shares; `step_particle(arrays, i, parameters)` is the step of particle i, a POINTMASS_HD
// function, so a CUDA, Thrust or Kokkos loop over i runs the same arithmetic as `step` (then
// call `finish_step()` on the host to expire particles). The same bits on a device need the
// compiler settings docs/hardening.md lists (no contraction into fused multiply-adds, and
// the device's power function agreeing with the host's).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "damping.hpp"
#include "detail/handle_table.hpp"
#include "detail/soa_block.hpp"
#include "detail/system_kernel.hpp"
#include "detail/validate.hpp"
#include "features.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "real.hpp"
#include "vector3.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

template <class S, DampingPolicy D = damping::PerSecond, class P = position::Euler,
          class... Features>
  requires(Real<S> || PrecisionChoice<S>) && (detail::is_feature_v<Features> && ...)
class ParticleSystem
    : public detail::SystemKernel<real_of_t<S>, D, P, detail::SystemLayout<S, D, Features...>> {
  using R = real_of_t<S>;
  using Layout = detail::SystemLayout<S, D, Features...>;
  using Kernel = detail::SystemKernel<R, D, P, Layout>;
  using Storage = typename Layout::position_storage;
  using Block = detail::SoaBlock<Layout>;
  // P is checked here, with one sentence, rather than as a constraint (see position.hpp).
  static_assert(detail::check_policy_pair<D, P>());

 public:
  using real = R;
  using damping_policy = D;
  using position_policy = P;
  using damping_state = typename D::template State<R>;
  using damping_factors = damping_factors_t<D, R>;
  /// The scalar particle whose step this system reproduces.
  using particle_type = Particle<S, D, P>;
  /// How positions are stored (precision.hpp): R, a wider Real, or Compensated<R>.
  using position_precision = position_precision_of_t<S>;
  /// What position(i) returns and spawn and set_position take, per component (R, or double
  /// for Precision<float, double> and Precision<float, Compensated<float>>).
  using position_value = typename Storage::value;
  /// The element of the position columns (position_x(), ...).
  using position_element = typename Layout::position_element;
  /// Raw pointers to the arrays (nullptr for those not stored) and the number of live
  /// particles: what step_particle works on.
  using Arrays = typename Layout::Arrays;
  using typename Kernel::StepParameters;
  /// The element type of column C: R, but for Column::damping with a damping policy of the
  /// user's whose state is neither StoredDamping nor LogDamping (then that state).
  template <Column C>
  using element_t = typename Layout::template element_t<C>;

  static constexpr bool per_particle_damping = Layout::per_particle_damping;
  static constexpr bool per_particle_acceleration = Layout::per_particle_acceleration;
  static constexpr bool has_forces = Layout::has_forces;
  static constexpr bool has_lifetime = Layout::has_lifetime;
  static constexpr bool has_interpolation = Layout::has_interpolation;
  static constexpr bool has_handles = Layout::has_handles;
  /// The user's columns (features::Column<Tag, T>) as a std::tuple, and how many.
  using user_columns = typename Layout::user_columns;
  static constexpr std::size_t user_column_count = Layout::user_column_count;
  /// The element type of the user column tagged Tag.
  template <class Tag>
  using user_element_t = typename Layout::template user_element_t<Layout::template user_index<Tag>>;
  /// True when the user column tagged Tag exists.
  template <class Tag>
  static constexpr bool has_column = Layout::template user_index<Tag> < user_column_count;
  /// True when the damping policy has a damping value at all (not damping::None).
  static constexpr bool stores_damping = !std::is_empty_v<damping_state>;
  static_assert(!per_particle_damping || stores_damping,
                "features::PerParticleDamping needs a damping policy with a damping value "
                "(damping::None has none)");
  /// True when this configuration stores column C.
  template <Column C>
  static constexpr bool stores = Layout::template stores<C>;

  /// Bytes each particle occupies (the block adds under 4.5 KiB per array of padding).
  static constexpr std::size_t storage_bytes_per_particle = Layout::bytes_per_particle;
  /// How many arrays the block holds.
  static constexpr std::size_t array_count = Layout::array_count;

  /// Returned by spawn when its input was rejected.
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  using HandleTable = std::conditional_t<
      has_handles,
      detail::HandleTable<typename detail::handles_of<Features..., features::Handles>::type::
                              generation_type>,
      detail::NoHandleTable>;
  static_assert(((detail::is_handles<Features>::value ? 1 : 0) + ... + 0) <= 1,
                "ParticleSystem: at most one features::Handles / BasicHandles<G>");
  template <std::size_t... I>
  static constexpr bool unique_tags(std::index_sequence<I...>) {
    return ((Layout::template user_index<
                 typename std::tuple_element_t<I, user_columns>::tag> == I) &&
            ...);
  }
  static_assert(unique_tags(std::make_index_sequence<user_column_count>{}),
                "ParticleSystem: two features::Column<Tag, T> with the same Tag");

 public:
  /// A particle's stable name (features::Handles): see handle() and find().
  using Handle = typename std::conditional_t<has_handles, HandleTable,
                                             detail::HandleTable<std::uint32_t>>::Handle;

  // --- construction --------------------------------------------------------------------------

  ParticleSystem() = default;
  /// An empty system with room for `capacity` particles.
  explicit ParticleSystem(std::size_t capacity) { reserve(capacity); }

  /// A copy with the same particles, capacity and uniform values; it starts walking forwards.
  ParticleSystem(const ParticleSystem& other)
      : block_(other.block_.with_capacity(other.capacity())),
        damping_(other.damping_),
        acceleration_(other.acceleration_),
        handles_(other.handles_) {}
  ParticleSystem(ParticleSystem&& other) noexcept
      : block_(std::move(other.block_)),
        backward_(std::exchange(other.backward_, false)),
        damping_(other.damping_),
        acceleration_(other.acceleration_),
        handles_(std::move(other.handles_)) {}
  ParticleSystem& operator=(ParticleSystem other) noexcept {
    swap(other);
    return *this;
  }
  ~ParticleSystem() = default;

  void swap(ParticleSystem& other) noexcept {
    block_.swap(other.block_);
    std::swap(backward_, other.backward_);
    std::swap(damping_, other.damping_);
    std::swap(acceleration_, other.acceleration_);
    std::swap(handles_, other.handles_);
  }
  friend void swap(ParticleSystem& a, ParticleSystem& b) noexcept { a.swap(b); }

  // --- size and capacity ---------------------------------------------------------------------

  std::size_t size() const noexcept { return block_.size(); }
  bool empty() const noexcept { return size() == 0; }
  std::size_t capacity() const noexcept { return block_.capacity(); }
  /// The largest capacity a system of this configuration can have.
  static constexpr std::size_t max_size() noexcept {
    if constexpr (has_handles) {  // slots and indices are 32-bit (detail/handle_table.hpp)
      return std::min(Block::max_capacity, HandleTable::max_slots);
    } else {
      return Block::max_capacity;
    }
  }

  /// Makes room for `capacity` particles in one block (no-op if there is room already).
  /// A capacity beyond max_size() throws std::length_error and changes nothing.
  void reserve(std::size_t capacity) {
    if (capacity <= this->capacity()) return;
    if (capacity > max_size()) throw_length_error("reserve", capacity);
    if constexpr (has_handles) handles_.reserve(capacity);
    block_ = block_.with_capacity(capacity);
  }
  /// Removes every particle; keeps the capacity. (Not inside an expiry callback.)
  void clear() {
    if (!detail::check_not_expiring("clear", expiring_, 0)) return;
    if constexpr (has_handles) {
      for (std::size_t i = 0; i < size(); ++i) handles_.release(arrays().handle_slot[i]);
    }
    set_size(0);
  }

  // --- uniform values ------------------------------------------------------------------------

  /// The acceleration of every particle (gravity); finite.
  void set_acceleration(const Vector3<R>& acceleration)
    requires(!per_particle_acceleration)
  {
    if (detail::check_finite("set_acceleration", "acceleration", acceleration)) {
      acceleration_ = acceleration;
    }
  }
  Vector3<R> acceleration() const noexcept
    requires(!per_particle_acceleration)
  {
    return acceleration_;
  }
  /// The damping of every particle, in [0, 1] (per second or per frame, as the policy says).
  void set_damping(R damping)
    requires(stores_damping && !per_particle_damping)
  {
    if (detail::check_damping("set_damping", damping)) damping_ = damping_state(damping);
  }
  R damping() const noexcept
    requires(!per_particle_damping)
  {
    return damping_.value();
  }

  // --- spawning and killing ------------------------------------------------------------------

  /// Adds a particle at `position` with `velocity` and returns its index. Per-particle
  /// values start as a default Particle's: acceleration 0, damping 1, mass 1, no force, age 0,
  /// lifetime infinite. Non-finite input is reported and nothing is added (returns npos).
  /// Grows the block when full (invalidating spans and arrays()).
  std::size_t spawn(const Vector3<position_value>& position, const Vector3<R>& velocity) {
    if (!valid_position("spawn", position)) return npos;
    if (!detail::check_finite("spawn", "velocity", velocity)) return npos;
    if (size() == capacity()) grow();
    const std::size_t i = size();
    std::uint32_t slot = 0;
    if constexpr (has_handles) {
      slot = handles_.acquire(i);
      if (slot == HandleTable::none) throw_length_error("spawn", HandleTable::max_slots + 1);
    }
    set_size(i + 1);
    const Arrays& a = arrays();
    store_position(i, position);
    if constexpr (has_handles) a.handle_slot[i] = slot;
    clear_user_columns(i, std::make_index_sequence<user_column_count>{});
    store(a.velocity_x, a.velocity_y, a.velocity_z, i, velocity);
    if constexpr (per_particle_acceleration) {
      store(a.acceleration_x, a.acceleration_y, a.acceleration_z, i, {});
    }
    if constexpr (has_forces) {
      a.inverse_mass[i] = R(1);
      store(a.force_x, a.force_y, a.force_z, i, {});
    }
    if constexpr (per_particle_damping) Layout::store_damping(a, i, damping_state{});
    if constexpr (has_lifetime) {
      a.age[i] = R(0);
      a.lifetime[i] = real_infinity<R>;
    }
    return i;
  }
  /// Adds a copy of `particle`: its position and velocity, and whichever of its
  /// acceleration, damping, inverse mass and accumulated force the system stores per
  /// particle (the others are the system's uniform values).
  std::size_t spawn(const particle_type& particle) {
    const std::size_t i = spawn(particle.position(), particle.velocity());
    if (i == npos) return npos;
    const Arrays& a = arrays();
    if constexpr (!std::is_same_v<position_precision, R>) {  // the stored numbers, exactly
      store(a.position_x, a.position_y, a.position_z, i, particle.stored_position());
      if constexpr (Layout::compensated_positions) {
        store(a.position_error_x, a.position_error_y, a.position_error_z, i,
              particle.stored_position_error());
      }
      store_previous_position(i);
    }
    if constexpr (per_particle_acceleration) {
      store(a.acceleration_x, a.acceleration_y, a.acceleration_z, i, particle.acceleration());
    }
    if constexpr (has_forces) {
      a.inverse_mass[i] = particle.inverse_mass();
      store(a.force_x, a.force_y, a.force_z, i, particle.force_accumulator());
    }
    if constexpr (per_particle_damping) {
      Layout::store_damping(a, i, damping_state(particle.damping()));
    }
    return i;
  }
  /// Adds a particle with a value for each user column, in the order of the features.
  template <class... Values>
    requires(sizeof...(Values) > 0 && sizeof...(Values) == user_column_count)
  std::size_t spawn(const Vector3<position_value>& position, const Vector3<R>& velocity,
                    const Values&... values) {
    const std::size_t i = spawn(position, velocity);
    if (i != npos) store_user_columns(i, std::make_index_sequence<user_column_count>{}, values...);
    return i;
  }
  /// Spawns `count` particles, reserving once: particle k is spawn(generator(k)...), where
  /// generator(k) returns the arguments of a spawn as a tuple-like value (a std::pair of
  /// position and velocity, a std::tuple with the user columns' values after them) or a
  /// particle_type. Returns how many were added (a rejected one is reported and skipped);
  /// they are the last ones, [size() - returned, size()), until the next removal.
  template <class Generator>
  std::size_t spawn_burst(std::size_t count, Generator&& generator) {
    if (count > max_size() - size()) throw_length_error("spawn_burst", size() + count);
    if (size() + count > capacity()) {
      reserve(std::max(size() + count, std::min(2 * capacity(), max_size())));
    }
    std::size_t spawned = 0;
    for (std::size_t k = 0; k < count; ++k) {
      decltype(auto) made = generator(k);
      std::size_t i;
      if constexpr (std::is_convertible_v<decltype(made), const particle_type&>) {
        i = spawn(static_cast<const particle_type&>(made));
      } else {
        i = std::apply([&](const auto&... arguments) { return spawn(arguments...); }, made);
      }
      if (i != npos) ++spawned;
    }
    return spawned;
  }

  /// Removes particle `index` by moving the last particle into its place (order not kept).
  void kill(std::size_t index) {
    if (detail::check_not_expiring("kill", expiring_, index) &&
        detail::check_index("kill", index, size())) {
      remove(index);
    }
  }
  /// Removes every particle for which predicate(index) is true, by swap-remove, and returns
  /// how many. The predicate sees each particle once; after a removal it is asked about the
  /// particle moved into the freed index.
  template <class Predicate>
  std::size_t kill_if(Predicate&& predicate) {
    if (!detail::check_not_expiring("kill_if", expiring_, 0)) return 0;
    const std::size_t before = size();
    std::size_t i = 0;
    while (i < size()) {
      if (predicate(i)) {
        remove(i);
      } else {
        ++i;
      }
    }
    return before - size();
  }

  // --- per-particle values (index < size(): checked when POINTMASS_CHECKS is on) -------------

  Vector3<position_value> position(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("position", i)) return {};
    const Arrays& a = arrays();
    if constexpr (Layout::compensated_positions) {
      return {Storage::value_of(a.position_x[i], a.position_error_x[i]),
              Storage::value_of(a.position_y[i], a.position_error_y[i]),
              Storage::value_of(a.position_z[i], a.position_error_z[i])};
    } else {
      return load(a.position_x, a.position_y, a.position_z, i);
    }
  }
  /// Particle i's position relative to `origin` (a camera), as float: from the whole
  /// stored position, exact wherever the true offset is a float (precision.hpp).
  Vector3<float> position_relative_to(std::size_t i, const Vector3<position_value>& origin) const
      noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("position_relative_to", i)) return {};
    return relative(arrays(), i, origin);
  }
  /// Every particle's position relative to `origin`, as float, into `buffer` (at least
  /// size() elements; element i for particle i): what a renderer uploads. A buffer too small
  /// is reported and nothing is written.
  void positions_relative_to(const Vector3<position_value>& origin,
                             std::span<Vector3<float>> buffer) const {
    if (!detail::check_buffer("positions_relative_to", "buffer", buffer.size(), size())) return;
    const Arrays a = arrays();
    const std::size_t count = size();
    for (std::size_t i = 0; i < count; ++i) buffer[i] = relative(a, i, origin);
  }
  Vector3<R> velocity(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("velocity", i)) return {};
    return load(arrays().velocity_x, arrays().velocity_y, arrays().velocity_z, i);
  }
  /// The acceleration particle i has (its own, or the system's).
  Vector3<R> acceleration(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("acceleration", i)) return {};
    if constexpr (per_particle_acceleration) {
      return load(arrays().acceleration_x, arrays().acceleration_y, arrays().acceleration_z, i);
    } else {
      return acceleration_;
    }
  }
  /// The damping particle i has (its own, or the system's).
  R damping(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("damping", i)) return R(1);
    if constexpr (per_particle_damping) {
      return Layout::load_damping(arrays(), i).value();
    } else {
      return damping_.value();
    }
  }

  void set_position(std::size_t i, const Vector3<position_value>& position) {
    if (detail::check_index("set_position", i, size()) &&
        valid_position("set_position", position)) {
      store_position(i, position);
    }
  }
  void set_velocity(std::size_t i, const Vector3<R>& velocity) {
    if (detail::check_index("set_velocity", i, size()) &&
        detail::check_finite("set_velocity", "velocity", velocity)) {
      store(arrays().velocity_x, arrays().velocity_y, arrays().velocity_z, i, velocity);
    }
  }
  void set_acceleration(std::size_t i, const Vector3<R>& acceleration)
    requires per_particle_acceleration
  {
    if (detail::check_index("set_acceleration", i, size()) &&
        detail::check_finite("set_acceleration", "acceleration", acceleration)) {
      store(arrays().acceleration_x, arrays().acceleration_y, arrays().acceleration_z, i,
            acceleration);
    }
  }
  void set_damping(std::size_t i, R damping)
    requires per_particle_damping
  {
    if (detail::check_index("set_damping", i, size()) &&
        detail::check_damping("set_damping", damping)) {
      Layout::store_damping(arrays(), i, damping_state(damping));
    }
  }

  R inverse_mass(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS)
    requires has_forces
  {
    return valid_index("inverse_mass", i) ? arrays().inverse_mass[i] : R(0);
  }
  Vector3<R> force_accumulator(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS)
    requires has_forces
  {
    if (!valid_index("force_accumulator", i)) return {};
    return load(arrays().force_x, arrays().force_y, arrays().force_z, i);
  }
  /// mass > 0 (infinity makes the particle immovable), with 1/mass finite and normal.
  void set_mass(std::size_t i, R mass)
    requires has_forces
  {
    if (detail::check_index("set_mass", i, size()) && detail::check_mass("set_mass", mass)) {
      arrays().inverse_mass[i] = R(1) / mass;
    }
  }
  /// inverse mass 0 (immovable) or finite, normal and > 0.
  void set_inverse_mass(std::size_t i, R inverse_mass)
    requires has_forces
  {
    if (detail::check_index("set_inverse_mass", i, size()) &&
        detail::check_inverse_mass("set_inverse_mass", inverse_mass)) {
      arrays().inverse_mass[i] = inverse_mass;
    }
  }
  /// Adds a force to particle i for the next step only. As Particle::add_force: a hot-path
  /// call, so its preconditions (i < size(), a finite force) are checked when
  /// POINTMASS_CHECKS is on.
  void add_force(std::size_t i, const Vector3<R>& force) noexcept(!POINTMASS_HOST_CHECKS)
    requires has_forces
  {
#if POINTMASS_HOST_CHECKS
    if (!detail::check_index("add_force", i, size()) ||
        !detail::check_finite("add_force", "force", force)) {
      return;
    }
#endif
    const Arrays& a = arrays();
    a.force_x[i] += force.x;
    a.force_y[i] += force.y;
    a.force_z[i] += force.z;
  }

  R age(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS)
    requires has_lifetime
  {
    return valid_index("age", i) ? arrays().age[i] : R(0);
  }
  R lifetime(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS)
    requires has_lifetime
  {
    return valid_index("lifetime", i) ? arrays().lifetime[i] : R(0);
  }
  /// Seconds particle i lives (> 0; infinity for ever: an infinite lifetime never expires).
  /// It is removed by the step after which its age reaches this. Ages add up in R: in float
  /// a step of t stops adding to an age once the age's spacing exceeds 2 t (at 60 Hz, after
  /// 2^19 s, about 6 days), so give lifetimes beyond 2^17 s to a double system.
  void set_lifetime(std::size_t i, R seconds)
    requires has_lifetime
  {
    if (detail::check_index("set_lifetime", i, size()) &&
        detail::check_lifetime("set_lifetime", seconds)) {
      arrays().lifetime[i] = seconds;
    }
  }

  // --- user columns (features::Column<Tag, T>) ------------------------------------------------

  /// The user column tagged Tag, over the live particles.
  template <class Tag>
    requires has_column<Tag>
  std::span<user_element_t<Tag>> column() noexcept {
    return {Layout::template user_pointer<Layout::template user_index<Tag>>(arrays()), size()};
  }
  template <class Tag>
    requires has_column<Tag>
  std::span<const user_element_t<Tag>> column() const noexcept {
    return {Layout::template user_pointer<Layout::template user_index<Tag>>(arrays()), size()};
  }
  /// Particle i's value in the user column tagged Tag.
  template <class Tag>
    requires has_column<Tag>
  user_element_t<Tag> column(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("column", i)) return {};
    return Layout::template user_pointer<Layout::template user_index<Tag>>(arrays())[i];
  }
  template <class Tag>
    requires has_column<Tag>
  void set_column(std::size_t i, const user_element_t<Tag>& value) {
    if (detail::check_index("set_column", i, size())) {
      Layout::template user_pointer<Layout::template user_index<Tag>>(arrays())[i] = value;
    }
  }

  // --- stable handles (features::Handles) ----------------------------------------------------

  /// The handle of particle i: it finds this particle for as long as it lives. O(1).
  Handle handle(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS)
    requires has_handles
  {
    if (!valid_index("handle", i)) return {};
    return handles_.handle(arrays().handle_slot[i]);
  }
  /// The current index of the particle `handle` names, or nothing once it has died. O(1).
  std::optional<std::size_t> find(const Handle& handle) const noexcept
    requires has_handles
  {
    return handles_.find(handle);
  }
  /// True while the particle `handle` names is alive.
  bool contains(const Handle& handle) const noexcept
    requires has_handles
  {
    return handles_.find(handle).has_value();
  }
  /// Bytes of the slot table beside the block (8 a slot with std::uint32_t generations).
  std::size_t handle_table_bytes() const noexcept
    requires has_handles
  {
    return handles_.bytes();
  }

  // --- fixed steps: interpolation (features::Interpolation) ----------------------------------

  /// Particle i's position before the last step (its spawn or set_position position if it
  /// has not stepped since).
  Vector3<position_element> previous_position(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS)
    requires has_interpolation
  {
    if (!valid_index("previous_position", i)) return {};
    return {arrays().previous_position_x[i], arrays().previous_position_y[i],
            arrays().previous_position_z[i]};
  }
  /// Particle i's position at the fraction `alpha` in [0, 1] of the last step: alpha 0 gives
  /// the previous position and 1 the current one, bit for bit; between them
  /// previous + (current - previous) alpha.
  Vector3<position_element> interpolated_position(std::size_t i, R alpha) const
    requires has_interpolation
  {
    if (!detail::check_index("interpolated_position", i, size()) ||
        !detail::check_fraction("interpolated_position", "alpha", alpha)) {
      return {};
    }
    Vector3<position_element> out{};
    for_each_output_position(alpha, i, i + 1, [&](std::size_t, auto x, auto y, auto z) {
      out = {x, y, z};
    });
    return out;
  }

  // --- renderer hand-off ---------------------------------------------------------------------

  /// Copies the positions into `out` as x, y, z at out[i * stride], out[i * stride + 1],
  /// out[i * stride + 2] (stride >= 3: 3 packed, more for interleaved vertices; pass
  /// buffer.subspan(offset) to start elsewhere), converted to T. `out` needs
  /// (size() - 1) * stride + 3 elements; a shorter one is reported and nothing is written.
  template <class T>
    requires std::is_arithmetic_v<T>
  void copy_positions(std::span<T> out, std::size_t stride = 3) const {
    copy_strided("copy_positions", R(1), out, stride);
  }
  /// Copies the positions into vectors with x, y, z members (glm::vec3, ...): out[i] for
  /// particle i; `out` needs size() elements.
  template <class V>
    requires(!std::is_arithmetic_v<V> && requires(V& v) { v.x = v.y = v.z; })
  void copy_positions(std::span<V> out) const {
    copy_vectors("copy_positions", R(1), out);
  }
  /// As copy_positions, with the positions at the fraction alpha of the last step
  /// (interpolated_position).
  template <class T>
    requires(has_interpolation && std::is_arithmetic_v<T>)
  void copy_interpolated_positions(R alpha, std::span<T> out, std::size_t stride = 3) const {
    if (detail::check_fraction("copy_interpolated_positions", "alpha", alpha)) {
      copy_strided("copy_interpolated_positions", alpha, out, stride);
    }
  }
  template <class V>
    requires(has_interpolation && !std::is_arithmetic_v<V> &&
             requires(V& v) { v.x = v.y = v.z; })
  void copy_interpolated_positions(R alpha, std::span<V> out) const {
    if (detail::check_fraction("copy_interpolated_positions", "alpha", alpha)) {
      copy_vectors("copy_interpolated_positions", alpha, out);
    }
  }

  // --- spans for renderers and other engines (valid until the block grows or moves) ---------

  /// Column C of the live particles, for any column this configuration stores. The damping
  /// columns of PerSecond and Exact (d and ln d as hi + lo, which must agree) are read-only:
  /// set_damping(i, d) writes them.
  template <Column C>
    requires stores<C>
  std::span<std::conditional_t<Layout::template read_only<C>, const element_t<C>, element_t<C>>>
  column() noexcept {
    return {arrays().*(Layout::template entry<C>::member), size()};
  }
  template <Column C>
    requires stores<C>
  std::span<const element_t<C>> column() const noexcept {
    return {arrays().*(Layout::template entry<C>::member), size()};
  }

  std::span<position_element> position_x() noexcept { return column<Column::position_x>(); }
  std::span<position_element> position_y() noexcept { return column<Column::position_y>(); }
  std::span<position_element> position_z() noexcept { return column<Column::position_z>(); }
  std::span<R> velocity_x() noexcept { return column<Column::velocity_x>(); }
  std::span<R> velocity_y() noexcept { return column<Column::velocity_y>(); }
  std::span<R> velocity_z() noexcept { return column<Column::velocity_z>(); }
  std::span<const position_element> position_x() const noexcept {
    return column<Column::position_x>();
  }
  std::span<const position_element> position_y() const noexcept {
    return column<Column::position_y>();
  }
  std::span<const position_element> position_z() const noexcept {
    return column<Column::position_z>();
  }
  std::span<const R> velocity_x() const noexcept { return column<Column::velocity_x>(); }
  std::span<const R> velocity_y() const noexcept { return column<Column::velocity_y>(); }
  std::span<const R> velocity_z() const noexcept { return column<Column::velocity_z>(); }

  /// The raw arrays (see step_particle), with size() live particles. Valid until the block
  /// grows or moves (a growing spawn, reserve, move, swap).
  const Arrays& arrays() const noexcept { return block_.arrays(); }

  // --- the step ------------------------------------------------------------------------------

  /// What every particle's step of `duration` shares: computes the uniform damping factors
  /// (the one power function of a step with uniform per-second damping).
  StepParameters step_parameters(R duration) const noexcept {
    StepParameters parameters{};
    parameters.duration = duration;
    if constexpr (!per_particle_damping) parameters.factors = D::factors(damping_, duration);
    parameters.acceleration = acceleration_;
    return parameters;
  }

  /// Advances every particle by `duration` seconds (see step_particle), then expires those
  /// whose lifetime is over. A negative, NaN or infinite duration is a contract violation,
  /// checked when POINTMASS_CHECKS is on; zero changes nothing. Allocates nothing.
  void step(R duration) {
    if constexpr (PositionPolicyFor<P, D>) {  // else the static_assert above has said why
      if (!begin_step(duration)) return;
      const StepParameters parameters = step_parameters(duration);
      (backward_ ? Kernel::step_range_backward : Kernel::step_range)(arrays(), 0, size(),
                                                                     parameters);
      backward_ = !backward_ && Kernel::alternates(size());
      finish_step();
    }
  }
  /// As step(duration), calling on_expire(i) for each particle whose lifetime is over,
  /// before its removal (see "Expiry callback" above).
  template <class OnExpire>
    requires(has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  void step(R duration, OnExpire&& on_expire) {
    step_calling(duration, on_expire);
  }

  /// True when the next `step` walks the particles backwards (see alternates). A copy
  /// starts forwards; a move or swap takes the direction along.
  bool next_step_backward() const noexcept { return backward_; }

  /// True if a step of `duration` has work to do; reports a bad duration (when checked).
  bool begin_step(R duration) const {
#if POINTMASS_HOST_CHECKS
    if (!detail::check_duration("step", duration)) return false;
#endif
    return !real_equal(duration, R(0)) && size() != 0;
  }

  /// After the particles have stepped: removes those whose age reached their (finite)
  /// lifetime. Called by step; call it yourself after stepping through step_particle
  /// elsewhere.
  void finish_step() {
    NoCallback none;
    finish_calling(none);
  }
  /// finish_step calling on_expire(i) for each expiring particle before its removal.
  template <class OnExpire>
    requires(has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  void finish_step(OnExpire&& on_expire) {
    finish_calling(on_expire);
  }

 private:
  template <class OnExpire>
  void step_calling(R duration, OnExpire& on_expire) {
    if constexpr (PositionPolicyFor<P, D>) {  // else the static_assert above has said why
      if (!begin_step(duration)) return;
      const StepParameters parameters = step_parameters(duration);
      (backward_ ? Kernel::step_range_backward : Kernel::step_range)(arrays(), 0, size(),
                                                                     parameters);
      backward_ = !backward_ && Kernel::alternates(size());
      finish_calling(on_expire);
    }
  }
  template <class OnExpire>
  void finish_calling(OnExpire& on_expire) {
    if constexpr (has_lifetime) {
      // kill_if's order and result, but a step expires few particles: a block of
      // vector_block particles none of which has expired (a test that vectorises) is
      // skipped whole; only a block with an expiry is walked one particle at a time.
      constexpr std::size_t block = Kernel::vector_block;
      std::size_t i = 0;
      while (i < size()) {
        const R* age = arrays().age;
        const R* lifetime = arrays().lifetime;
        if (i % block == 0 && i + block <= size()) {
          bool any_expired = false;
          for (std::size_t k = i; k < i + block; ++k) any_expired |= expired(age[k], lifetime[k]);
          if (!any_expired) {
            i += block;
            continue;
          }
        }
        if (expired(age[i], lifetime[i])) {
          if constexpr (!std::is_same_v<std::remove_cvref_t<OnExpire>, NoCallback>) {
            const ExpiringScope scope(expiring_);
            on_expire(std::as_const(i));
          }
          remove(i);
        } else {
          ++i;
        }
      }
    }
  }

  // step and finish_step without a callback (any configuration, Lifetime or not).
  struct NoCallback {
    void operator()(std::size_t) const noexcept {}
  };
  // Marks the system as inside an expiry callback while it lives.
  struct ExpiringScope {
    bool& flag;
    explicit ExpiringScope(bool& expiring) noexcept : flag(expiring) { flag = true; }
    ExpiringScope(const ExpiringScope&) = delete;
    ExpiringScope& operator=(const ExpiringScope&) = delete;
    ~ExpiringScope() { flag = false; }
  };

  template <std::size_t... I>
  void clear_user_columns([[maybe_unused]] std::size_t i, std::index_sequence<I...>) noexcept {
    ((Layout::template user_pointer<I>(arrays())[i] = typename Layout::template user_element_t<I>{}),
     ...);
  }
  template <std::size_t... I, class... Values>
  void store_user_columns(std::size_t i, std::index_sequence<I...>, const Values&... values) {
    ((Layout::template user_pointer<I>(arrays())[i] = values), ...);
  }

  // Calls store(i, x, y, z) for particles [first, last) with the position at the fraction
  // alpha of the last step (alpha 1: the current position; without Interpolation always).
  // The choice of alpha is made once, outside the loop, so 0 and 1 copy bits.
  template <class Store>
  void for_each_output_position(R alpha, std::size_t first, std::size_t last,
                                Store&& store_one) const {
    const Arrays& a = arrays();
    bool current = true;
    if constexpr (has_interpolation) current = real_equal(alpha, R(1));
    if (current) {
      for (std::size_t i = first; i < last; ++i) {
        store_one(i, a.position_x[i], a.position_y[i], a.position_z[i]);
      }
      return;
    }
    if constexpr (has_interpolation) {
      if (real_equal(alpha, R(0))) {
        for (std::size_t i = first; i < last; ++i) {
          store_one(i, a.previous_position_x[i], a.previous_position_y[i],
                    a.previous_position_z[i]);
        }
        return;
      }
      using E = position_element;
      const E fraction = static_cast<E>(alpha);
      for (std::size_t i = first; i < last; ++i) {
        const E px = a.previous_position_x[i];
        const E py = a.previous_position_y[i];
        const E pz = a.previous_position_z[i];
        store_one(i, px + (a.position_x[i] - px) * fraction,
                  py + (a.position_y[i] - py) * fraction, pz + (a.position_z[i] - pz) * fraction);
      }
    }
  }
  template <class T>
  void copy_strided(const char* function, R alpha, std::span<T> out, std::size_t stride) const {
    if (!detail::check_at_least(function, "stride", stride, 3)) return;
    if (size() == 0) return;
    if (!detail::check_strided_buffer(function, out.size(),
                              (size() - 1) * stride + 3)) {  // no overflow: < max_size() * stride
      return;
    }
    T* data = out.data();
    for_each_output_position(alpha, 0, size(), [&](std::size_t i, auto x, auto y, auto z) {
      T* vertex = data + i * stride;
      vertex[0] = static_cast<T>(x);
      vertex[1] = static_cast<T>(y);
      vertex[2] = static_cast<T>(z);
    });
  }
  template <class V>
  void copy_vectors(const char* function, R alpha, std::span<V> out) const {
    if (!detail::check_buffer(function, "out", out.size(), size())) return;
    V* data = out.data();
    for_each_output_position(alpha, 0, size(), [&](std::size_t i, auto x, auto y, auto z) {
      using T = std::remove_cvref_t<decltype(data[i].x)>;
      data[i].x = static_cast<T>(x);
      data[i].y = static_cast<T>(y);
      data[i].z = static_cast<T>(z);
    });
  }


 public:
  /// True when a particle of this `age` and `lifetime` has expired: its age reached a finite
  /// lifetime (an infinite one never expires, even when the age itself overflows to
  /// infinity). finish_step's test, for loops of one's own (pointmass/kokkos.hpp).
  POINTMASS_HD static constexpr bool expired(R age, R lifetime) noexcept {
    return (age >= lifetime) & (lifetime < real_infinity<R>);
  }

 private:
  bool valid_index([[maybe_unused]] const char* function,
                   [[maybe_unused]] std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
#if POINTMASS_HOST_CHECKS
    return detail::check_index(function, i, size());
#else
    return true;
#endif
  }

  [[noreturn]] static void throw_length_error(const char* function, std::size_t capacity) {
#if POINTMASS_HAS_EXCEPTIONS
    throw std::length_error(std::string("pointmass: ") + function + ": argument 'capacity' = " +
                            std::to_string(capacity) + " must be <= max_size() = " +
                            std::to_string(max_size()));
#else
    detail::report_scalar(function, "capacity", "<= max_size()", capacity);
    std::abort();
#endif
  }

  // Full: doubles the capacity (at least 16), up to max_size().
  void grow() {
    const std::size_t current = capacity();
    if (current >= max_size()) throw_length_error("spawn", current + 1);
    const std::size_t wanted = current < 8 ? 16 : current > max_size() / 2 ? max_size()
                                                                            : 2 * current;
    reserve(wanted);
  }

  void remove(std::size_t index) noexcept {
    const std::size_t last = size() - 1;
    if constexpr (has_handles) handles_.release(arrays().handle_slot[index]);
    if (index != last) {
      Block::move_particle(arrays(), last, index);
      if constexpr (has_handles) handles_.relocate(arrays().handle_slot[index], index);
    }
    set_size(last);
  }

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
    if (!detail::check_finite(function, "position", position)) return false;
    if constexpr (Layout::compensated_positions) {
      return detail::check_representable(
          function, "position", position,
          Vector3<R>{Storage::element_of(position.x), Storage::element_of(position.y),
                     Storage::element_of(position.z)});
    } else {
      return true;
    }
  }
  void store_position(std::size_t i, const Vector3<position_value>& position) noexcept {
    const Arrays& a = arrays();
    if constexpr (Layout::compensated_positions) {
      store(a.position_x, a.position_y, a.position_z, i,
            Vector3<R>{Storage::element_of(position.x), Storage::element_of(position.y),
                       Storage::element_of(position.z)});
      store(a.position_error_x, a.position_error_y, a.position_error_z, i,
            Vector3<R>{Storage::error_of(position.x), Storage::error_of(position.y),
                       Storage::error_of(position.z)});
    } else {
      store(a.position_x, a.position_y, a.position_z, i, position);
    }
    if constexpr (has_interpolation) store_previous_position(i);  // a jump, not a motion
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
  static Vector3<float> relative(const Arrays& a, std::size_t i,
                                 const Vector3<position_value>& origin) noexcept {
    if constexpr (Layout::compensated_positions) {
      return {Storage::relative(a.position_x[i], a.position_error_x[i], origin.x),
              Storage::relative(a.position_y[i], a.position_error_y[i], origin.y),
              Storage::relative(a.position_z[i], a.position_error_z[i], origin.z)};
    } else {
      return {Storage::relative(a.position_x[i], origin.x),
              Storage::relative(a.position_y[i], origin.y),
              Storage::relative(a.position_z[i], origin.z)};
    }
  }

  void set_size(std::size_t size) noexcept { block_.arrays().size = size; }

  Block block_;
  bool backward_ = false;  // the next step walks backwards (see alternates)
  bool expiring_ = false;  // inside an expiry callback (removals are refused)
  [[no_unique_address]] damping_state damping_{};
  Vector3<R> acceleration_{};
  [[no_unique_address]] HandleTable handles_{};
};

}  // namespace pointmass

// Deprecated: defining POINTMASS_ENABLE_PARALLEL before this header still brings in the
// parallel step; include <pointmass/parallel.hpp> instead (the macro goes in the next release).
#if defined(POINTMASS_ENABLE_PARALLEL)
#include "parallel.hpp"
#endif
