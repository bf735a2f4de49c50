// SPDX-License-Identifier: BSL-1.0
// What each compile-time choice stores and computes, the staggered block, and that a feature
// not chosen costs nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "counting_damping.hpp"
#include "system_support.hpp"

namespace {

using namespace pointmass;
using pointmass::test::CountingPerSecond;
using pointmass::test::same_bits;

template <class System>
std::size_t stored_arrays(const System& system) {
  const auto& a = pointmass::detail::SystemAccess::arrays(system);
  const void* pointers[] = {
      a.position_x, a.position_y,     a.position_z,     a.velocity_x,     a.velocity_y,
      a.velocity_z, a.acceleration_x, a.acceleration_y, a.acceleration_z, a.inverse_mass,
      a.force_x,    a.force_y,        a.force_z,        a.damping,        a.age,
      a.age_error,  a.lifetime};
  return static_cast<std::size_t>(
      std::count_if(std::begin(pointers), std::end(pointers), [](const void* p) { return p; }));
}

}  // namespace

TEST_CASE_TEMPLATE("each feature stores its arrays, and nothing else", R, float, double) {
  using Bare = ParticleSystem<R, damping::None, position::Euler>;
  using Sparks = ParticleSystem<R>;  // uniform per-second damping and gravity
  using Damped =
      ParticleSystem<R, damping::PerSecond, position::Euler, features::PerParticleDamping>;
  using ExactDamped =
      ParticleSystem<R, damping::Exact, position::Exact, features::PerParticleDamping>;
  using Accelerated =
      ParticleSystem<R, damping::PerFrame, position::Euler, features::PerParticleAcceleration>;
  using Forced = ParticleSystem<R, damping::None, position::Euler, features::ForceAccumulator>;
  using Aging = ParticleSystem<R, damping::None, position::Euler, features::Lifetime>;
  using Everything = ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime,
                                    features::ForceAccumulator, features::PerParticleAcceleration,
                                    features::PerParticleDamping>;

  static_assert(Bare::storage_bytes_per_particle == 6 * sizeof(R));
  static_assert(Sparks::storage_bytes_per_particle == 6 * sizeof(R));
  // Per-second damping stores d and ln d as hi + lo (no logarithm a step), as Exact does, and
  // d^t for the last step length (no exponential a fixed step).
  static_assert(Damped::storage_bytes_per_particle == 10 * sizeof(R));
  static_assert(ExactDamped::storage_bytes_per_particle == 9 * sizeof(R));
  static_assert(Accelerated::storage_bytes_per_particle == 9 * sizeof(R));
  static_assert(Forced::storage_bytes_per_particle == 10 * sizeof(R));
  static_assert(Aging::storage_bytes_per_particle == 9 * sizeof(R));  // age as age + error
  static_assert(Everything::storage_bytes_per_particle == 20 * sizeof(R));

  // The accessors of what is not stored do not exist.
  static_assert(!requires(Bare & s) { s.template column<Column::acceleration_x>(); });
  static_assert(requires(Accelerated & s) { s.template column<Column::acceleration_x>(); });
  static_assert(!requires(Sparks & s) { s.set_damping(std::size_t{0}, R(1)); });
  static_assert(requires(Sparks & s) { s.set_damping(R(1)); });
  static_assert(requires(Damped & s) { s.template column<Column::damping>(); });
  static_assert(!Sparks::template stores<Column::damping> &&
                Damped::template stores<Column::damping>);
  // (set_damping(d) without a uniform value says why it cannot be called: compile-fail tests
  // system_set_damping_without_damping and system_set_damping_per_particle.)
  static_assert(!requires(Sparks & s) { s.add_force(std::size_t{0}, Vector3<R>{}); });
  static_assert(requires(Forced & s) { s.add_force(std::size_t{0}, Vector3<R>{}); });
  static_assert(!requires(Sparks & s) { s.template column<Column::age>(); });
  static_assert(requires(Aging & s) { s.template column<Column::age>(); });
  static_assert(requires(Accelerated & s) { s.set_acceleration(std::size_t{0}, Vector3<R>{}); });
  static_assert(!requires(Accelerated & s) { s.set_acceleration(Vector3<R>{}); });

  // The same at run time: the block holds exactly those arrays.
  CHECK(stored_arrays(Bare(10)) == 6);
  CHECK(stored_arrays(Sparks(10)) == 6);
  CHECK(stored_arrays(Damped(10)) == 7);
  CHECK(stored_arrays(Accelerated(10)) == 9);
  CHECK(stored_arrays(Forced(10)) == 10);
  CHECK(stored_arrays(Aging(10)) == 9);
  CHECK(stored_arrays(Everything(10)) == 17);
  CHECK(pointmass::detail::SystemAccess::arrays(Accelerated(10)).inverse_mass == nullptr);
  CHECK(pointmass::detail::SystemAccess::arrays(Forced(10)).acceleration_x == nullptr);
}

