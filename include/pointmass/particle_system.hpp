// SPDX-License-Identifier: BSL-1.0
// pointmass/particle_system.hpp — many particles in structure-of-arrays form: the public API.
//
//   ParticleSystem<float>                                           sparks: per-second damping
//                                                                   and gravity for all, p + v t
//   ParticleSystem<float, damping::None, position::Euler, features::Lifetime>      fireworks
//   ParticleSystem<double, damping::Exact, position::Exact,
//                  features::PerParticleDamping, features::ForceAccumulator>       debris
//   ParticleSystem<Precision<float, Compensated<float>>>            far from the origin
//
// ParticleSystem<S, DampingPolicy, PositionPolicy, Features...> steps many particles with the
// policies of `Particle` and its results, bit for bit: each particle's step is advance<D, P>
// (particle.hpp) on x, y and z (tests/system/ proves it for every policy pair). S is a Real or
// a Precision<Real, Position> (precision.hpp). Each feature tag (features.hpp) adds what it
// stores, and what is not chosen is neither stored nor computed. docs/particle-system.md is
// the user's guide: every member family with an example, and the rules below in full.
//
// Rules in brief. Removal is swap-remove, so an index names a particle until the next kill,
// kill_if, clear or step with Lifetime; a handle (features::Handles) for as long as it lives.
// Spans, arrays() and pointers into them are valid until the next spawn that grows the block,
// reserve, move or swap. Indices are checked when POINTMASS_CHECKS is on; otherwise an index
// >= size() is undefined behaviour, as for std::vector::operator[]. Bad values are reported
// (config.hpp) and change nothing. `step` never allocates.
//
// Members by header. Here: the types and traits, construction and capacity, the uniform
// values, spawning and killing, each particle's position, velocity, acceleration and
// damping, arrays() and the step. The rest come from the facets, empty public bases (each
// documents its members where it lives):
//   system/columns.hpp            column<C>(), position_x() ... velocity_z(), and the user
//                                 columns: column<Tag>(), column<Tag>(i), set_column<Tag>
//   system/handles.hpp            Handle, handle, find, contains, handle_table_bytes
//   system/force_accumulator.hpp  inverse_mass, force_accumulator, set_mass,
//                                 set_inverse_mass, add_force
//   system/lifetime.hpp           age, lifetime, set_lifetime
//   system/interpolation.hpp      previous_position, interpolated_position,
//                                 copy_interpolated_positions
//   system/hand_off.hpp           copy_positions, positions_relative_to, position_relative_to
//
// Owns: the public API, the line of facets, and detail::SystemAccess (what the steps of
// parallel.hpp and kokkos.hpp reach of the state). Below it: features.hpp (the tags and the
// table of arrays), detail/system_state.hpp (what the system holds, and how each call
// works), detail/soa_block.hpp (the one allocation), detail/system_kernel.hpp (the step
// loop).
// Must not include: <execution> or anything that starts threads (parallel.hpp adds those).
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "damping.hpp"
#include "detail/system_kernel.hpp"
#include "detail/system_state.hpp"
#include "detail/validate.hpp"
#include "features.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "real.hpp"
#include "system/columns.hpp"
#include "system/force_accumulator.hpp"
#include "system/hand_off.hpp"
#include "system/handles.hpp"
#include "system/interpolation.hpp"
#include "system/lifetime.hpp"
#include "vector3.hpp"

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {
// The facets (detail::SystemFacets, below) stand in one line rather than one base each, so that
// no two empty bases share a type (an API probe compares sizeof with the state's). A facet's
// member that needs a feature is constrained on the layout's trait (`requires
// Base::Layout::has_handles`), never on the class being defined; names that overload one
// another (column<C>() and column<Tag>()) stay in one facet, since a derived class's member
// hides a base's. A new facet: a header under system/ with the same opening comment, one more
// link in the line, and its line in this file's opening comment.

namespace detail {
// The facets, each over the one before it and the first over the state: one line of bases,
// in which every facet is empty (a system is as big as its state).
template <class State>
using SystemFacets = SystemHandOff<SystemInterpolation<
    SystemLifetime<SystemForceAccumulator<SystemHandles<SystemColumns<State>>>>>>;
}  // namespace detail

// clang-format off
template <class S, DampingPolicy D = damping::PerSecond, class P = position::Euler,
          class... Features>
  requires((Real<S> || PrecisionChoice<S>) && (detail::is_feature_v<Features> && ...))
class ParticleSystem
    : public detail::SystemKernel<real_of_t<S>, D, P, detail::SystemLayout<S, D, Features...>>,
      public detail::SystemFacets<detail::SystemStateBase<S, D, P, Features...>> {
  // clang-format on
  using State = detail::SystemState<S, D, P, Features...>;
  using Facets = detail::SystemFacets<detail::SystemStateBase<S, D, P, Features...>>;
  using R = real_of_t<S>;
  using Layout = typename State::Layout;
  using Kernel = typename State::Kernel;
  using State::acceleration_;
  using State::damping_;
  using State::load;
  using State::removing_;
  using State::store;
  using State::valid_index;
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
  using position_value = typename State::position_value;
  /// The element of the position columns (position_x(), ..., and the previous positions).
  using position_element = typename Layout::position_element;
  /// Raw pointers to the arrays (nullptr for those not stored) and the number of live
  /// particles: what step_particle works on.
  using Arrays = typename Layout::Arrays;
  using typename Kernel::StepParameters;
  /// A particle's stable name (features::Handles; system/handles.hpp).
  using typename Facets::Handle;
  // The columns' traits (element_t, stores, user_columns, user_column_count, user_element_t,
  // has_column) are system/columns.hpp's.

  static constexpr bool per_particle_damping = Layout::per_particle_damping;
  static constexpr bool per_particle_acceleration = Layout::per_particle_acceleration;
  static constexpr bool has_forces = Layout::has_forces;
  static constexpr bool has_lifetime = Layout::has_lifetime;
  static constexpr bool has_interpolation = Layout::has_interpolation;
  static constexpr bool has_handles = Layout::has_handles;
  /// True when the damping policy has a damping value at all (not damping::None).
  static constexpr bool stores_damping = !std::is_empty_v<damping_state>;
  static_assert(!per_particle_damping || stores_damping,
                "features::PerParticleDamping needs a damping policy with a damping value "
                "(damping::None has none)");
  /// Bytes each particle occupies (the block adds under 4.5 KiB per array of padding).
  static constexpr std::size_t storage_bytes_per_particle = Layout::bytes_per_particle;
  /// How many arrays the block holds.
  static constexpr std::size_t array_count = Layout::array_count;
  /// Returned by spawn when its input was rejected.
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  // --- construction, size and capacity -------------------------------------------------------

  ParticleSystem() = default;
  /// An empty system with room for `capacity` particles.
  explicit ParticleSystem(std::size_t capacity) { reserve(capacity); }
  /// A copy has the same particles, capacity and uniform values; it starts walking forwards.
  ParticleSystem(const ParticleSystem&) = default;
  ParticleSystem(ParticleSystem&&) noexcept = default;
  ParticleSystem& operator=(ParticleSystem other) noexcept {
    swap(other);
    return *this;
  }
  ~ParticleSystem() = default;
  void swap(ParticleSystem& other) noexcept { State::swap_state(other); }
  friend void swap(ParticleSystem& a, ParticleSystem& b) noexcept { a.swap(b); }

  [[nodiscard]] std::size_t size() const noexcept { return State::size(); }
  [[nodiscard]] bool empty() const noexcept { return size() == 0; }
  [[nodiscard]] std::size_t capacity() const noexcept { return State::capacity(); }
  /// The largest capacity a system of this configuration can have.
  using State::max_size;
  /// Makes room for `capacity` particles in one block (no-op if there is room already).
  /// A capacity beyond max_size() throws std::length_error and changes nothing.
  void reserve(std::size_t capacity) { State::reserve_checked(capacity); }
  /// Removes every particle; keeps the capacity. (Not inside an expiry callback.)
  void clear() {
    if (detail::check_not_removing("clear", removing_, 0)) State::remove_all();
  }

  // --- uniform values ------------------------------------------------------------------------

  /// The acceleration of every particle (gravity); finite.
  void set_acceleration(const Vector3<R>& acceleration) requires(!per_particle_acceleration) {
    if (detail::check_finite("set_acceleration", "acceleration", acceleration)) {
      acceleration_ = acceleration;
    }
  }
  [[nodiscard]] Vector3<R> acceleration() const noexcept requires(!per_particle_acceleration) {
    return acceleration_;
  }
  /// The damping of every particle, in [0, 1] (per second or per frame, as the policy says).
  // clang-format off
  void set_damping(R damping)
    requires(stores_damping && !per_particle_damping)
  {
    // clang-format on
    if (detail::check_damping("set_damping", damping)) {
      damping_ = damping_state(damping);
      State::forget_factors();
    }
  }
  [[nodiscard]] R damping() const noexcept requires(!per_particle_damping) {
    return damping_.value();
  }

  // --- spawning and killing ------------------------------------------------------------------

  /// Adds a particle at `position` with `velocity` and returns its index. Per-particle
  /// values start as a default Particle's (acceleration 0, damping 1, mass 1, no force, age 0,
  /// lifetime infinite), user columns as T{}. Non-finite input is reported and nothing is
  /// added (returns npos). Grows the block when full (invalidating spans and arrays()).
  std::size_t spawn(const Vector3<position_value>& position, const Vector3<R>& velocity) {
    if (!State::valid_position("spawn", position) ||
        !detail::check_finite("spawn", "velocity", velocity)) {
      return npos;
    }
    return State::append(position, velocity);
  }
  /// Adds a particle with a value for each user column, in the order of the features.
  // clang-format off
  template <class... Values>
    requires(sizeof...(Values) > 0 && sizeof...(Values) == Layout::user_column_count)
  std::size_t spawn(const Vector3<position_value>& position, const Vector3<R>& velocity,
                    const Values&... values) {
    // clang-format on
    const std::size_t i = spawn(position, velocity);
    if (i != npos) {
      State::store_user_columns(i, std::make_index_sequence<sizeof...(Values)>{}, values...);
    }
    return i;
  }
  /// Adds a copy of `particle`: its position and velocity, and whichever of its
  /// acceleration, damping, inverse mass and accumulated force the system stores per
  /// particle (the others are the system's uniform values).
  std::size_t spawn(const particle_type& particle) {
    const std::size_t i = spawn(particle.position(), particle.velocity());
    if (i != npos) State::store_particle(i, particle);
    return i;
  }
  /// spawn(arguments...), returning the new particle's handle (a default Handle, which
  /// finds nothing, when the input was rejected).
  template <class... Arguments>
    requires(has_handles)
  Handle spawn_handle(const Arguments&... arguments) {
    const std::size_t i = spawn(arguments...);
    return i == npos ? Handle{} : this->handle(i);
  }
  /// Spawns `count` particles, reserving once: particle k is spawn(generator(k)...), where
  /// generator(k) returns the arguments of a spawn as a tuple-like value (a std::pair of
  /// position and velocity, a std::tuple with the user columns' values after them) or a
  /// particle_type. Returns how many were added (a rejected one is reported, with
  /// ContractViolation::within = "spawn_burst" and element = k, and skipped);
  /// they are the last ones, [size() - returned, size()), until the next removal. If the
  /// report of a rejected one throws (the default handler) or the generator throws, the
  /// particles this call added are removed again before the exception leaves: the system
  /// holds what it held before the call (its capacity may have grown). Inside the generator
  /// removing (kill, kill_if, clear) or stepping is refused; a generator that replaces the
  /// particles whole (assigns, swaps or moves the system) ends the burst: it returns 0, and
  /// a throw after that leaves the particles as they are.
  template <class Generator>
  std::size_t spawn_burst(std::size_t count, Generator&& generator) {
    State::make_room(count);
    const std::size_t before = size();
    const std::uint16_t replacements = State::replacements_;
    const auto spawn_all = [&]() -> std::size_t {
      // Removals and steps are refused while the burst runs (its particles are the last ones).
      const typename State::PassScope burst(removing_, detail::RemovalPass::burst);
      std::size_t spawned = 0;
      for (std::size_t k = 0; k < count; ++k) {
        decltype(auto) made = generator(k);
        // The generator replaced the particles whole (assigned, swapped or moved the system):
        // those this call added left with them, and the burst ends.
        if (State::replacements_ != replacements) return 0;
        const detail::ReportingElement reporting("spawn_burst", k);
        std::size_t i;
        if constexpr (std::is_convertible_v<decltype(made), const particle_type&>) {
          i = spawn(static_cast<const particle_type&>(made));
        } else {
          i = std::apply([&](const auto&... arguments) { return spawn(arguments...); }, made);
        }
        if (i != npos) ++spawned;
      }
      return spawned;
    };
#if POINTMASS_HAS_EXCEPTIONS
    try {
      return spawn_all();
    } catch (...) {
      // The last particles are this call's: removing the last moves no other particle.
      // (Particles replaced whole by the generator are not this call's: left as they are.)
      if (State::replacements_ == replacements) {
        while (size() > before) State::remove(size() - 1);
      }
      throw;
    }
#else
    static_cast<void>(before);
    return spawn_all();
#endif
  }

  /// Removes particle `index` by moving the last particle into its place (order not kept).
  void kill(std::size_t index) {
    if (detail::check_not_removing("kill", removing_, index) &&
        detail::check_index("kill", index, size())) {
      State::remove(index);
    }
  }
  /// Removes every particle for which predicate(index) is true, by swap-remove, and returns
  /// how many. The predicate sees each particle once; after a removal it is asked about the
  /// particle moved into the freed index. Spawning inside the predicate is allowed (the new
  /// particles are asked about too); removing (kill, kill_if, clear) or stepping is refused.
  template <class Predicate>
  std::size_t kill_if(Predicate&& predicate) {
    if (!detail::check_not_removing("kill_if", removing_, 0)) return 0;
    return State::remove_if(predicate);
  }

  // --- per-particle values (index < size(): checked when POINTMASS_CHECKS is on) -------------

  [[nodiscard]] Vector3<position_value> position(std::size_t i) const
      noexcept(!POINTMASS_HOST_CHECKS) {
    return valid_index("position", i) ? State::load_position(i) : Vector3<position_value>{};
  }
  [[nodiscard]] Vector3<R> velocity(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("velocity", i)) return {};
    return load(arrays().velocity_x, arrays().velocity_y, arrays().velocity_z, i);
  }
  /// The acceleration particle i has (its own, or the system's).
  [[nodiscard]] Vector3<R> acceleration(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("acceleration", i)) return {};
    if constexpr (per_particle_acceleration) {
      return load(arrays().acceleration_x, arrays().acceleration_y, arrays().acceleration_z, i);
    } else {
      return acceleration_;
    }
  }
  /// The damping particle i has (its own, or the system's).
  [[nodiscard]] R damping(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("damping", i)) return R(1);
    if constexpr (per_particle_damping) {
      return Layout::load_damping(arrays(), i).value();
    } else {
      return damping_.value();
    }
  }

  /// A jump: with features::Interpolation the previous position moves with it.
  void set_position(std::size_t i, const Vector3<position_value>& position) {
    if (detail::check_index("set_position", i, size()) &&
        State::valid_position("set_position", position)) {
      State::store_position(i, position);
    }
  }
  void set_velocity(std::size_t i, const Vector3<R>& velocity) {
    if (detail::check_index("set_velocity", i, size()) &&
        detail::check_finite("set_velocity", "velocity", velocity)) {
      store(arrays().velocity_x, arrays().velocity_y, arrays().velocity_z, i, velocity);
    }
  }
  void set_acceleration(std::size_t i,
                        const Vector3<R>& acceleration) requires per_particle_acceleration {
    if (detail::check_index("set_acceleration", i, size()) &&
        detail::check_finite("set_acceleration", "acceleration", acceleration)) {
      store(arrays().acceleration_x, arrays().acceleration_y, arrays().acceleration_z, i,
            acceleration);
    }
  }
  void set_damping(std::size_t i, R damping) requires per_particle_damping {
    if (detail::check_index("set_damping", i, size()) &&
        detail::check_damping("set_damping", damping)) {
      State::store_damping(i, damping_state(damping));
    }
  }

  /// The raw arrays (see step_particle), with size() live particles. Valid until the block
  /// grows or moves (a growing spawn, reserve, move, swap).
  using State::arrays;

  // --- the step ------------------------------------------------------------------------------

  /// Advances every particle by `duration` seconds (see step_particle), then expires those
  /// whose lifetime is over. A negative, NaN or infinite duration is a contract violation,
  /// checked when POINTMASS_CHECKS is on; zero changes nothing. Allocates nothing.
  void step(R duration) {
    if constexpr (PositionPolicyFor<P, D>) {  // else the static_assert above has said why
      if (State::walk(duration)) {
        typename State::NoCallback none;
        State::expire(none);
      }
    }
  }
  /// As step(duration), calling on_expire(i) for each particle whose lifetime is over, once,
  /// after the step and before its removal, so that particle i still holds its final state.
  /// Spawning inside the callback is allowed and immediate (the new particles are stepped
  /// from the next step on); removing particles (kill, kill_if, clear) or stepping (step,
  /// finish_step) is refused.
  // clang-format off
  template <class OnExpire>
    requires(has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  void step(R duration, OnExpire&& on_expire) {
    // clang-format on
    if constexpr (PositionPolicyFor<P, D>) {
      if (State::walk(duration)) State::expire(on_expire);
    }
  }

  /// True when the next `step` walks the particles backwards (see alternates). A copy
  /// starts forwards; a move or swap takes the direction along.
  [[nodiscard]] bool next_step_backward() const noexcept { return State::backward_; }

  // Loops of one's own (a device, a thread pool: parallel.hpp, kokkos.hpp) step the arrays
  // with step_particle(arrays(), i, step_parameters(t)) for i < size(), after begin_step(t)
  // said there is work, then call finish_step() on the host to expire particles.

  /// Says that the arrays were written from outside (through arrays(): a device's results
  /// copied back): the next step recomputes what the system keeps between steps (each
  /// particle's d^t for the last step length, with per-particle PerSecond or
  /// AccelerateThenDamp damping). finish_step() says it too.
  void arrays_changed() noexcept { State::forget_retention(); }

  /// What every particle's step of `duration` shares: the uniform damping factors (the one
  /// power function of a step with uniform per-second damping), those the last step kept if it
  /// had this length, else computed (the same bits either way). It changes nothing: only the
  /// library's steps (`step`, the parallel step, KokkosSystem::step) keep factors for the next
  /// step. It does not check the duration: call it once begin_step(duration) has accepted it
  /// (and said there is work), as step does. Likewise step_particle does not check its index: the loop's bounds are
  /// [0, size()), or step_range's, which checks them.
  using State::step_parameters;
  /// True if a step of `duration` has work to do; reports a bad duration (when checked).
  using State::begin_step;
  /// After the particles have stepped: removes those whose age reached their (finite)
  /// lifetime. Called by step.
  void finish_step() {
    arrays_changed();
    typename State::NoCallback none;
    State::expire(none, "finish_step");
  }
  /// finish_step calling on_expire(i) for each expiring particle before its removal.
  // clang-format off
  template <class OnExpire>
    requires(has_lifetime && std::is_invocable_v<OnExpire&, std::size_t>)
  void finish_step(OnExpire&& on_expire) {
    // clang-format on
    arrays_changed();
    State::expire(on_expire, "finish_step");
  }
  /// True when a particle of this `age` and `lifetime` has expired: its age reached a finite
  /// lifetime (an infinite one never expires, even when the age itself overflows).
  using State::expired;

 private:
  friend struct detail::SystemAccess;  // parallel.hpp, kokkos.hpp: steps that keep as step does
};

