// SPDX-License-Identifier: BSL-1.0
// The compute roofs of a force-driven step: how fast a particle-step can be when its data is
// in registers and L1 and only its arithmetic counts, for the two ways the library computes
// forces.
//   * fused_compute_roof: the laws' fused forms (forces/fused.hpp, what step(t, laws) runs)
//     and the Euler step, vectorised, over 64 particles in local arrays;
//   * scalar_compute_roof: each law's force() and Particle::integrate (what a registry or an
//     update_force loop runs per particle), over 64 particles in a local array.
// Both repeat their block as many times as the benchmark's size has blocks of 64, and put the
// block back to its start every 4,096 passes (drag and damping would bring it to rest).
#pragma once

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace pointmass_benchmarks {

inline constexpr std::size_t roof_block = 64;
inline constexpr std::uint64_t roof_refresh = 4096;  // 68 s of motion at 1/60 s: never at rest

/// Particle k of a roof's block: position, velocity and mass, from the caller's scene.
template <class R>
struct RoofStart {
  pointmass::Vector3<R> position, velocity;
  R mass;
};

// Runs `pass` over the blocks of state.range(0) particles; items_per_second: particle-steps/s.
template <class Block, class Pass>
void time_roof(benchmark::State& state, const Block& start, Pass&& pass) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::size_t blocks = (n + roof_block - 1) / roof_block;
  Block b = start;
  std::uint64_t passes = 0;
  for (auto _ : state) {
    for (std::size_t k = 0; k < blocks; ++k) {
      pass(b);
      benchmark::DoNotOptimize(b);
      benchmark::ClobberMemory();
      if (++passes % roof_refresh == 0) b = start;
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(blocks * roof_block));
}

/// The fused laws `drag` and `spring` and the Euler step under `acceleration`, damping
/// `kept_per_second`, for steps of t; `start(k)` gives particle k's RoofStart.
template <class R, class Drag, class Spring, class Start>
void fused_compute_roof(benchmark::State& state, const Drag& drag, const Spring& spring,
                        pointmass::Vector3<R> acceleration, R kept_per_second, R t, Start&& start) {
  struct Block {
    std::array<R, roof_block> px, py, pz, vx, vy, vz, w;
  };
  Block first{};
  for (std::size_t i = 0; i < roof_block; ++i) {
    const RoofStart<R> s = start(i * 16);
    first.px[i] = s.position.x, first.py[i] = s.position.y, first.pz[i] = s.position.z;
    first.vx[i] = s.velocity.x, first.vy[i] = s.velocity.y, first.vz[i] = s.velocity.z;
    first.w[i] = R(1) / s.mass;
  }
  // The forms the step evaluates (forces/fused.hpp).
  const auto fused_drag = pointmass::forces::detail::fused_form(drag);
  const auto fused_spring = pointmass::forces::detail::fused_form(spring);
  const R kept = std::pow(kept_per_second, t);  // d^t, as the system keeps it for t
  // Captured by value: captured references could alias the block, and the loop stayed scalar.
  time_roof(state, first, [=](Block& b) {
    // No pragma: a local block aliases nothing, and the compiler vectorises this loop exactly
    // when it can vectorise the step's (clang's assume_safety warns where it cannot).
    for (std::size_t i = 0; i < roof_block; ++i) {
      using V = pointmass::Vector3<R>;
      const V p{b.px[i], b.py[i], b.pz[i]};
      const V v{b.vx[i], b.vy[i], b.vz[i]};
      const R w = b.w[i];
      const V d = fused_drag.fused(p, v, w, t).force;
      const V s = fused_spring.fused(p, v, w, t).force;
      const V f{(R(0) + d.x) + s.x, (R(0) + d.y) + s.y, (R(0) + d.z) + s.z};
      const V a = acceleration + f * w;
      b.px[i] = p.x + v.x * t, b.py[i] = p.y + v.y * t, b.pz[i] = p.z + v.z * t;
      b.vx[i] = v.x * kept + a.x * t, b.vy[i] = v.y * kept + a.y * t;
      b.vz[i] = v.z * kept + a.z * t;
    }
  });
}

/// Each law's force() added to a Particle<R>, then its integrate, under `acceleration` and
/// damping `kept_per_second` per second, for steps of t; `start(k)` as above.
template <class R, class Drag, class Spring, class Start>
void scalar_compute_roof(benchmark::State& state, const Drag& drag, const Spring& spring,
                         pointmass::Vector3<R> acceleration, R kept_per_second, R t,
                         Start&& start) {
  using Block = std::array<pointmass::Particle<R>, roof_block>;
  Block first{};
  for (std::size_t i = 0; i < roof_block; ++i) {
    const RoofStart<R> s = start(i * 16);
    first[i].set_position(s.position);
    first[i].set_velocity(s.velocity);
    first[i].set_acceleration(acceleration);
    first[i].set_damping(kept_per_second);
    first[i].set_mass(s.mass);
  }
  time_roof(state, first, [&](Block& b) {
    for (auto& particle : b) {
      pointmass::forces::update_force(drag, particle, t);
      pointmass::forces::update_force(spring, particle, t);
      particle.integrate(t);
    }
  });
}

}  // namespace pointmass_benchmarks