TEST_CASE_TEMPLATE(
    "uniform damping computes its factors once per step length, per-particle "
    "once each a step",
    R, float, double) {
  using Uniform = ParticleSystem<R, CountingPerSecond>;
  Uniform uniform(100);
  ParticleSystem<R, CountingPerSecond, position::Euler, features::PerParticleDamping> each(100);
  for (int i = 0; i < 100; ++i) {
    uniform.spawn({}, {R(1), R(0), R(0)});
    each.spawn({}, {R(1), R(0), R(0)});
  }
  uniform.set_damping(R(0.5));
  CountingPerSecond::factor_calls = 0;
  for (int step = 0; step < 3; ++step) uniform.step(R(0.1));
  CHECK(CountingPerSecond::factor_calls == 1);  // a fixed step: the factors are kept
  uniform.step(R(0.2));
  CHECK(CountingPerSecond::factor_calls == 2);  // a new length
  uniform.step(R(0.1));
  CHECK(CountingPerSecond::factor_calls == 3);  // the old length again: one entry is kept
  uniform.set_damping(R(0.9));
  uniform.step(R(0.1));
  CHECK(CountingPerSecond::factor_calls == 4);  // a new damping, the same length
  Uniform copy = uniform;
  copy.step(R(0.1));
  CHECK(CountingPerSecond::factor_calls == 4);  // a copy carries the kept factors
  uniform.step(R(0));
  CHECK(CountingPerSecond::factor_calls == 4);  // a zero step computes none
  // A loop of one's own reads the kept factors for the kept length and computes others,
  // without keeping them (begin_step does not change the system's kept factors).
  static_cast<void>(uniform.begin_step(R(0.1)));
  CHECK(CountingPerSecond::factor_calls == 4);
  static_cast<void>(uniform.begin_step(R(0.3)));
  static_cast<void>(uniform.begin_step(R(0.3)));
  CHECK(CountingPerSecond::factor_calls == 6);
  CountingPerSecond::factor_calls = 0;
  for (int step = 0; step < 3; ++step) each.step(R(0.1));
  CHECK(CountingPerSecond::factor_calls == 300);
}

