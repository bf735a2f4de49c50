// SPDX-License-Identifier: BSL-1.0
// Shared by the Kokkos tests: the execution space under test, a reproducible scene for any
// configuration, a bit-for-bit comparison of every stored array, and the equivalence run
// (a ParticleSystem stepped by ParticleSystem::step and a KokkosSystem stepped by Kokkos
// from the same start, compared after every step count asked for).
#pragma once

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <tuple>
#include <type_traits>
#include <typeinfo>

#include <pointmass/kokkos.hpp>
#include <pointmass/particle_system.hpp>

namespace pointmass::test {

using Space = POINTMASS_TEST_KOKKOS_SPACE;
using Memory = Space::memory_space;

template <class System>
using DeviceSystem = KokkosSystem<System, Memory>;

template <class R>
Vector3<R> random_vector(std::mt19937& engine, R scale) {
  std::uniform_real_distribution<R> component(-scale, scale);
  return {component(engine), component(engine), component(engine)};
}

/// True when `a` and `b` have the same size and every array the configuration stores holds
/// the same bits in both (found through the layout's table, so every column counts).
template <class System>
bool same_arrays(const System& a, const System& b) {
  if (a.size() != b.size()) return false;
  using Layout = detail::layout_of_t<System>;
  typename System::Arrays first = pointmass::detail::SystemAccess::arrays(a);
  bool same = true;
  std::size_t arrays = 0;
  Layout::for_each_array_pair(first, pointmass::detail::SystemAccess::arrays(b),
                              [&](auto* x, auto* y) {
                                ++arrays;
                                same = same && std::memcmp(x, y, a.size() * sizeof(*x)) == 0;
                              });
  return same && arrays == pointmass::detail::SystemAccess::Layout<System>::array_count;
}

/// Steps of varied length (seconds), including a long one that takes Exact past |kt| = 1/4.
template <class R>
constexpr std::array<R, 5> durations = {R(1) / R(60), R(1) / R(30), R(0.1), R(0.005), R(0.7)};

/// `count` particles with random positions and velocities and, as the configuration stores
/// them, random accelerations, damping values (among them 1 and 0), masses (some immovable),
/// forces and lifetimes (some infinite, the others over about the first 1,000 steps).
template <class System>
System make_scene(std::size_t count, std::uint32_t seed) {
  using R = typename System::real;
  std::mt19937 engine(seed);
  std::uniform_real_distribution<R> unit(R(0), R(1));
  System system(count);
  if constexpr (!System::template has<pointmass::features::PerParticleAcceleration>) {
    system.set_acceleration({R(1.5), R(-9.807), R(0.25)});
  }
  if constexpr (System::stores_damping &&
                !System::template has<pointmass::features::PerParticleDamping>) {
    system.set_damping(R(0.6));
  }
  for (std::size_t i = 0; i < count; ++i) {
    const Vector3<R> position = random_vector(engine, R(100));
    using Value = typename System::position_value;  // R, or wider (precision.hpp)
    REQUIRE(system.spawn({Value(position.x), Value(position.y), Value(position.z)},
                         random_vector(engine, R(30))) == i);
    if constexpr (System::template has<pointmass::features::PerParticleAcceleration>) {
      system.set_acceleration(i, random_vector(engine, R(20)));
    }
    if constexpr (System::template has<pointmass::features::PerParticleDamping>) {
      system.set_damping(i, i % 9 == 0 ? R(1) : i % 13 == 0 ? R(0) : unit(engine));
    }
    if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
      if (i % 6 == 0) {
        system.set_inverse_mass(i, R(0));  // immovable
      } else {
        system.set_mass(i, R(0.25) + R(3.75) * unit(engine));
      }
      system.add_force(i, random_vector(engine, R(5)));
    }
    if constexpr (System::template has<pointmass::features::Lifetime>) {
      // The 1,000 steps below last 171 s: most particles expire on the way, at random steps.
      system.set_lifetime(i, i % 7 == 0 ? real_infinity<R> : R(1) + R(199) * unit(engine));
    }
  }
  return system;
}

