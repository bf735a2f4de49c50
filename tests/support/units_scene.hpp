// SPDX-License-Identifier: BSL-1.0
// The scene that compares the plain and the SI particle (benchmarks/units_cost.cpp times it,
// tests/units/units_instructions.cpp counts its instructions): 1024 particles launched with
// the four ballistic shots in turn, then for 150 frames of 1/30 s a push (add_force) and a
// step each. Written once, so the two measures are of the same work.
#pragma once

#include <cstddef>
#include <vector>

#include <pointmass/extras/scenes.hpp>

namespace pointmass::test {

inline constexpr std::size_t units_scene_particles = 1024;
inline constexpr int units_scene_frames = 150;

/// Puts every particle at the start of one of the shots, in turn.
template <class Particle>
void launch_units_scene(std::vector<Particle>& particles) {
  using R = typename Particle::real;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    scenes::launch(particles[i], scenes::ballistic_shots<R>[i % 4]);
  }
}

/// The frames: each particle pushed, then stepped by `frame`.
template <class Particle>
void fly_units_scene(std::vector<Particle>& particles, const auto& frame, const auto& push) {
  for (int f = 0; f < units_scene_frames; ++f) {
    for (auto& particle : particles) {
      particle.add_force(push);
      particle.integrate(frame);
    }
  }
}

}  // namespace pointmass::test
