// SPDX-License-Identifier: BSL-1.0
// Lifetimes (system/lifetime.hpp): the expiry callback, once for each expiring particle in its
// final state, and the particles it spawns, stepped from the next step on.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;
using pointmass::test::SpawnTag;

TEST_CASE("expiry callback: each expiring particle once, in its final state, children next step") {
  using Fireworks = ParticleSystem<double, damping::PerSecond, position::Euler, features::Lifetime,
                                   features::Column<SpawnTag, int>>;
  Fireworks system;
  system.set_acceleration({0, -9.8, 0});
  system.set_damping(0.5);
  std::vector<Particle<double>> model;  // each parent's state, by spawn id
  for (int id = 0; id < 50; ++id) {
    const Vector3<double> p{double(id), 0, 0};
    const Vector3<double> v{0, 10 + double(id), 1};
    const std::size_t i = system.spawn(p, v, id);
    system.set_lifetime(i, (1 + id % 5) / 60.0);
    model.emplace_back();
    model.back().set_position(p);
    model.back().set_velocity(v);
    model.back().set_acceleration({0, -9.8, 0});
    model.back().set_damping(0.5);
  }
  const double t = 1.0 / 60;
  std::vector<int> seen;
  int next_child = 1000;
  std::vector<std::pair<int, Vector3<double>>> children;  // child id, its parent's final place
  for (int frame = 1; frame <= 5; ++frame) {
    for (std::size_t id = 0; id < 50; ++id) {
      if (frame <= 1 + int(id) % 5) model[id].integrate(t);
    }
    std::vector<int> this_step;
    system.step(t, [&](std::size_t i) {
      const int id = system.column<SpawnTag>(i);
      this_step.push_back(id);
      if (id >= 1000) return;  // children do not burst
      // The final state: the model after the same number of steps.
      CHECK(same_bits(system.position(i), model[std::size_t(id)].position()));
      CHECK(same_bits(system.velocity(i), model[std::size_t(id)].velocity()));
      CHECK(system.age(i) >= system.lifetime(i));
      for (int c = 0; c < 2; ++c) {  // children, spawned during the callback
        const std::size_t child = system.spawn(system.position(i), {0, 1, 0}, next_child);
        system.set_lifetime(child, 1.0);
        children.emplace_back(next_child++, system.position(i));
      }
    });
    std::sort(this_step.begin(), this_step.end());
    std::vector<int> expected;
    for (int id = 0; id < 50; ++id) {
      if (1 + id % 5 == frame) expected.push_back(id);
    }
    CHECK(this_step == expected);  // each once, exactly those whose lifetime ended now
    seen.insert(seen.end(), this_step.begin(), this_step.end());
    // The children spawned in this step exist after it, where their parent ended, unstepped.
    for (std::size_t i = 0; i < system.size(); ++i) {
      const int id = system.column<SpawnTag>(i);
      if (id < 1000) continue;
      const auto child = std::find_if(children.begin(), children.end(),
                                      [&](const auto& c) { return c.first == id; });
      REQUIRE(child != children.end());
      Particle<double> stepped;
      stepped.set_position(child->second);
      stepped.set_velocity({0, 1, 0});
      stepped.set_acceleration({0, -9.8, 0});
      stepped.set_damping(0.5);
      const int steps_since = frame - (id - 1000) / 20 - 1;  // 10 parents a frame, 2 each
      for (int s = 0; s < steps_since; ++s) stepped.integrate(t);
      CHECK(same_bits(system.position(i), stepped.position()));
      CHECK(system.age(i) == doctest::Approx(steps_since * t));
    }
  }
  CHECK(seen.size() == 50);
  CHECK(system.size() == 100);  // the children
}
