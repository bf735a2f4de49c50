// pointmass/particle_system.hpp — many particles in structure-of-arrays form.
//
//   pointmass::ParticleSystem<float>                                   sparks: per-second damping
//                                                                      and gravity for all, p + v t
//   pointmass::ParticleSystem<float, damping::None, position::Euler,
//                             features::Lifetime>                       fireworks that burn out
//   pointmass::ParticleSystem<double, damping::PerSecond, position::SemiImplicit,
//                             features::PerParticleDamping, features::Forces>
//
// ParticleSystem<Real, DampingPolicy, PositionPolicy, Features...> steps many particles with
// the same policies as `Particle` and the same results: each particle's step is
// `advance<D, P>` (particle.hpp) applied to x, y and z apart, so a system and the
// equivalent `Particle`s agree bit for bit (tests/system/ proves it for every policy pair).
//
// "Skip what a scene doesn't need". Everything a scene may do without is a compile-time
// feature tag; what is not chosen is neither stored nor computed:
//
//   tag (namespace features)    stores per particle              without it
//   (always)                    position x, y, z; velocity x, y, z
//   PerParticleDamping          the damping policy's State       one damping for the system:
//                               (d, or d and ln d for Exact);    D::factors (d^t, ...) is
//                               factors computed per particle    computed once per step
//   PerParticleAcceleration     acceleration x, y, z             one acceleration (gravity)
//                                                                for the system
//   Forces                      inverse mass, force accumulator  every particle has mass 1
//                               x, y, z (cleared by each step)   and no force
//   Lifetime                    age, lifetime (seconds); a step  particles live until killed
//                               ages every particle and removes
//                               those with age >= lifetime
//
// With uniform per-second damping a step calls the power function once, not once per
// particle; with PerParticleDamping and PerSecond, AccelerateThenDamp or Exact it calls it
// per particle, which also stops vectorisation of the loop: choose it only when particles
// really differ in drag. Tags may come in any order; an unknown tag is a compile error.
// `storage_bytes_per_particle` tells what a configuration costs in memory.
//
// Storage: one allocation of `capacity()` particles per array, every array in the same block,
// 64-byte aligned, each starting a multiple of 448 bytes (less beyond 9 arrays) further into
// its 4 KiB page than the one before. (Arrays that share their offset within a page make the
// loads of one alias the stores of another in the processor's 4 KiB store-forwarding check;
// staggering them measured up to 1.9x faster.) Capacity is reserved up front (constructor or
// `reserve`); `spawn` beyond it grows the block (doubling), `step` never allocates.
//
// Killing is swap-remove: `kill(i)` moves the last particle into slot i. Order is not kept,
// and an index names a particle only until the next kill, expiry or step with Lifetime.
//
// Access: `position_x()`, `velocity_y()`, ... return std::span over the live particles, for a
// renderer to upload or another engine to compute on. Writing through them skips the
// setters' validation. `arrays()` gives the raw pointers and `step_parameters(t)` the values a
// step shares; `step_particle(arrays, i, parameters)` is the step of particle i, a
// POINTMASS_HD function, so a CUDA, Thrust or Kokkos loop over i computes exactly what
// `step` does (then call `finish_step()` on the host to expire particles).
//
// Vectorisation: the step loop runs over a trip count that is a multiple of 16 (the rest
// apart) and tells the compiler its arrays do not overlap (`#pragma GCC ivdep`, or clang's
// `vectorize(assume_safety)`), so g++ and clang vectorise it at plain -O2 as well as at -O3;
// -march=native (or -mavx2 -mfma) widens the vectors. See docs/performance.md.
//
// Traversal: while the arrays take more than `alternation_floor_bytes` (32 KiB) and at most
// `alternation_limit_bytes` (8 MiB), successive steps walk the particles forwards and
// backwards in turn, so each step begins on the data the previous one left in cache. Same
// results either way; see docs/performance.md.
//
// Parallel: define POINTMASS_ENABLE_PARALLEL before including this header to get
// `pointmass::step(policy, system, t)` for the standard execution policies
// (std::execution::par_unseq, ...). Only then does the header include <execution>; with
// libstdc++ the parallel policies run on TBB, so link TBB (CMake: TBB::tbb). The serial
// `system.step(t)` never touches threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <span>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "damping.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "real.hpp"
#include "vector3.hpp"

#if defined(POINTMASS_ENABLE_PARALLEL)
#include <execution>
#endif

#if defined(__clang__)
#define POINTMASS_DETAIL_INDEPENDENT_ITERATIONS _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__)
#define POINTMASS_DETAIL_INDEPENDENT_ITERATIONS _Pragma("GCC ivdep")
#else
#define POINTMASS_DETAIL_INDEPENDENT_ITERATIONS
#endif

// The step kernel is inlined into its loop even at -O2, where g++ would otherwise call the
// larger configurations' kernel and so not vectorise the loop.
#if defined(__GNUC__)
#define POINTMASS_DETAIL_INLINE [[gnu::always_inline]]
#else
#define POINTMASS_DETAIL_INLINE
#endif