TEST_CASE_TEMPLATE("arrays share one block, 64-byte aligned, staggered within their pages", R,
                   float, double) {
  using Everything = ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime,
                                    features::ForceAccumulator, features::PerParticleAcceleration,
                                    features::PerParticleDamping>;
  for (const std::size_t capacity : {std::size_t{1}, std::size_t{1000}, std::size_t{100000}}) {
    CAPTURE(capacity);
    ParticleSystem<R> sparks(capacity);
    Everything everything(capacity);
    static_assert(pointmass::detail::SystemAccess::Layout<Everything>::array_count ==
                  20);  // the damping state in three columns, d^t
    for (const std::size_t arrays : {std::size_t{6}, std::size_t{20}}) {
      CAPTURE(arrays);
      const auto& a = pointmass::detail::SystemAccess::arrays(sparks);
      const auto& b = pointmass::detail::SystemAccess::arrays(everything);
      std::vector<std::uintptr_t> starts;
      if (arrays == 6) {
        for (const R* p :
             {a.position_x, a.position_y, a.position_z, a.velocity_x, a.velocity_y, a.velocity_z}) {
          starts.push_back(reinterpret_cast<std::uintptr_t>(p));
        }
      } else {
        for (const R* p : {b.position_x,        b.position_y,   b.position_z,     b.velocity_x,
                           b.velocity_y,        b.velocity_z,   b.acceleration_x, b.acceleration_y,
                           b.acceleration_z,    b.inverse_mass, b.force_x,        b.force_y,
                           b.force_z,           b.damping,      b.damping_log_hi, b.damping_log_lo,
                           b.damping_retention, b.age,          b.age_error,      b.lifetime}) {
          starts.push_back(reinterpret_cast<std::uintptr_t>(p));
        }
      }
      std::set<std::uintptr_t> page_offsets;
      for (const auto start : starts) {
        CHECK(start % 64 == 0);
        page_offsets.insert(start % 4096);
      }
      CHECK(page_offsets.size() == starts.size());  // no two arrays at the same page offset
      // In one block, without overlap: each array ends before the next begins.
      std::vector<std::uintptr_t> sorted = starts;
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t k = 1; k < sorted.size(); ++k) {
        const std::size_t bytes = capacity * sizeof(R);
        CHECK(sorted[k] - sorted[k - 1] >= bytes);
        CHECK(sorted[k] - sorted[k - 1] <= bytes + 4096 + 448);
      }
    }
  }
}

/// True when System's column C is given read-only, as a span of const R.
template <class System, Column C, class R>
constexpr bool const_column =
    std::is_same_v<decltype(std::declval<System&>().template column<C>()), std::span<const R>>;

TEST_CASE_TEMPLATE("per-particle damping states live in columns of R that move together", R, float,
                   double) {
  // PerSecond and Exact: d, ln d's hi and lo, each a column of R (a step reads plain arrays),
  // read-only through column() (the three must agree); PerFrame's d stays writable.
  using Damped =
      ParticleSystem<R, damping::PerSecond, position::Euler, features::PerParticleDamping>;
  using FrameDamped =
      ParticleSystem<R, damping::PerFrame, position::Euler, features::PerParticleDamping>;
  static_assert(const_column<Damped, Column::damping, R>);
  static_assert(const_column<Damped, Column::damping_log_hi, R>);
  static_assert(
      std::is_same_v<decltype(std::declval<FrameDamped&>().template column<Column::damping>()),
                     std::span<R>>);
  static_assert(!FrameDamped::template stores<Column::damping_log_hi>);
  // AccelerateThenDamp keeps d^t for the last step length beside d: its d is read-only too
  // (a write through the column would leave the kept d^t stale); set_damping refreshes both.
  using ListingDamped =
      ParticleSystem<R, damping::AccelerateThenDamp, position::Euler, features::PerParticleDamping>;
  CHECK(const_column<ListingDamped, Column::damping, R>);
  // Every column of a damping state is read-only where the state has it: ln d's lo part, and
  // d^t kept for the last step length (PerSecond and AccelerateThenDamp), whose write would
  // leave it stale against d; Exact keeps d and ln d as PerSecond does.
  using ExactDamped =
      ParticleSystem<R, damping::Exact, position::Exact, features::PerParticleDamping>;
  CHECK(const_column<Damped, Column::damping_log_lo, R>);
  CHECK(const_column<Damped, Column::damping_retention, R>);
  CHECK(const_column<ListingDamped, Column::damping_retention, R>);
  CHECK(const_column<ExactDamped, Column::damping, R>);
  CHECK(const_column<ExactDamped, Column::damping_log_hi, R>);
  CHECK(const_column<ExactDamped, Column::damping_log_lo, R>);

  Damped system(8);
  const R values[] = {R(0.25), R(0.5), R(0.99), R(0)};
  for (const R d : values) {
    const std::size_t i = system.spawn({}, {R(1), R(0), R(0)});
    system.set_damping(i, d);
  }
  system.kill(1);  // swap-remove: the last particle (d = 0) moves into slot 1
  const R expected[] = {R(0.25), R(0), R(0.99)};
  const auto d = system.template column<Column::damping>();
  const auto hi = system.template column<Column::damping_log_hi>();
  const auto lo = system.template column<Column::damping_log_lo>();
  REQUIRE(d.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    const damping::LogDamping<R> state(expected[i]);
    CHECK(system.damping(i) == expected[i]);
    CHECK(same_bits(d[i], expected[i]));
    CHECK(same_bits(hi[i], state.split_log().hi));
    CHECK(same_bits(lo[i], state.split_log().lo));
  }
  // A step with those columns keeps what d^t says: d = 0 stops the particle at once.
  system.step(R(0.5));
  CHECK(system.velocity(1).x == R(0));
  CHECK(system.velocity(0).x == R(0.5));  // 0.25^0.5, exact
}

