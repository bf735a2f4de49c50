// SPDX-License-Identifier: BSL-1.0
// Shared by the snapshot tests and the golden snapshots' writer: configurations, a portable
// random source and a scene of births, deaths, forces and steps that any configuration runs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <pointmass/particle_system.hpp>
#include <pointmass/snapshot.hpp>

namespace pointmass::test::snapshots {

struct Kind {};  // a user column: the firework's kind

using Fireworks =
    ParticleSystem<float, damping::PerSecond, position::SemiImplicit, features::PerParticleDamping,
                   features::Lifetime, features::Interpolation, features::Handles,
                   features::Column<Kind, std::uint32_t>>;
using Rope = ParticleSystem<double, damping::PerSecond, position::VelocityVerlet,
                            features::ForceAccumulator, features::Handles>;
using Far = ParticleSystem<Precision<float, Compensated<float>>, damping::Exact, position::Exact,
                           features::PerParticleAcceleration, features::Lifetime,
                           features::BasicHandles<std::uint8_t>>;
using Wide = ParticleSystem<long double, damping::PerFrame, position::Euler, features::Lifetime,
                            features::Interpolation>;
using Sparks = ParticleSystem<float>;

/// The same numbers on every platform (std's distributions are not).
struct Random {
  std::uint64_t state;
  std::uint32_t next() noexcept {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<std::uint32_t>(state >> 33);
  }
  /// In [-scale, scale), a multiple of scale / 2^20.
  template <class R>
  R uniform(R scale) noexcept {
    return scale * (R(static_cast<std::int32_t>(next() >> 11) - (1 << 20)) / R(1 << 20));
  }
};

/// `steps` frames of 1/60 s: each spawns a few particles (lifetimes, damping, mass, a kind
/// where the configuration has them), kills one, pushes every particle and steps; particles
/// whose lifetime ends are removed by the step.
template <class System>
void run_scene(System& system, Random& random, int steps) {
  using R = typename System::real;
  using P = typename System::position_value;
  for (int frame = 0; frame < steps; ++frame) {
    if constexpr (!System::template has<features::PerParticleAcceleration>) {
      system.set_acceleration({R(0), R(-9.81), random.uniform(R(1))});
    }
    if constexpr (System::stores_damping && !System::template has<features::PerParticleDamping>) {
      system.set_damping(R(0.5) + random.uniform(R(0.25)));
    }
    for (int n = 0; n < 6; ++n) {
      // (Drawn in order: a call's arguments are evaluated in an order each compiler picks.)
      const Vector3<P> position{P(random.uniform(R(100))), P(random.uniform(R(100))), P(1e3)};
      const Vector3<R> velocity{random.uniform(R(20)), random.uniform(R(20)),
                                random.uniform(R(20))};
      const std::size_t i = system.spawn(position, velocity);
      if constexpr (System::template has<features::Lifetime>) {
        system.set_lifetime(i, R(0.1) + R(random.next() % 90) / R(60));
      }
      if constexpr (System::template has<features::PerParticleDamping>) {
        system.set_damping(i, R(0.2) + R(random.next() % 80) / R(100));
      }
      if constexpr (System::template has<features::PerParticleAcceleration>) {
        system.set_acceleration(i, {R(0), R(-9.81), random.uniform(R(1))});
      }
      if constexpr (System::template has<features::ForceAccumulator>) {
        system.set_mass(i, R(0.5) + R(random.next() % 8) / R(4));
      }
      if constexpr (System::template has<Kind>) system.template set_column<Kind>(i, random.next());
    }
    if (system.size() > 3) system.kill(random.next() % system.size());
    if constexpr (System::template has<features::ForceAccumulator>) {
      for (std::size_t i = 0; i < system.size(); ++i) {  // a spring to the origin, and drag
        const auto p = system.position(i);
        const auto v = system.velocity(i);
        system.add_force(i, Vector3<R>{R(-4) * p.x - v.x, R(-4) * p.y - v.y, R(-4) * p.z - v.z});
      }
    }
    system.step(R(1) / R(60));
  }
}

/// Every stored column's live values, as bytes (the value bytes of each element).
template <class System>
std::vector<std::vector<std::byte>> columns_of(const System& system) {
  using Access = detail::SystemAccess;
  std::vector<std::vector<std::byte>> columns;
  Access::Layout<System>::for_each_array(Access::arrays(system), [&](const auto* array) {
    using T = std::remove_cvref_t<decltype(*array)>;
    auto& column = columns.emplace_back();
    for (std::size_t i = 0; i < system.size(); ++i) {
      const auto* bytes = reinterpret_cast<const std::byte*>(array + i);
      column.insert(column.end(), bytes, bytes + detail::value_bytes<T>);
    }
  });
  return columns;
}

}  // namespace pointmass::test::snapshots
