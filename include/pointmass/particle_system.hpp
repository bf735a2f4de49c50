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
// policies of `Particle` and its results, bit for bit: each particle's step is integrate<D, P>
// (particle.hpp) on x, y and z (tests/system/ proves it for every policy pair). S is a Real or
// a Precision<Real, Position> (precision.hpp). Each feature tag (features.hpp) adds what it
// stores, and what is not chosen is neither stored nor computed. docs/particle-system.md is
// the manual of every public name (tests/system/public_names.txt lists them).
//
// Rules in brief. Removal is swap-remove, so an index names a particle until the next kill,
// kill_if, clear or step with Lifetime; a handle (features::Handles) for as long as it lives.
// Spans and pointers into them are valid until the next spawn that grows the block, reserve,
// move or swap. Indices are checked when POINTMASS_CHECKS is on; otherwise an index >= size()
// is undefined behaviour, as for std::vector::operator[]. Bad values are reported
// (config.hpp) and change nothing. `step` never allocates.
//
// Every public name is declared in this class: the facets' members (system/*.hpp, private
// bases) are re-exported by name, so nothing of the state or the kernel below is reachable.
//
// Owns: the public API and the line of facets; StepView (system/step_view.hpp) and
// detail::SystemAccess (detail/system_access.hpp) are included at its end.
// Must not include: <execution> or anything that starts threads (parallel.hpp adds those).
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "damping.hpp"
#include "detail/system_kernel.hpp"
#include "detail/system_passes.hpp"
#include "detail/system_state.hpp"
#include "detail/validate.hpp"
#include "features.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "real.hpp"
#include "system/columns.hpp"
#include "system/deprecated.hpp"
#include "system/force_accumulator.hpp"
#include "system/hand_off.hpp"
#include "system/handles.hpp"
#include "system/interpolation.hpp"
#include "system/laws_step.hpp"
#include "system/lifetime.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {
// The facets (detail::SystemFacets, below) stand in one line rather than one base each, so that
// no two empty bases share a type (an API probe compares sizeof with the state's). A facet's
// member that needs a feature is constrained on the layout's trait (`requires
// Base::Layout::has_handles`), never on the class being defined; names that overload one
// another (column<C>() and column<Tag>()) stay in one facet, since a derived class's member
// hides a base's. A new facet: a header under system/ with the same opening comment, one more
// link in the line, and its line in this file's opening comment.

namespace detail {
// The facets, each over the one before it and the first over the state: one line of private
// bases, in which every facet is empty (a system is as big as its state).
template <class State>
using SystemFacets = SystemLawsStep<SystemDeprecated<SystemHandOff<SystemInterpolation<
    SystemLifetime<SystemForceAccumulator<SystemHandles<SystemColumns<State>>>>>>>>;
}  // namespace detail

// clang-format off
template <class S, DampingPolicy D = damping::PerSecond, class P = position::Euler,
          class... Features>
  requires((Real<S> || PrecisionChoice<S>) && (detail::is_feature_v<Features> && ...))
class ParticleSystem : private detail::SystemFacets<detail::SystemStateBase<S, D, P, Features...>> {
  // clang-format on
  using State = detail::SystemPasses<S, D, P, Features...>;
  using Facets = detail::SystemFacets<detail::SystemStateBase<S, D, P, Features...>>;
  using R = real_of_t<S>;
  using Layout = typename State::Layout;
  using Kernel = typename State::Kernel;
  using damping_state = typename D::template State<R>;
  using State::acceleration_;
  using State::damping_;
  using State::load;
  using State::removing_;
  using State::store;
  using State::valid_index;
  static constexpr bool per_particle_damping_ = Layout::per_particle_damping;
  static constexpr bool per_particle_acceleration_ = Layout::per_particle_acceleration;
  static constexpr bool has_lifetime_ = Layout::has_lifetime;
  static_assert(!per_particle_damping_ || !std::is_empty_v<damping_state>,
                "features::PerParticleDamping needs a damping policy with a damping value "
                "(damping::None has none)");
  // P is checked here, with one sentence, rather than as a constraint (see position.hpp).
  static_assert(detail::check_policy_pair<D, P>());

