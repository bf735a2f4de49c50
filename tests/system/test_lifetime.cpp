// SPDX-License-Identifier: BSL-1.0
// Lifetimes (system/lifetime.hpp): particles age by each step and expire when the age reaches
// the lifetime, exactly the expired ones and on the exact step; the expiry callback, once for
// each expiring particle in its final state, and the particles it spawns.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;
using pointmass::test::SpawnTag;

TEST_CASE_TEMPLATE("lifetime: particles age by each step and expire when age reaches lifetime", R,
                   float, double) {
  ParticleSystem<R, damping::None, position::Euler, features::Lifetime> system(4);
  const std::size_t a = system.spawn({}, {});
  const std::size_t b = system.spawn({R(1), R(0), R(0)}, {});
  const std::size_t c = system.spawn({R(2), R(0), R(0)}, {});
  system.set_lifetime(a, R(0.25));
  system.set_lifetime(b, R(1));
  CHECK(system.lifetime(c) == real_infinity<R>);
  system.step(R(0.1));
  system.step(R(0.1));
  CHECK(system.size() == 3);
  CHECK(system.age(0) == R(0.1) + R(0.1));
  system.step(R(0.1));  // a: age 0.3 >= 0.25
  REQUIRE(system.size() == 2);
  std::multiset<R> left{system.position(0).x, system.position(1).x};
  CHECK(left == std::multiset<R>{R(1), R(2)});
  for (int i = 0; i < 10; ++i) system.step(R(0.1));  // b: age 1.3
  REQUIRE(system.size() == 1);
  CHECK(system.position(0).x == R(2));
}

TEST_CASE_TEMPLATE("lifetime in a large system: exactly the expired particles go, every step", R,
                   float, double) {
  // 1,000 particles (many blocks of 16) with lifetimes (n + 1/2) / 64 s in a shuffled order,
  // stepped by 1/64 s (exact in binary): after step k, exactly those with n >= k are alive,
  // each of them once, whatever the order the swap-removes left them in.
  constexpr std::size_t count = 1000;
  ParticleSystem<R, damping::None, position::Euler, features::Lifetime> system(count);
  std::vector<std::size_t> order(count);
  for (std::size_t n = 0; n < count; ++n) order[n] = n;
  std::shuffle(order.begin(), order.end(), std::mt19937(42));
  for (const std::size_t n : order) {
    const std::size_t i = system.spawn({R(n), R(0), R(0)}, {});  // x names the particle
    system.set_lifetime(i, (R(n) + R(0.5)) / R(64));
  }
  for (std::size_t k = 1; k <= 40; ++k) {
    system.step(R(1) / R(64));
    REQUIRE(system.size() == count - k);
    std::vector<std::size_t> alive;
    for (std::size_t i = 0; i < system.size(); ++i) {
      CHECK(system.age(i) < system.lifetime(i));
      alive.push_back(static_cast<std::size_t>(system.position(i).x));
    }
    std::sort(alive.begin(), alive.end());
    CHECK(alive.front() == k);
    CHECK(std::adjacent_find(alive.begin(), alive.end()) == alive.end());  // no duplicates
  }
}

TEST_CASE_TEMPLATE(
    "lifetime: the step on which the age equals the lifetime exactly removes the "
    "particle, and a lifetime one ulp longer lives one step more",
    R, float, double) {
  // 40 particles: 32 in whole vector blocks (the block scan), 8 in the rest (one at a time).
  // Steps of 1/64 s add up exactly, so after step 3 the age is 3/64 s to the last bit. Even
  // indices live exactly 3/64 s, odd ones the next R above it; x names the particle.
  constexpr std::size_t count = 40;
  ParticleSystem<R, damping::None, position::Euler, features::Lifetime> system(count);
  const R exact = R(3) / R(64);
  const R longer = std::nextafter(exact, real_infinity<R>);
  for (std::size_t n = 0; n < count; ++n) {
    const std::size_t i = system.spawn({R(n), R(0), R(0)}, {});
    system.set_lifetime(i, n % 2 == 0 ? exact : longer);
  }
  const auto expired = [](R age, R lifetime) {
    return pointmass::detail::lifetime_expired(age, R(0), lifetime);
  };
  CHECK(expired(exact, exact));
  // the age is age + age_error: what the rounding dropped counts
  const R below = std::nextafter(exact, R(0));
  CHECK(pointmass::detail::lifetime_expired(below, exact - below, exact));
  CHECK_FALSE(expired(std::nextafter(exact, R(0)), exact));
  CHECK_FALSE(expired(real_infinity<R>, real_infinity<R>));  // never, even overflowed
  const auto alive = [&] {
    std::vector<std::size_t> names;
    for (std::size_t i = 0; i < system.size(); ++i) {
      names.push_back(static_cast<std::size_t>(system.position(i).x));
    }
    std::sort(names.begin(), names.end());
    return names;
  };
  system.step(R(1) / R(64));
  system.step(R(1) / R(64));
  CHECK(system.size() == count);
  system.step(R(1) / R(64));
  REQUIRE(system.size() == count / 2);
  CHECK(system.age(0) == exact);
  const std::vector<std::size_t> names = alive();
  for (std::size_t k = 0; k < names.size(); ++k) {
    CAPTURE(k);
    CHECK(names[k] == 2 * k + 1);  // every odd one, and only those
  }
  system.step(R(1) / R(64));
  CHECK(system.empty());
}

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