// The members of one feature or one use live in facets (system/*.hpp), public bases that add
// no data: a system is as big as its state, and reaches the state through them alone.
template <class R, class D, class P, class... Features>
constexpr bool facets_cost_nothing() {
  using System = ParticleSystem<R, D, P, Features...>;
  using State = detail::SystemState<R, D, P, Features...>;
  return sizeof(System) == sizeof(State) && alignof(System) == alignof(State) &&
         !std::is_convertible_v<System*, State*>;
}

TEST_CASE_TEMPLATE("the facets add members and no bytes", R, float, double) {
  struct Tag {};
  static_assert(facets_cost_nothing<R, damping::None, position::Euler>());
  static_assert(facets_cost_nothing<R, damping::PerSecond, position::Euler>());
  static_assert(facets_cost_nothing<R, damping::Exact, position::Exact,
                                    features::PerParticleDamping, features::ForceAccumulator>());
  static_assert(facets_cost_nothing<R, damping::PerSecond, position::Euler, features::Lifetime,
                                    features::Handles, features::Interpolation,
                                    features::ForceAccumulator, features::Column<Tag, int>>());
  static_assert(facets_cost_nothing<R, damping::PerFrame, position::Euler,
                                    features::BasicHandles<std::uint16_t>,
                                    features::PerParticleAcceleration>());

  // Each facet's members exist with its feature only.
  using Sparks = ParticleSystem<R>;
  using Full = ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime,
                              features::Handles, features::Interpolation,
                              features::ForceAccumulator, features::Column<Tag, int>>;
  static_assert(!requires(const Sparks& s) { s.handle(std::size_t{0}); });
  static_assert(requires(const Full& s) { s.handle(std::size_t{0}); });
  static_assert(!requires(const Sparks& s) { s.previous_position(std::size_t{0}); });
  static_assert(requires(const Full& s) { s.previous_position(std::size_t{0}); });
  static_assert(!requires(const Sparks& s) { s.inverse_mass(std::size_t{0}); });
  static_assert(requires(const Full& s) { s.inverse_mass(std::size_t{0}); });
  static_assert(!requires(const Sparks& s) { s.age(std::size_t{0}); });
  static_assert(requires(const Full& s) { s.age(std::size_t{0}); });
  static_assert(!Sparks::template has<Tag> && Full::template has<Tag>);
  static_assert(requires(const Full& s) { s.template column<Tag>(std::size_t{0}); });
  // Both column families answer on the same system: neither facet hides the other.
  static_assert(requires(Full & s) {
    s.template column<Tag>();
    s.template column<Column::age>();
  });

  Full system;
  const std::size_t i = system.spawn({R(1), R(2), R(3)}, {});
  system.template set_column<Tag>(i, 7);
  system.set_lifetime(i, R(2));
  system.set_mass(i, R(4));
  CHECK(system.template column<Tag>(i) == 7);
  CHECK(system.template column<Column::lifetime>()[i] == R(2));
  CHECK(system.inverse_mass(i) == R(0.25));
  CHECK(system.find(system.handle(i)) == std::optional<std::size_t>(i));
  CHECK(system.template column<pointmass::Column::position_x>()[i] == R(1));
}