 public:
  using real = R;
  using damping_policy = D;
  using position_policy = P;
  /// The scalar particle whose step this system reproduces.
  using particle_type = Particle<S, D, P>;
  /// What position(i) returns and spawn and set_position take, per component (R, or double
  /// for Precision<float, double> and Precision<float, Compensated<float>>).
  using position_value = typename State::position_value;
  /// The element of the position columns (column<Column::position_x>(), ..., and the
  /// previous positions).
  using position_element = typename Layout::position_element;
  /// A particle's stable name (features::Handles): see handle() and find().
  using typename Facets::Handle;
  class StepView;

  /// True when the configuration has `Feature` (a tag of features.hpp; features::Handles for
  /// any BasicHandles<G>) or a user column tagged `Feature` (features::Column<Feature, T>).
  template <class Feature>
  static constexpr bool has = detail::has_feature_v<Feature, Features...>;
  /// True when the damping policy has a damping value at all (not damping::None), as for
  /// Particle: set_damping exists.
  static constexpr bool stores_damping = !std::is_empty_v<damping_state>;
  /// True when the block holds column C (features.hpp's Column), for column<C>().
  template <Column C>
  static constexpr bool stores = Layout::template stores<C>;
  /// Bytes each particle occupies (the block adds under 4.5 KiB per array of padding).
  static constexpr std::size_t storage_bytes_per_particle = Layout::bytes_per_particle;
  /// Returned by spawn when its input was rejected.
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  // --- construction, size and capacity -------------------------------------------------------

  ParticleSystem() = default;
  /// An empty system with room for `capacity` particles.
  explicit ParticleSystem(std::size_t capacity) { reserve(capacity); }
  /// A copy has the same particles, capacity and uniform values.
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
  void set_acceleration(const Vector3<R>& acceleration) requires(!per_particle_acceleration_) {
    if (detail::check_finite("set_acceleration", "acceleration", acceleration)) {
      acceleration_ = acceleration;
    }
  }
  [[nodiscard]] Vector3<R> acceleration() const noexcept requires(!per_particle_acceleration_) {
    return acceleration_;
  }
  /// The damping of every particle, in [0, 1] (per second or per frame, as the policy says).
  // clang-format off
  void set_damping(R damping)
    requires(stores_damping && !per_particle_damping_)
  {
    // clang-format on
    if (detail::check_damping("set_damping", damping)) {
      damping_ = damping_state(damping);
      State::forget_factors();
    }
  }
  /// Without one damping value for all: a sentence, rather than the constraints not met.
  void set_damping(R) requires(!stores_damping || per_particle_damping_) {
    static_assert(stores_damping && !per_particle_damping_,
                  "set_damping(d): no damping for all particles (damping::None damps nothing; "
                  "with features::PerParticleDamping, set_damping(i, d))");
  }
  [[nodiscard]] R damping() const noexcept requires(!per_particle_damping_) {
    return damping_.value();
  }

  // --- spawning and killing ------------------------------------------------------------------