/// Steps a ParticleSystem (ParticleSystem::step) and two KokkosSystems (Kokkos, in Space:
/// KokkosSystem::step, and the device's loop of one particle per index) from the same scene of `count` particles `steps` times, then copies the Kokkos arrays back and
/// checks that they equal the host's bit for bit, that the particles moved, and that
/// lifetimes expired particles (the same ones, in the same order: every array is compared).
template <class System>
void check_equivalence(std::size_t count, int steps, std::uint32_t seed) {
  using R = typename System::real;
  CAPTURE(count);
  System host = make_scene<System>(count, seed);
  DeviceSystem<System> device(host);
  // The loop KokkosSystem::step runs on a device (one particle per index), run here too.
  DeviceSystem<System> each(host);
  REQUIRE(device.size() == count);
  const auto start = host.position(count - 1);  // wider than R with wide positions
  for (int step = 0; step < steps; ++step) {
    const R t = durations<R>[static_cast<std::size_t>(step) % durations<R>.size()];
    host.step(t);
    device.step(Space(), t);
    detail::kokkos_step_each<System>(Space(), each.arrays(), each.step_parameters(t));
    each.expire(Space());
  }
  System back;
  device.copy_to(back);
  REQUIRE(back.size() == host.size());
  CHECK(same_arrays(back, host));
  each.copy_to(back);
  REQUIRE(back.size() == host.size());
  CHECK(same_arrays(back, host));
  if constexpr (System::template has<pointmass::features::Lifetime>) {
    CHECK(host.size() < count);  // particles expired ...
    CHECK(host.size() > 0);      // ... not all of them
  } else {
    CHECK_FALSE(host.position(count - 1) == start);  // the particles moved
  }
}

/// The feature sets each policy pair runs with: none, each feature alone, and all of them
/// (PerParticleDamping only where the damping policy has a value).
template <class R, class D, class P>
struct FeatureSets {
  static constexpr bool damped = !std::is_empty_v<typename D::template State<R>>;
  using All = std::conditional_t<
      damped,
      ParticleSystem<R, D, P, features::PerParticleDamping, features::PerParticleAcceleration,
                     features::ForceAccumulator, features::Lifetime>,
      ParticleSystem<R, D, P, features::PerParticleAcceleration, features::ForceAccumulator,
                     features::Lifetime>>;
  using Common = std::tuple<ParticleSystem<R, D, P>,
                            ParticleSystem<R, D, P, features::PerParticleAcceleration>,
                            ParticleSystem<R, D, P, features::ForceAccumulator>,
                            ParticleSystem<R, D, P, features::Lifetime>, All>;
  using type = std::conditional_t<
      damped,
      decltype(std::tuple_cat(
          std::declval<Common>(),
          std::declval<std::tuple<ParticleSystem<R, D, P, features::PerParticleDamping>>>())),
      Common>;
};

/// Sizes around the vector block (16) and the backward walk's chunk (256).
inline constexpr std::array<std::size_t, 6> sizes_around_the_block = {15, 16, 17, 255, 256, 257};

/// One configuration at every size, 1,000 steps.
template <class System>
void check_configuration() {
  INFO("configuration: ", doctest::String(typeid(System).name()));
  std::uint32_t seed = 11;
  for (const std::size_t count : sizes_around_the_block) {
    check_equivalence<System>(count, 1000, seed++);
  }
}

template <class... Systems>
void check_configurations(std::tuple<Systems...>*) {
  (check_configuration<Systems>(), ...);
}

/// Every feature set of policy pair (D, P), float and double, at every size, 1,000 steps.
template <class D, class P>
void check_pair() {
  check_configurations(static_cast<typename FeatureSets<float, D, P>::type*>(nullptr));
  check_configurations(static_cast<typename FeatureSets<double, D, P>::type*>(nullptr));
}

}  // namespace pointmass::test