TEST_CASE("a feature not chosen costs nothing: the configurations' bytes and arrays as before") {
  // The figures of the configurations before these features existed (examples/variants.cmake
  // checks the same): 6 numbers per particle, +3 Lifetime, +4 ForceAccumulator, +3
  // PerParticleAcceleration.
  static_assert(ParticleSystem<float>::storage_bytes_per_particle == 24);
  static_assert(pointmass::detail::SystemAccess::Layout<ParticleSystem<float>>::array_count == 6);
  static_assert(ParticleSystem<double, damping::None>::storage_bytes_per_particle == 48);
  static_assert(ParticleSystem<float, damping::None, position::Euler,
                               features::Lifetime>::storage_bytes_per_particle == 36);
  // The raw arrays gain pointers for the new columns (nullptr, never walked), nothing for
  // absent user columns; the system object gains nothing for absent handles.
  using Lean = ParticleSystem<float>;
  static_assert(sizeof(Lean::StepView::Arrays) == 31 * sizeof(float*) + sizeof(std::size_t));
  // The object beside its arrays: block pointer and capacity, two flags, d and ln d (hi, lo),
  // the acceleration: 48 bytes on a 64-bit target, as before (measured on the commit before);
  // and the last step's length and its factor d^t, kept for the next step of that length: 8.
  // (a static_assert under `if constexpr` outside a template is checked on every target)
  static_assert(sizeof(void*) != 8 || sizeof(Lean) - sizeof(Lean::StepView::Arrays) == 56);
  // Each feature adds exactly its own columns.
  static_assert(ParticleSystem<float, damping::None, position::Euler,
                               features::Interpolation>::storage_bytes_per_particle == 36);
  static_assert(ParticleSystem<double, damping::None, position::Euler,
                               features::Handles>::storage_bytes_per_particle == 52);
}

TEST_CASE("VelocityVerlet adds its kick columns and nothing else") {
  // The credited half kick, one number per axis (position.hpp); the last half step is one
  // number for the whole system.
  using Semi =
      ParticleSystem<float, damping::PerSecond, position::SemiImplicit, features::ForceAccumulator>;
  using Verlet = ParticleSystem<float, damping::PerSecond, position::VelocityVerlet,
                                features::ForceAccumulator>;
  static_assert(Verlet::storage_bytes_per_particle == Semi::storage_bytes_per_particle + 16);
  static_assert(Verlet::stores<Column::kick_x> && !Semi::stores<Column::kick_x>);
  Verlet system(4);
  system.spawn({}, {});
  system.set_acceleration({0.0f, -10.0f, 0.0f});
  system.step(0.1f);
  CHECK(system.column<Column::kick_y>()[0] == -0.5f);  // a t / 2
  CHECK(system.column<Column::kick_half_step>()[0] == 0.05f);
}

TEST_CASE("VelocityVerlet: a particle spawned into a running system steps as a new Particle") {
  // Each particle settles the kick with the half step that credited it (0 for a new one), so
  // a spark spawned after 10 steps, or made movable after being immovable, is the Particle.
  using Body = Particle<float, damping::PerSecond, position::VelocityVerlet>;
  ParticleSystem<float, damping::PerSecond, position::VelocityVerlet, features::ForceAccumulator>
      system(4);
  system.set_acceleration({0.0f, -9.8f, 0.0f});
  Body early;
  early.set_acceleration({0.0f, -9.8f, 0.0f});
  system.spawn(early);
  Body late = early;
  Body pinned = early;
  pinned.set_inverse_mass(0.0f);
  system.spawn(pinned);
  for (int n = 0; n < 10; ++n) {
    early.integrate(1.0f / 60.0f);
    pinned.integrate(1.0f / 60.0f);
    system.step(1.0f / 60.0f);
  }
  system.spawn(late);
  pinned.set_inverse_mass(1.0f);
  system.set_inverse_mass(1, 1.0f);
  for (int n = 0; n < 10; ++n) {
    for (Body* body : {&early, &pinned, &late}) body->integrate(1.0f / 50.0f);
    system.step(1.0f / 50.0f);
  }
  const Body* bodies[] = {&early, &pinned, &late};
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(same_bits(system.position(i), bodies[i]->position()));
    CHECK(same_bits(system.velocity(i), bodies[i]->velocity()));
  }
}