  /// Adds a particle at `position` with `velocity` and returns its index. Per-particle
  /// values start as a default Particle's (acceleration 0, damping 1, mass 1, no force, age 0,
  /// lifetime infinite), user columns as T{}. Non-finite input is reported and nothing is
  /// added (returns npos). Grows the block when full (invalidating spans).
  std::size_t spawn(const Vector3<position_value>& position, const Vector3<R>& velocity) {
    return State::valid_spawn(position, velocity) ? State::append(position, velocity) : npos;
  }
  /// Adds a particle with a value for each user column, in the order of the features.
  // clang-format off
  template <class... Values>
    requires(sizeof...(Values) > 0 && sizeof...(Values) == Layout::user_column_count)
  std::size_t spawn(const Vector3<position_value>& position, const Vector3<R>& velocity,
                    const Values&... values) {
    // clang-format on
    return State::valid_spawn(position, velocity) ? State::append(position, velocity, values...)
                                                  : npos;
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
    requires(Layout::has_handles)
  Handle spawn_handle(const Arguments&... arguments) {
    const std::size_t i = spawn(arguments...);
    return i == npos ? Handle{} : this->handle(i);
  }
  /// Spawns `count` particles, reserving once: particle k is spawn(generator(k)...), where
  /// generator(k) returns a spawn's arguments as a tuple-like value (position and velocity,
  /// then the user columns' values) or a particle_type. Returns how many were added, the last
  /// ones until the next removal (a rejected one is reported, with within = "spawn_burst" and
  /// element = k, and skipped). If the generator or a report throws, this call's particles
  /// are removed before the exception leaves (the capacity may have grown). Inside the
  /// generator removing or stepping is refused; one that replaces the particles whole
  /// (assigns, swaps or moves the system) ends the burst, which returns 0.
  template <class Generator>
  std::size_t spawn_burst(std::size_t count, Generator&& generator) {
    return State::spawn_each(count, generator, [this](const auto& made) {
      if constexpr (std::is_convertible_v<decltype(made), const particle_type&>) {
        return spawn(static_cast<const particle_type&>(made));
      } else {
        return std::apply([&](const auto&... arguments) { return spawn(arguments...); }, made);
      }
    });
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
    const auto& a = State::arrays();
    return load(a.velocity_x, a.velocity_y, a.velocity_z, i);
  }
  /// The acceleration particle i has (its own, or the system's).
  [[nodiscard]] Vector3<R> acceleration(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("acceleration", i)) return {};
    if constexpr (per_particle_acceleration_) {
      const auto& a = State::arrays();
      return load(a.acceleration_x, a.acceleration_y, a.acceleration_z, i);
    } else {
      return acceleration_;
    }
  }
  /// The damping particle i has (its own, or the system's).
  [[nodiscard]] R damping(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    if (!valid_index("damping", i)) return R(1);
    if constexpr (per_particle_damping_) {
      return Layout::load_damping(State::arrays(), i).value();
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
      const auto& a = State::arrays();
      store(a.velocity_x, a.velocity_y, a.velocity_z, i, velocity);
    }
  }
  void set_acceleration(std::size_t i,
                        const Vector3<R>& acceleration) requires per_particle_acceleration_ {
    if (detail::check_index("set_acceleration", i, size()) &&
        detail::check_finite("set_acceleration", "acceleration", acceleration)) {
      const auto& a = State::arrays();
      store(a.acceleration_x, a.acceleration_y, a.acceleration_z, i, acceleration);
    }
  }
  void set_damping(std::size_t i, R damping) requires per_particle_damping_ {
    if (detail::check_index("set_damping", i, size()) &&
        detail::check_damping("set_damping", damping)) {
      State::store_damping(i, damping_state(damping));
    }
  }

  // --- what the facets add (system/*.hpp documents each) -------------------------------------
  // column, set_column: the arrays as spans and the user's columns (columns.hpp); handle,
  // find, contains: features::Handles (handles.hpp); inverse_mass, set_mass,
  // set_inverse_mass, add_force, force_accumulator: features::ForceAccumulator
  // (force_accumulator.hpp); age, lifetime, set_lifetime: features::Lifetime (lifetime.hpp);
  // previous_position, interpolated_position, copy_interpolated_positions:
  // features::Interpolation (interpolation.hpp); copy_positions, position_relative_to: to a
  // renderer (hand_off.hpp).

  using Facets::add_force, Facets::age, Facets::column, Facets::contains,
      Facets::copy_interpolated_positions, Facets::copy_positions, Facets::find,
      Facets::force_accumulator, Facets::handle, Facets::interpolated_position,
      Facets::inverse_mass, Facets::lifetime, Facets::position_relative_to,
      Facets::previous_position, Facets::set_column, Facets::set_inverse_mass, Facets::set_lifetime,
      Facets::set_mass;

  // --- the step (and step(duration, laws[, Substeps][, on_expire]): system/laws_step.hpp) ----
  using Facets::step;