namespace detail {
/// What ParticleSystem::step does around its walk, for the steps of parallel.hpp and
/// kokkos.hpp: before it, the uniform damping factors kept for the step length
/// (keep_step_parameters; step_parameters() keeps none); after it, the damping_retention
/// column's d^t kept as this duration's (finish_step(), which cannot know what a loop of the
/// caller's did, forgets it). So the next step of the same length computes no exponential,
/// as after step.
struct SystemAccess {
  template <class System, class R>
  static typename System::StepParameters keep_step_parameters(System& system, R duration) {
    return system.keep_step_parameters(duration);  // the state's, reached through the system
  }
  template <class System, class R, class OnExpire>
  static void finish_step(System& system, R duration, OnExpire& on_expire) {
    system.record_retention(duration);  // the state's, reached through the system
    system.expire(on_expire);
  }
  template <class System, class R>
  static void finish_step(System& system, R duration) {
    typename System::NoCallback none;  // the state's, named through the system
    finish_step(system, duration, none);
  }
};
}  // namespace detail

}  // namespace pointmass

// Deprecated: defining POINTMASS_ENABLE_PARALLEL before this header still brings in the
// parallel step; include <pointmass/parallel.hpp> instead (the macro goes in the next release).
#if defined(POINTMASS_ENABLE_PARALLEL)
#include "parallel.hpp"
#endif