namespace pointmass::features {

/// Each particle has its own damping value (set_damping(i, d)).
struct PerParticleDamping {};
/// Each particle has its own acceleration (set_acceleration(i, a)); otherwise one for all.
struct PerParticleAcceleration {};
/// Each particle has an inverse mass and a force accumulator (add_force(i, f)).
struct Forces {};
/// Each particle has an age and a lifetime; a step removes those whose age reaches it.
struct Lifetime {};

}  // namespace pointmass::features

namespace pointmass {

namespace detail {

template <class T, class... List>
inline constexpr bool contains_v = (std::is_same_v<T, List> || ...);

template <class T>
inline constexpr bool is_feature_v =
    contains_v<T, features::PerParticleDamping, features::PerParticleAcceleration,
               features::Forces, features::Lifetime>;

struct NoFactors {};

}  // namespace detail

template <Real R, DampingPolicy D = damping::PerSecond, PositionPolicyFor<D> P = position::Euler,
          class... Features>
  requires(detail::is_feature_v<Features> && ...)
class ParticleSystem {
 public:
  using real = R;
  using damping_policy = D;
  using position_policy = P;
  using damping_state = typename D::template State<R>;
  using damping_factors = damping_factors_t<D, R>;
  /// The scalar particle whose step this system reproduces.
  using particle_type = Particle<R, D, P>;

  static constexpr bool per_particle_damping =
      detail::contains_v<features::PerParticleDamping, Features...>;
  static constexpr bool per_particle_acceleration =
      detail::contains_v<features::PerParticleAcceleration, Features...>;
  static constexpr bool has_forces = detail::contains_v<features::Forces, Features...>;
  static constexpr bool has_lifetime = detail::contains_v<features::Lifetime, Features...>;
  /// True when the damping policy has a damping value at all (not damping::None).
  static constexpr bool stores_damping = !std::is_empty_v<damping_state>;
  static_assert(!per_particle_damping || stores_damping,
                "features::PerParticleDamping needs a damping policy with a damping value "
                "(damping::None has none)");

  /// Bytes each particle occupies (the block adds under 4.5 KiB per array of padding).
  static constexpr std::size_t storage_bytes_per_particle =
      6 * sizeof(R) + (per_particle_acceleration ? 3 * sizeof(R) : 0) +
      (has_forces ? 4 * sizeof(R) : 0) + (per_particle_damping ? sizeof(damping_state) : 0) +
      (has_lifetime ? 2 * sizeof(R) : 0);
  /// How many arrays the block holds.
  static constexpr std::size_t array_count = 6 + (per_particle_acceleration ? 3 : 0) +
                                             (has_forces ? 4 : 0) +
                                             (per_particle_damping ? 1 : 0) +
                                             (has_lifetime ? 2 : 0);

  /// Returned by spawn when its input was rejected.
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  /// Raw pointers to the arrays (nullptr for those the configuration does not store) and
  /// the number of live particles: what step_particle works on.
  struct Arrays {
    R* position_x = nullptr;
    R* position_y = nullptr;
    R* position_z = nullptr;
    R* velocity_x = nullptr;
    R* velocity_y = nullptr;
    R* velocity_z = nullptr;
    R* acceleration_x = nullptr;
    R* acceleration_y = nullptr;
    R* acceleration_z = nullptr;
    R* inverse_mass = nullptr;
    R* force_x = nullptr;
    R* force_y = nullptr;
    R* force_z = nullptr;
    damping_state* damping = nullptr;
    R* age = nullptr;
    R* lifetime = nullptr;
    std::size_t size = 0;
  };

  /// What every particle's step shares: the duration, the uniform damping factors (d^t, ...)
  /// and the uniform acceleration, where the configuration has them.
  struct StepParameters {
    R duration{};
    [[no_unique_address]] std::conditional_t<per_particle_damping, detail::NoFactors,
                                             damping_factors> factors{};
    Vector3<R> acceleration{};
  };

  // --- construction --------------------------------------------------------------------------

  ParticleSystem() = default;
  /// An empty system with room for `capacity` particles.
  explicit ParticleSystem(std::size_t capacity) { reserve(capacity); }

  ParticleSystem(const ParticleSystem& other)
      : damping_(other.damping_), acceleration_(other.acceleration_) {
    reserve(other.capacity_);
    copy_arrays(other, other.size_);
    size_ = other.size_;
  }
  ParticleSystem(ParticleSystem&& other) noexcept
      : block_(std::exchange(other.block_, nullptr)),
        arrays_(std::exchange(other.arrays_, Arrays{})),
        size_(std::exchange(other.size_, 0)),
        capacity_(std::exchange(other.capacity_, 0)),
        backward_(std::exchange(other.backward_, false)),
        damping_(other.damping_),
        acceleration_(other.acceleration_) {}
  ParticleSystem& operator=(ParticleSystem other) noexcept {
    swap(other);
    return *this;
  }
  ~ParticleSystem() { release(block_); }