  /// Advances every particle by `duration` seconds (each particle's step is Particle's:
  /// detail/system_kernel.hpp), then expires those whose lifetime is over. A negative, NaN or
  /// infinite duration is a contract violation, checked when POINTMASS_CHECKS is on; zero
  /// changes nothing. Allocates nothing.
  void step(R duration) {
    if constexpr (PositionPolicyFor<P, D>) {  // else the static_assert above has said why
      if (State::walk(duration)) {
        detail::NoExpiryCallback none;
        State::expire(none);
      }
    }
  }
  /// As step(duration), calling on_expire(i) for each particle whose lifetime is over, once,
  /// after the step and before its removal, so that particle i still holds its final state.
  /// Spawning inside the callback is allowed and immediate (the new particles are stepped
  /// from the next step on); removing particles (kill, kill_if, clear) or stepping is refused.
  // clang-format off
  template <class OnExpire>
    requires(has_lifetime_ && std::is_invocable_v<OnExpire&, std::size_t>)
  void step(R duration, OnExpire&& on_expire) {
    // clang-format on
    if constexpr (PositionPolicyFor<P, D>) {
      if (State::walk(duration)) State::expire(on_expire);
    }
  }

  /// A step of one's own (threads, a device): begin_step(duration) returns the view of this
  /// step, whose step_particle(i) for every i < view.size() (in any order, on any threads)
  /// is step(duration)'s arithmetic; finish_step(std::move(view)) then expires particles as
  /// step does. A bad duration is reported (when checked) and gives an empty view.
  [[nodiscard]] StepView begin_step(R duration) { return begin_view(duration, "begin_step"); }
  /// Ends the step `view` began: removes the particles whose age reached their (finite)
  /// lifetime. A view of another system, a finished one, or one whose particles were spawned
  /// or killed after begin_step is a contract violation, reported; nothing is done.
  void finish_step(StepView&& view) {
    detail::NoExpiryCallback none;
    finish(view, none);
  }
  /// finish_step(view) calling on_expire(i) for each expiring particle before its removal.
  // clang-format off
  template <class OnExpire>
    requires(has_lifetime_ && std::is_invocable_v<OnExpire&, std::size_t>)
  void finish_step(StepView&& view, OnExpire&& on_expire) {
    // clang-format on
    finish(view, on_expire);
  }

  // --- deprecated: the names of 0.1 (system/deprecated.hpp; gone in 0.3) --------------------

  using Facets::array_count, Facets::arrays, Facets::arrays_changed, Facets::expired,
      Facets::finish_step, Facets::has_forces, Facets::has_handles, Facets::has_interpolation,
      Facets::has_lifetime, Facets::per_particle_acceleration, Facets::per_particle_damping,
      Facets::position_x, Facets::position_y, Facets::position_z, Facets::positions_relative_to,
      Facets::step_parameters, Facets::step_particle, Facets::step_range, Facets::velocity_x,
      Facets::velocity_y, Facets::velocity_z;
  using typename Facets::Arrays;
  using typename Facets::StepParameters;

 private:
  friend struct detail::SystemAccess;  // parallel.hpp, kokkos.hpp and the tests

  // `keep`: keep the uniform damping factors for the next step of this length, as step does
  // (the library's steps); a view from begin_step keeps nothing.
  StepView begin_view(R duration, const char* function, bool keep = false) {
    if constexpr (PositionPolicyFor<P, D>) {
      if (State::begin_step(duration, function)) {
        return StepView(
            this, State::arrays(),
            keep ? State::keep_step_parameters(duration) : State::step_parameters(duration));
      }
    }
    return StepView(this, typename Layout::Arrays{}, {});
  }
  template <class OnExpire>
  void finish(StepView& view, OnExpire& on_expire) {
    const StepView finished(std::move(view));
    const bool mine = finished.owner_ == this;
    const bool same = mine && (finished.size() == 0 ||
                               (finished.arrays_.size == size() &&
                                finished.arrays_.position_x == State::arrays().position_x));
    if (!detail::check_step_view("finish_step", mine, same, finished.size()) ||
        finished.size() == 0) {
      return;
    }
    // A loop of the caller's may not have refreshed every particle's d^t: the next step
    // computes it again.
    State::forget_retention();
    State::expire(on_expire, "finish_step");
  }
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END

// StepView, and what the library's own steps reach of the state.
#include "detail/system_access.hpp"
#include "system/step_view.hpp"

// Deprecated: defining POINTMASS_ENABLE_PARALLEL before this header still brings in the
// parallel step; include <pointmass/parallel.hpp> instead (the macro goes in the next release).
#if defined(POINTMASS_ENABLE_PARALLEL)
#include "parallel.hpp"
#endif
