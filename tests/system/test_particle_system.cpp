// SPDX-License-Identifier: BSL-1.0
// ParticleSystem (particle_system.hpp): spawn, kill by index and by predicate (swap-remove),
// capacity and growth, bad input reported with the argument's name and value, spawn_burst.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::random_vector;
using pointmass::test::same_bits;
using pointmass::test::SpawnTag;

TEST_CASE_TEMPLATE("spawn, kill by index and by predicate: swap-remove", R, float, double) {
  ParticleSystem<R> system(8);
  for (int i = 0; i < 6; ++i) system.spawn({R(i), R(0), R(0)}, {});
  REQUIRE(system.size() == 6);
  system.kill(1);  // the last (x = 5) takes index 1
  REQUIRE(system.size() == 5);
  CHECK(system.position(1).x == R(5));
  CHECK(system.position(4).x == R(4));
  system.kill(4);  // the last itself
  CHECK(system.size() == 4);
  // Remaining x: 0, 5, 2, 3. Remove the even ones.
  const std::size_t removed = system.kill_if(
      [&](std::size_t i) { return static_cast<int>(system.position(i).x) % 2 == 0; });
  CHECK(removed == 2);
  REQUIRE(system.size() == 2);
  std::multiset<R> left{system.position(0).x, system.position(1).x};
  CHECK(left == std::multiset<R>{R(3), R(5)});
  CHECK(system.template column<pointmass::Column::position_x>().size() == 2);
  system.clear();
  CHECK(system.empty());

  // Every particle removed: after each removal the predicate is asked about the particle
  // moved into the freed index, so each is asked once and none is left behind.
  for (int i = 0; i < 7; ++i) system.spawn({R(i), R(0), R(0)}, {});
  std::vector<int> asked;
  const std::size_t all = system.kill_if([&](std::size_t i) {
    asked.push_back(static_cast<int>(system.position(i).x));
    return true;
  });
  CHECK(all == 7);
  CHECK(system.empty());
  std::sort(asked.begin(), asked.end());
  CHECK(asked == std::vector<int>{0, 1, 2, 3, 4, 5, 6});
  CHECK(system.capacity() == 8);
}

// (That a step allocates nothing at all is counted by tests/hardening/test_allocation_failure.cpp,
// which replaces operator new.)
TEST_CASE_TEMPLATE("capacity is reserved up front, a step keeps the block, growth keeps data", R,
                   float, double) {
  ParticleSystem<R> system(64);
  std::mt19937 engine(1);
  for (int i = 0; i < 64; ++i)
    system.spawn(random_vector(engine, R(10)), random_vector(engine, R(10)));
  const R* block = system.template column<pointmass::Column::position_x>().data();
  for (int i = 0; i < 5; ++i) system.step(R(0.01));
  CHECK(system.capacity() == 64);
  CHECK(system.template column<pointmass::Column::position_x>().data() == block);

  ParticleSystem<R> before = system;  // a copy, to compare after growing
  system.spawn({}, {});               // beyond capacity: the block doubles
  CHECK(system.capacity() == 128);
  REQUIRE(system.size() == 65);
  for (std::size_t i = 0; i < 64; ++i) {
    REQUIRE(same_bits(system.position(i), before.position(i)));
    REQUIRE(same_bits(system.velocity(i), before.velocity(i)));
  }
  ParticleSystem<R> moved = std::move(system);
  CHECK(moved.size() == 65);
  CHECK(system.size() == 0);  // NOLINT(bugprone-use-after-move): moved-from is empty
}

TEST_CASE_TEMPLATE("bad input is reported with the argument's name and value", R, float, double) {
  using System = ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime,
                                features::ForceAccumulator>;
  System system(4);
  const R nan = std::numeric_limits<R>::quiet_NaN();
  auto message = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "(accepted)";
  };
  CHECK(message([&] {
          system.spawn({nan, R(0), R(0)}, {});
        }).find("'position'") != std::string::npos);
  CHECK(system.empty());  // nothing added
  system.spawn({}, {});
  CHECK(message([&] { system.set_damping(R(1.5)); }).find("'damping' = 1.5") != std::string::npos);
  CHECK(message([&] { system.set_lifetime(0, R(0)); }).find("'seconds' = 0") != std::string::npos);
  CHECK(message([&] { system.set_mass(0, R(-1)); }).find("'mass' = -1") != std::string::npos);
  CHECK(message([&] { system.kill(7); }).find("'index' = 7") != std::string::npos);
  CHECK(message([&] {
          system.set_acceleration({R(0), real_infinity<R>, R(0)});
        }).find("'acceleration'") != std::string::npos);
#if POINTMASS_CHECKS
  CHECK(message([&] { system.step(R(-0.1)); }).find("step: argument 'duration'") !=
        std::string::npos);
#endif
  CHECK(system.size() == 1);
  CHECK(system.damping() == R(1));
}

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