  void swap(ParticleSystem& other) noexcept {
    std::swap(block_, other.block_);
    std::swap(arrays_, other.arrays_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
    std::swap(backward_, other.backward_);
    std::swap(damping_, other.damping_);
    std::swap(acceleration_, other.acceleration_);
  }

  // --- size and capacity ---------------------------------------------------------------------

  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  std::size_t capacity() const noexcept { return capacity_; }

  /// Makes room for `capacity` particles in one block (no-op if there is room already).
  void reserve(std::size_t capacity) {
    if (capacity <= capacity_) return;
    ParticleSystem grown;
    grown.allocate(capacity);
    grown.copy_arrays(*this, size_);
    std::swap(block_, grown.block_);
    std::swap(arrays_, grown.arrays_);
    std::swap(capacity_, grown.capacity_);
    arrays_.size = size_;
  }
  /// Removes every particle; keeps the capacity.
  void clear() noexcept { set_size(0); }

  // --- uniform values ------------------------------------------------------------------------

  /// The acceleration of every particle (gravity); finite.
  void set_acceleration(const Vector3<R>& acceleration)
    requires(!per_particle_acceleration)
  {
    if (!is_finite(acceleration)) {
      detail::report_vector("set_acceleration", "acceleration", "finite", acceleration);
      return;
    }
    acceleration_ = acceleration;
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
    if (check_damping("set_damping", damping)) damping_ = damping_state(damping);
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
  std::size_t spawn(const Vector3<R>& position, const Vector3<R>& velocity) {
    if (!is_finite(position)) return reject_vector("spawn", "position", position);
    if (!is_finite(velocity)) return reject_vector("spawn", "velocity", velocity);
    if (size_ == capacity_) reserve(capacity_ < 8 ? 16 : 2 * capacity_);
    const std::size_t i = size_;
    set_size(size_ + 1);
    store(arrays_.position_x, arrays_.position_y, arrays_.position_z, i, position);
    store(arrays_.velocity_x, arrays_.velocity_y, arrays_.velocity_z, i, velocity);
    if constexpr (per_particle_acceleration) {
      store(arrays_.acceleration_x, arrays_.acceleration_y, arrays_.acceleration_z, i, {});
    }
    if constexpr (has_forces) {
      arrays_.inverse_mass[i] = R(1);
      store(arrays_.force_x, arrays_.force_y, arrays_.force_z, i, {});
    }
    if constexpr (per_particle_damping) arrays_.damping[i] = damping_state{};
    if constexpr (has_lifetime) {
      arrays_.age[i] = R(0);
      arrays_.lifetime[i] = real_infinity<R>;
    }
    return i;
  }
  /// Adds a copy of `particle`: its position and velocity, and whichever of its
  /// acceleration, damping, inverse mass and accumulated force the system stores per
  /// particle (the others are the system's uniform values).
  std::size_t spawn(const particle_type& particle) {
    const std::size_t i = spawn(particle.position(), particle.velocity());
    if (i == npos) return npos;
    if constexpr (per_particle_acceleration) {
      store(arrays_.acceleration_x, arrays_.acceleration_y, arrays_.acceleration_z, i,
            particle.acceleration());
    }
    if constexpr (has_forces) {
      arrays_.inverse_mass[i] = particle.inverse_mass();
      store(arrays_.force_x, arrays_.force_y, arrays_.force_z, i, particle.force_accumulator());
    }
    if constexpr (per_particle_damping) arrays_.damping[i] = damping_state(particle.damping());
    return i;
  }

  /// Removes particle `index` by moving the last particle into its place (order not kept).
  void kill(std::size_t index) {
    if (!check_index("kill", index)) return;
    const std::size_t last = size_ - 1;
    if (index != last) move_particle(last, index);
    set_size(last);
  }
  /// Removes every particle for which predicate(index) is true, by swap-remove, and returns
  /// how many. The predicate sees each particle once; after a removal it is asked about the
  /// particle moved into the freed index.
  template <class Predicate>
  std::size_t kill_if(Predicate&& predicate) {
    const std::size_t before = size_;
    std::size_t i = 0;
    while (i < size_) {
      if (predicate(i)) {
        const std::size_t last = size_ - 1;
        if (i != last) move_particle(last, i);
        set_size(last);
      } else {
        ++i;
      }
    }
    return before - size_;
  }

  // --- per-particle values -------------------------------------------------------------------

  Vector3<R> position(std::size_t i) const noexcept {
    return load(arrays_.position_x, arrays_.position_y, arrays_.position_z, i);
  }
  Vector3<R> velocity(std::size_t i) const noexcept {
    return load(arrays_.velocity_x, arrays_.velocity_y, arrays_.velocity_z, i);
  }
  /// The acceleration particle i has (its own, or the system's).
  Vector3<R> acceleration(std::size_t i) const noexcept {
    if constexpr (per_particle_acceleration) {
      return load(arrays_.acceleration_x, arrays_.acceleration_y, arrays_.acceleration_z, i);
    } else {
      static_cast<void>(i);
      return acceleration_;
    }
  }
  /// The damping particle i has (its own, or the system's).
  R damping(std::size_t i) const noexcept {
    if constexpr (per_particle_damping) {
      return arrays_.damping[i].value();
    } else {
      static_cast<void>(i);
      return damping_.value();
    }
  }

  void set_position(std::size_t i, const Vector3<R>& position) {
    if (check_index("set_position", i) && check_finite("set_position", "position", position)) {
      store(arrays_.position_x, arrays_.position_y, arrays_.position_z, i, position);
    }
  }
  void set_velocity(std::size_t i, const Vector3<R>& velocity) {
    if (check_index("set_velocity", i) && check_finite("set_velocity", "velocity", velocity)) {
      store(arrays_.velocity_x, arrays_.velocity_y, arrays_.velocity_z, i, velocity);
    }
  }
  void set_acceleration(std::size_t i, const Vector3<R>& acceleration)
    requires per_particle_acceleration
  {
    if (check_index("set_acceleration", i) &&
        check_finite("set_acceleration", "acceleration", acceleration)) {
      store(arrays_.acceleration_x, arrays_.acceleration_y, arrays_.acceleration_z, i,
            acceleration);
    }
  }
  void set_damping(std::size_t i, R damping)
    requires per_particle_damping
  {
    if (check_index("set_damping", i) && check_damping("set_damping", damping)) {
      arrays_.damping[i] = damping_state(damping);
    }
  }

  R inverse_mass(std::size_t i) const noexcept
    requires has_forces
  {
    return arrays_.inverse_mass[i];
  }
  Vector3<R> force_accumulator(std::size_t i) const noexcept
    requires has_forces
  {
    return load(arrays_.force_x, arrays_.force_y, arrays_.force_z, i);
  }
  /// mass > 0 (infinity makes the particle immovable), with 1/mass finite.
  void set_mass(std::size_t i, R mass)
    requires has_forces
  {
    if (!check_index("set_mass", i)) return;
    if (real_isnan(mass) || !(mass > R(0)) || !real_isfinite(R(1) / mass)) {
      detail::report_scalar("set_mass", "mass", "> 0, not NaN, with 1/mass finite", mass);
      return;
    }
    arrays_.inverse_mass[i] = R(1) / mass;
  }
  /// inverse mass >= 0 and finite; 0 makes the particle immovable.
  void set_inverse_mass(std::size_t i, R inverse_mass)
    requires has_forces
  {
    if (!check_index("set_inverse_mass", i)) return;
    if (!real_isfinite(inverse_mass) || inverse_mass < R(0)) {
      detail::report_scalar("set_inverse_mass", "inverse_mass", ">= 0 and finite", inverse_mass);
      return;
    }
    arrays_.inverse_mass[i] = inverse_mass;
  }
  /// Adds a force to particle i for the next step only.
  void add_force(std::size_t i, const Vector3<R>& force)
    requires has_forces
  {
    if (!check_index("add_force", i) || !check_finite("add_force", "force", force)) return;
    arrays_.force_x[i] += force.x;
    arrays_.force_y[i] += force.y;
    arrays_.force_z[i] += force.z;
  }

  R age(std::size_t i) const noexcept
    requires has_lifetime
  {
    return arrays_.age[i];
  }
  R lifetime(std::size_t i) const noexcept
    requires has_lifetime
  {
    return arrays_.lifetime[i];
  }
  /// Seconds particle i lives (> 0; infinity for ever). It is removed by the step after
  /// which its age reaches this.
  void set_lifetime(std::size_t i, R seconds)
    requires has_lifetime
  {
    if (!check_index("set_lifetime", i)) return;
    if (real_isnan(seconds) || !(seconds > R(0))) {
      detail::report_scalar("set_lifetime", "seconds", "> 0 (infinity: for ever)", seconds);
      return;
    }
    arrays_.lifetime[i] = seconds;
  }

  // --- spans for renderers and other engines -------------------------------------------------

  std::span<R> position_x() noexcept { return {arrays_.position_x, size_}; }
  std::span<R> position_y() noexcept { return {arrays_.position_y, size_}; }
  std::span<R> position_z() noexcept { return {arrays_.position_z, size_}; }
  std::span<R> velocity_x() noexcept { return {arrays_.velocity_x, size_}; }
  std::span<R> velocity_y() noexcept { return {arrays_.velocity_y, size_}; }
  std::span<R> velocity_z() noexcept { return {arrays_.velocity_z, size_}; }
  std::span<const R> position_x() const noexcept { return {arrays_.position_x, size_}; }
  std::span<const R> position_y() const noexcept { return {arrays_.position_y, size_}; }
  std::span<const R> position_z() const noexcept { return {arrays_.position_z, size_}; }
  std::span<const R> velocity_x() const noexcept { return {arrays_.velocity_x, size_}; }
  std::span<const R> velocity_y() const noexcept { return {arrays_.velocity_y, size_}; }
  std::span<const R> velocity_z() const noexcept { return {arrays_.velocity_z, size_}; }
  std::span<R> acceleration_x() noexcept
    requires per_particle_acceleration
  {
    return {arrays_.acceleration_x, size_};
  }
  std::span<R> acceleration_y() noexcept
    requires per_particle_acceleration
  {
    return {arrays_.acceleration_y, size_};
  }
  std::span<R> acceleration_z() noexcept
    requires per_particle_acceleration
  {
    return {arrays_.acceleration_z, size_};
  }
  std::span<R> inverse_masses() noexcept
    requires has_forces
  {
    return {arrays_.inverse_mass, size_};
  }
  std::span<R> force_x() noexcept
    requires has_forces
  {
    return {arrays_.force_x, size_};
  }
  std::span<R> force_y() noexcept
    requires has_forces
  {
    return {arrays_.force_y, size_};
  }
  std::span<R> force_z() noexcept
    requires has_forces
  {
    return {arrays_.force_z, size_};
  }
  std::span<damping_state> damping_states() noexcept
    requires per_particle_damping
  {
    return {arrays_.damping, size_};
  }
  std::span<R> ages() noexcept
    requires has_lifetime
  {
    return {arrays_.age, size_};
  }
  std::span<R> lifetimes() noexcept
    requires has_lifetime
  {
    return {arrays_.lifetime, size_};
  }

  /// The raw arrays (see step_particle). Valid until the next spawn, reserve or move.
  const Arrays& arrays() const noexcept { return arrays_; }

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

  /// The step of particle i, as Particle::integrate computes it:
  ///   a  = acceleration + force * inverse_mass;  v1 = D::velocity(v0, a, t, f);
  ///   p1 = P::position(p0, v0, v1, a, t, f);     force = 0;  age += t
  /// on each of x, y and z (advance<D, P> in particle.hpp). A particle of inverse mass 0 does
  /// not move. Plain arithmetic on the arrays: runs on a GPU as it runs here.
  POINTMASS_DETAIL_INLINE POINTMASS_HD static constexpr void step_particle(const Arrays& arrays, std::size_t i,
                                                   const StepParameters& parameters) noexcept {
    const R t = parameters.duration;
    const auto factors = factors_of(arrays, i, parameters);
    R ax, ay, az;
    if constexpr (per_particle_acceleration) {
      ax = arrays.acceleration_x[i];
      ay = arrays.acceleration_y[i];
      az = arrays.acceleration_z[i];
    } else {
      ax = parameters.acceleration.x;
      ay = parameters.acceleration.y;
      az = parameters.acceleration.z;
    }
    if constexpr (has_forces) {
      const R inverse_mass = arrays.inverse_mass[i];
      ax = ax + arrays.force_x[i] * inverse_mass;
      ay = ay + arrays.force_y[i] * inverse_mass;
      az = az + arrays.force_z[i] * inverse_mass;
      arrays.force_x[i] = R(0);
      arrays.force_y[i] = R(0);
      arrays.force_z[i] = R(0);
      const bool movable = inverse_mass > R(0);
      advance_if(movable, arrays.position_x[i], arrays.velocity_x[i], ax, t, factors);
      advance_if(movable, arrays.position_y[i], arrays.velocity_y[i], ay, t, factors);
      advance_if(movable, arrays.position_z[i], arrays.velocity_z[i], az, t, factors);
    } else {
      advance<D, P>(arrays.position_x[i], arrays.velocity_x[i], ax, t, factors);
      advance<D, P>(arrays.position_y[i], arrays.velocity_y[i], ay, t, factors);
      advance<D, P>(arrays.position_z[i], arrays.velocity_z[i], az, t, factors);
    }
    if constexpr (has_lifetime) arrays.age[i] += t;
  }

  /// Steps particles [begin, end): the vectorised loop over step_particle.
#if defined(__clang__)
#pragma clang diagnostic push
  // Some configurations do not vectorise (a power function per particle; clang 14 also
  // declines float damping::Exact). clang reports that against the function, not the loop,
  // so the whole function is in the region where the warning is off: -Werror builds of
  // users' code must not fail on it.
#pragma clang diagnostic ignored "-Wpass-failed"
#endif
  static void step_range(const Arrays& arrays_in, std::size_t begin, std::size_t end,
                         const StepParameters& parameters_in) noexcept {
    // Local copies: the loop's stores cannot alias them, so the compiler keeps the shared
    // values in registers instead of reloading them for every vector of particles.
    const Arrays arrays = arrays_in;
    const StepParameters parameters = parameters_in;
    step_segment(arrays, begin, end - begin, parameters);
  }

  /// Steps particles [begin, end) as step_range does, with the same results, but walks them
  /// from the end: the part past the last whole chunk of backward_chunk first, then whole
  /// chunks from the last to the first, each chunk forwards through the same vectorised
  /// loop (a single copy of it in this function: clang 14 lost the loop's no-alias mark on
  /// a second inlined copy and left that copy scalar).
  static void step_range_backward(const Arrays& arrays_in, std::size_t begin, std::size_t end,
                                  const StepParameters& parameters_in) noexcept {
    const Arrays arrays = arrays_in;  // local copies, as in step_range
    const StepParameters parameters = parameters_in;
    std::size_t first = end - (end - begin) % backward_chunk;
    std::size_t count = end - first;
    for (;;) {
      step_segment(arrays, first, count, parameters);
      if (first == begin) break;
      first -= backward_chunk;
      count = backward_chunk;
    }
  }

 private:
  // Particles [first, first + count): the loop marked for vectorisation (when the
  // configuration can vectorise) over a trip count that is a multiple of vector_block, which
  // lets g++'s -O2 cost model vectorise it without a remainder loop; then the remainder.
  POINTMASS_DETAIL_INLINE static void step_segment(const Arrays& arrays, std::size_t first,
                                                   std::size_t count,
                                                   const StepParameters& parameters) noexcept {
    const std::size_t blocked = count & ~(vector_block - 1);
    if constexpr (vectorisable) {
      POINTMASS_DETAIL_INDEPENDENT_ITERATIONS
      for (std::size_t k = 0; k < blocked; ++k) step_particle(arrays, first + k, parameters);
    } else {  // a power function per particle: no vector loop to ask for
      for (std::size_t k = 0; k < blocked; ++k) step_particle(arrays, first + k, parameters);
    }
    for (std::size_t k = blocked; k < count; ++k) step_particle(arrays, first + k, parameters);
  }

 public:
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

  /// After the particles have stepped: removes those whose age reached their lifetime.
  /// Called by step; call it yourself after stepping through step_particle elsewhere.
  void finish_step() {
    if constexpr (has_lifetime) {
      // kill_if's order and result, but a step expires few particles: a block of
      // vector_block particles none of which has expired (a test that vectorises) is
      // skipped whole; only a block with an expiry is walked one particle at a time.
      const R* age = arrays_.age;
      const R* lifetime = arrays_.lifetime;
      std::size_t i = 0;
      while (i < size_) {
        if (i % vector_block == 0 && i + vector_block <= size_) {
          bool any_expired = false;
          for (std::size_t k = i; k < i + vector_block; ++k) {
            any_expired |= !(age[k] < lifetime[k]);
          }
          if (!any_expired) {
            i += vector_block;
            continue;
          }
        }
        if (age[i] < lifetime[i]) {
          ++i;
        } else {
          const std::size_t last = size_ - 1;
          if (i != last) move_particle(last, i);
          set_size(last);
        }
      }
    }
  }

  /// Advances every particle by `duration` seconds (see step_particle), then expires those
  /// whose lifetime is over. A negative, NaN or infinite duration is a contract violation,
  /// checked when POINTMASS_CHECKS is on; zero changes nothing. Allocates nothing.
  void step(R duration) {
    if (!begin_step(duration)) return;
    const StepParameters parameters = step_parameters(duration);
    (backward_ ? step_range_backward : step_range)(arrays_, 0, size_, parameters);
    backward_ = !backward_ && alternates(size_);
    finish_step();
  }

  /// True when the next `step` walks the particles backwards (see alternates). A copy
  /// starts forwards; a move or swap takes the direction along.
  bool next_step_backward() const noexcept { return backward_; }

  /// True when `step` alternates its walk for a system of `count` particles: when their
  /// arrays take more than alternation_floor_bytes and at most alternation_limit_bytes.
  static constexpr bool alternates(std::size_t count) noexcept {
    const std::size_t bytes = count * storage_bytes_per_particle;
    return bytes > alternation_floor_bytes && bytes <= alternation_limit_bytes;
  }

  /// While the arrays take at most this many bytes, `step` walks the particles forwards and
  /// backwards in turn: each step then starts on the particles the step before finished
  /// with, still in the processor's caches, instead of on those evicted longest ago. The
  /// results are the same either way (every particle's step is independent of the others).
  /// Beyond a few times the size of a core's L2 cache, the cached share is too small to
  /// repay the backward walk's weaker hardware prefetch, so larger systems always walk
  /// forwards. docs/performance.md has the measurements on both sides of the limit.
  static constexpr std::size_t alternation_limit_bytes = std::size_t{8} << 20;
  /// Arrays that fit in a 32 KiB L1 data cache stay there whichever way a step walks, so
  /// systems this small (1,365 float or 682 double particles with six arrays) always walk
  /// forwards, the cheaper loop.
  static constexpr std::size_t alternation_floor_bytes = std::size_t{32} << 10;
  /// The backward walk's chunk, a multiple of vector_block.
  static constexpr std::size_t backward_chunk = 256;

  /// True if a step of `duration` has work to do; reports a bad duration (when checked).
  bool begin_step(R duration) const {
#if POINTMASS_CHECKS
    if (!real_isfinite(duration) || duration < R(0)) {
      detail::report_scalar("step", "duration", "finite and >= 0", duration);
      return false;
    }
#endif
    return duration != R(0) && size_ != 0;
  }

  /// False when a step calls a power function (or expm1) per particle: per-particle damping
  /// with any policy but PerFrame. Only a vectorisable loop is marked for vectorisation.
  static constexpr bool vectorisable =
      !per_particle_damping || std::is_same_v<D, damping::PerFrame>;

  /// The loop's trip count is a multiple of this (the widest vector: 16 floats, 8 doubles).
  static constexpr std::size_t vector_block = 16;
  static_assert(backward_chunk % vector_block == 0);

 private:
  POINTMASS_DETAIL_INLINE POINTMASS_HD static constexpr auto factors_of(const Arrays& arrays, std::size_t i,
                                                const StepParameters& parameters) noexcept {
    if constexpr (per_particle_damping) {
      return D::factors(arrays.damping[i], parameters.duration);
    } else {
      static_cast<void>(arrays);
      static_cast<void>(i);
      return parameters.factors;
    }
  }

  // Both outcomes computed, one kept: a select the vectoriser can do, where a branch is not.
  template <class F>
  POINTMASS_DETAIL_INLINE POINTMASS_HD static constexpr void advance_if(bool movable, R& p, R& v, R a, R t,
                                                const F& factors) noexcept {
    R p1 = p;
    R v1 = v;
    advance<D, P>(p1, v1, a, t, factors);
    p = select(movable, p1, p);
    v = select(movable, v1, v);
  }

  // condition ? if_true : if_false, as bit operations (g++ -O2 does not if-convert `?:` here).
  POINTMASS_DETAIL_INLINE POINTMASS_HD static constexpr R select(bool condition, R if_true,
                                                                 R if_false) noexcept {
    if constexpr (sizeof(R) == 4 || sizeof(R) == 8) {
      using Bits = std::conditional_t<sizeof(R) == 4, std::uint32_t, std::uint64_t>;
      const Bits mask = Bits(0) - static_cast<Bits>(condition);
      return __builtin_bit_cast(R, static_cast<Bits>((__builtin_bit_cast(Bits, if_true) & mask) |
                                                     (__builtin_bit_cast(Bits, if_false) & ~mask)));
    } else {
      return condition ? if_true : if_false;
    }
  }

  static void store(R* x, R* y, R* z, std::size_t i, const Vector3<R>& value) noexcept {
    x[i] = value.x;
    y[i] = value.y;
    z[i] = value.z;
  }
  static Vector3<R> load(const R* x, const R* y, const R* z, std::size_t i) noexcept {
    return {x[i], y[i], z[i]};
  }

  bool check_index(const char* function, std::size_t index) const {
    if (index < size_) return true;
    detail::report_scalar(function, "index", "< size()", index);
    return false;
  }
  static bool check_finite(const char* function, const char* argument, const Vector3<R>& v) {
    if (is_finite(v)) return true;
    detail::report_vector(function, argument, "finite", v);
    return false;
  }
  static bool check_damping(const char* function, R damping) {
    if (!real_isnan(damping) && damping >= R(0) && damping <= R(1)) return true;
    detail::report_scalar(function, "damping", "in [0, 1]", damping);
    return false;
  }
  static std::size_t reject_vector(const char* function, const char* argument,
                                   const Vector3<R>& v) {
    detail::report_vector(function, argument, "finite", v);
    return npos;
  }

  void set_size(std::size_t size) noexcept {
    size_ = size;
    arrays_.size = size;
  }

  template <class T>
  static void move_element(T* array, std::size_t from, std::size_t to) noexcept {
    if (array != nullptr) array[to] = array[from];
  }
  void move_particle(std::size_t from, std::size_t to) noexcept {
    for_each_array([&](auto* array) { move_element(array, from, to); });
  }

  // Calls f on every array pointer of arrays_ (nullptr for those not stored), in block order.
  template <class F>
  void for_each_array(F&& f) {
    for_each_array_of(arrays_, f);
  }
  template <class A, class F>
  static void for_each_array_of(A& a, F&& f) {
    f(a.position_x), f(a.position_y), f(a.position_z);
    f(a.velocity_x), f(a.velocity_y), f(a.velocity_z);
    f(a.acceleration_x), f(a.acceleration_y), f(a.acceleration_z);
    f(a.inverse_mass), f(a.force_x), f(a.force_y), f(a.force_z);
    f(a.damping), f(a.age), f(a.lifetime);
  }

  // The block: each array's bytes rounded up to whole 4 KiB pages, plus a stagger, so array
  // k starts k * stagger bytes into its page (mod 4096).
  static constexpr std::size_t page = 4096;
  static constexpr std::size_t alignment = 64;
  static constexpr std::size_t stagger =
      std::min<std::size_t>(448, page / array_count / alignment * alignment);

  static std::size_t array_span_bytes(std::size_t bytes) noexcept {
    return (bytes + page - 1) / page * page + stagger;
  }

  void allocate(std::size_t capacity) {
    std::size_t offsets[16] = {};
    std::size_t total = 0;
    std::size_t k = 0;
    auto place = [&](std::size_t element_size, bool is_stored) {
      offsets[k++] = is_stored ? total : npos;
      if (is_stored) total += array_span_bytes(capacity * element_size);
    };
    for (int j = 0; j < 6; ++j) place(sizeof(R), true);
    for (int j = 0; j < 3; ++j) place(sizeof(R), per_particle_acceleration);
    for (int j = 0; j < 4; ++j) place(sizeof(R), has_forces);
    place(sizeof(damping_state), per_particle_damping);
    for (int j = 0; j < 2; ++j) place(sizeof(R), has_lifetime);

    block_ = static_cast<std::byte*>(::operator new(total, std::align_val_t{alignment}));
    capacity_ = capacity;
    k = 0;
    std::byte* const base = block_;
    for_each_array([&](auto*& array) {
      using T = std::remove_pointer_t<std::remove_reference_t<decltype(array)>>;
      const std::size_t offset = offsets[k++];
      array = offset == npos ? nullptr : reinterpret_cast<T*>(base + offset);
    });
  }
  static void release(std::byte* block) noexcept {
    if (block != nullptr) ::operator delete(block, std::align_val_t{alignment});
  }

  // Copies the first `count` particles of `other`'s arrays into this one's.
  void copy_arrays(const ParticleSystem& other, std::size_t count) noexcept {
    if (count == 0) return;
    Arrays source = other.arrays_;
    std::size_t k = 0;
    void* sources[16] = {};
    for_each_array_of(source, [&](auto* array) { sources[k++] = array; });
    k = 0;
    for_each_array([&](auto* array) {
      using T = std::remove_pointer_t<decltype(array)>;
      const void* from = sources[k++];
      if (array != nullptr) std::memcpy(array, from, count * sizeof(T));
    });
  }

  std::byte* block_ = nullptr;
  Arrays arrays_{};
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
  bool backward_ = false;  // the next step walks backwards (see alternates)
  [[no_unique_address]] damping_state damping_{};
  Vector3<R> acceleration_{};
};

#if defined(POINTMASS_ENABLE_PARALLEL)

namespace detail {

/// A random-access iterator over the numbers 0, 1, 2, ...: the chunks a parallel step runs.
class CountingIterator {
 public:
  using iterator_category = std::random_access_iterator_tag;
  using value_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using pointer = const std::size_t*;
  using reference = std::size_t;

  CountingIterator() = default;
  explicit CountingIterator(std::size_t value) noexcept : value_(value) {}
  std::size_t operator*() const noexcept { return value_; }
  std::size_t operator[](difference_type n) const noexcept {
    return value_ + static_cast<std::size_t>(n);
  }
  CountingIterator& operator++() noexcept { return ++value_, *this; }
  CountingIterator operator++(int) noexcept { return CountingIterator(value_++); }
  CountingIterator& operator--() noexcept { return --value_, *this; }
  CountingIterator operator--(int) noexcept { return CountingIterator(value_--); }
  CountingIterator& operator+=(difference_type n) noexcept {
    value_ += static_cast<std::size_t>(n);
    return *this;
  }
  CountingIterator& operator-=(difference_type n) noexcept {
    value_ -= static_cast<std::size_t>(n);
    return *this;
  }
  friend CountingIterator operator+(CountingIterator i, difference_type n) noexcept {
    return i += n;
  }
  friend CountingIterator operator+(difference_type n, CountingIterator i) noexcept {
    return i += n;
  }
  friend CountingIterator operator-(CountingIterator i, difference_type n) noexcept {
    return i -= n;
  }
  friend difference_type operator-(CountingIterator a, CountingIterator b) noexcept {
    return static_cast<difference_type>(a.value_) - static_cast<difference_type>(b.value_);
  }
  friend auto operator<=>(CountingIterator, CountingIterator) = default;

 private:
  std::size_t value_ = 0;
};

}  // namespace detail

/// Steps `system` by `duration` with the execution policy `policy` (for example
/// std::execution::par_unseq): the particles are split into chunks of 16,384, each stepped
/// by the vectorised loop; expiry (Lifetime) then runs on the calling thread. The results
/// are those of system.step(duration), bit for bit.
template <class ExecutionPolicy, Real R, class D, class P, class... Features>
  requires std::is_execution_policy_v<std::remove_cvref_t<ExecutionPolicy>>
void step(ExecutionPolicy&& policy, ParticleSystem<R, D, P, Features...>& system, R duration) {
  using System = ParticleSystem<R, D, P, Features...>;
  if (!system.begin_step(duration)) return;
  constexpr std::size_t chunk = 16384;
  const typename System::Arrays& arrays = system.arrays();
  const typename System::StepParameters parameters = system.step_parameters(duration);
  const std::size_t size = system.size();
  const std::size_t chunks = (size + chunk - 1) / chunk;
  std::for_each(std::forward<ExecutionPolicy>(policy), detail::CountingIterator(0),
                detail::CountingIterator(chunks), [&](std::size_t c) {
                  const std::size_t begin = c * chunk;
                  System::step_range(arrays, begin, std::min(begin + chunk, size), parameters);
                });
  system.finish_step();
}

#endif  // POINTMASS_ENABLE_PARALLEL

}  // namespace pointmass
