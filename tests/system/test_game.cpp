// SPDX-License-Identifier: BSL-1.0
// What a game needs of the batch: bursts; and that none of it costs a configuration that
// does not choose it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;
using pointmass::test::SpawnTag;

TEST_CASE("spawn_burst: count particles from a generator, reserving once") {
  using Painted =
      ParticleSystem<float, damping::None, position::Euler, features::Column<SpawnTag, int>>;
  Painted system;
  system.spawn({}, {}, -1);
  const std::size_t added = system.spawn_burst(1000, [](std::size_t k) {
    return std::tuple{Vector3<float>{float(k), 0, 0}, Vector3<float>{0, 1, 0}, int(k)};
  });
  CHECK(added == 1000);
  CHECK(system.size() == 1001);
  CHECK(system.capacity() == 1001);  // one reservation, to the count asked for
  for (std::size_t i = 1; i < system.size(); ++i) {
    CHECK(system.column<SpawnTag>(i) == int(i - 1));
    CHECK(system.position(i).x == float(i - 1));
  }
  // A generator of particles, into a system without columns.
  ParticleSystem<float> sparks;
  Particle<float> model;
  model.set_velocity({1, 2, 3});
  CHECK(sparks.spawn_burst(3, [&](std::size_t) { return model; }) == 3);
  CHECK(sparks.velocity(2) == Vector3<float>{1, 2, 3});
}

TEST_CASE("a feature not chosen costs nothing: the configurations' bytes and arrays as before") {
  // The figures of the configurations before these features existed (examples/variants.cmake
  // checks the same): 6 numbers per particle, +2 Lifetime, +4 ForceAccumulator, +3
  // PerParticleAcceleration.
  static_assert(ParticleSystem<float>::storage_bytes_per_particle == 24);
  static_assert(pointmass::detail::SystemAccess::Layout<ParticleSystem<float>>::array_count == 6);
  static_assert(ParticleSystem<double, damping::None>::storage_bytes_per_particle == 48);
  static_assert(ParticleSystem<float, damping::None, position::Euler,
                               features::Lifetime>::storage_bytes_per_particle == 32);
  // The raw arrays gain pointers for the new columns (nullptr, never walked), nothing for
  // absent user columns; the system object gains nothing for absent handles.
  using Lean = ParticleSystem<float>;
  static_assert(sizeof(Lean::StepView::Arrays) == 26 * sizeof(float*) + sizeof(std::size_t));
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