TEST_CASE("expiry callback that throws: it and those before it are removed, the rest next step") {
  // 12 particles (ids in a column) expire on the first step, 4 live on. The callback throws on
  // its third call, as a callback does that kill()s (refused) or fails to allocate.
  using Shells = ParticleSystem<float, damping::None, position::Euler, features::Lifetime,
                                features::Column<SpawnTag, int>>;
  Shells system;
  for (int id = 0; id < 16; ++id) {
    system.set_lifetime(system.spawn({float(id), 0, 0}, {}, id), id < 12 ? 0.01f : 100.0f);
  }
  std::vector<int> first;
  struct Thrown {};
  CHECK_THROWS_AS(system.step(1.0f / 60,
                              [&](std::size_t i) {
                                first.push_back(system.column<SpawnTag>(i));
                                if (first.size() == 3) throw Thrown{};
                              }),
                  Thrown);
  REQUIRE(first.size() == 3);
  CHECK(system.size() == 13);  // the three reported, the third included, are gone
  std::set<int> left;
  for (std::size_t i = 0; i < system.size(); ++i) left.insert(system.column<SpawnTag>(i));
  for (const int id : first) CHECK(left.count(id) == 0);
  // The next step reports the nine not reached, each once, and removes them.
  std::vector<int> second;
  system.step(1.0f / 60, [&](std::size_t i) { second.push_back(system.column<SpawnTag>(i)); });
  std::sort(second.begin(), second.end());
  CHECK(second.size() == 9);
  CHECK(std::adjacent_find(second.begin(), second.end()) == second.end());
  for (const int id : second) CHECK((id < 12 && left.count(id) == 1));
  CHECK(system.size() == 4);
}

TEST_CASE("lifetime: float ages count every step exactly, far from zero") {
  // From 2^18 s each 1/60 s step rounds to 1/32 s in a float sum (ages twice too fast), and
  // from 2^19 s it adds nothing; the counted age (age + age_error) gains the steps' sum.
  ParticleSystem<float, damping::None, position::Euler, features::Lifetime> system(2);
  const std::size_t early = system.spawn({}, {});
  const std::size_t late = system.spawn({}, {});
  system.column<Column::age>()[early] = 0x1p18f;
  system.column<Column::age>()[late] = 0x1p19f;
  system.set_lifetime(early, 0x1p18f + 100.0f);
  system.set_lifetime(late, 0x1p19f + 100.0f);
  const float step = 1.0f / 60.0f;
  const double exact_steps = 100.0 / double(step);  // 6,000 steps of the float step
  std::size_t steps = 0;
  std::size_t early_gone = 0;
  while (system.size() > 0 && steps < 20000) {
    system.step(step);
    ++steps;
    if (early_gone == 0 && system.size() < 2) early_gone = steps;
    if (steps == 3000) {  // 50 s in: both ages have grown by 50 s
      for (std::size_t i = 0; i < system.size(); ++i) {
        const double grown = double(system.age(i)) - double(system.lifetime(i)) + 100.0;
        CHECK(grown == doctest::Approx(3000.0 * double(step)).epsilon(1e-6));
      }
    }
  }
  // Each expires on the step its exact age reaches its lifetime (within the rounding of one).
  CHECK(double(early_gone) >= exact_steps - 1.0);
  CHECK(double(early_gone) <= exact_steps + 1.0);
  CHECK(double(steps) >= exact_steps - 1.0);
  CHECK(double(steps) <= exact_steps + 1.0);
}
