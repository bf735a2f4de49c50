// SPDX-License-Identifier: BSL-1.0
// Columns (system/columns.hpp): spans over the live particles that write through; user columns
// given at spawn or T{}, written by span and index, kept by growth and copies, and following
// their particle through kills, kill_if and expiry.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;
using pointmass::test::SpawnTag;

namespace {

struct ColourTag {};
struct Colour {
  std::uint8_t r, g, b, a;
};

using Recorded = ParticleSystem<double, damping::None, position::Euler, features::Lifetime,
                                features::Column<SpawnTag, std::uint64_t>>;

/// The reference model: the same particles on plain vectors, stepped by scalar Particles,
/// removed by the same swap-remove rules (kill: the last moves in; kill_if and expiry: one
/// pass, asking again about the particle moved into a freed index).
struct Model {
  std::vector<std::uint64_t> spawn;
  std::vector<Particle<double, damping::None, position::Euler>> body;
  std::vector<double> age, age_error, lifetime;  // the age is age + age_error (Kahan's sum)

  void add(std::uint64_t id, const Vector3<double>& p, const Vector3<double>& v, double life) {
    spawn.push_back(id);
    body.emplace_back();
    body.back().set_position(p);
    body.back().set_velocity(v);
    body.back().set_acceleration({0, -9.8, 0});
    age.push_back(0);
    age_error.push_back(0);
    lifetime.push_back(life);
  }
  void remove(std::size_t i) {
    const std::size_t last = spawn.size() - 1;
    spawn[i] = spawn[last];
    body[i] = body[last];
    age[i] = age[last];
    age_error[i] = age_error[last];
    lifetime[i] = lifetime[last];
    spawn.pop_back();
    body.pop_back();
    age.pop_back();
    age_error.pop_back();
    lifetime.pop_back();
  }
  template <class Predicate>
  void remove_if(Predicate predicate) {
    std::size_t i = 0;
    while (i < spawn.size()) {
      if (predicate(i)) {
        remove(i);
      } else {
        ++i;
      }
    }
  }
  void step(double t) {
    for (std::size_t i = 0; i < spawn.size(); ++i) {
      body[i].integrate(t);
      const double step = t + age_error[i];
      const double sum = age[i] + step;
      age_error[i] = step - (sum - age[i]);
      age[i] = sum;
    }
    remove_if([&](std::size_t i) { return age[i] + age_error[i] >= lifetime[i]; });
  }
};

bool same_as_model(const Recorded& system, const Model& model) {
  if (system.size() != model.spawn.size()) return false;
  for (std::size_t i = 0; i < system.size(); ++i) {
    if (system.column<SpawnTag>(i) != model.spawn[i]) return false;
    if (!same_bits(system.position(i), model.body[i].position())) return false;
    if (!same_bits(system.velocity(i), model.body[i].velocity())) return false;
    if (!same_bits(system.age(i), model.age[i] + model.age_error[i])) return false;
  }
  return true;
}

}  // namespace

TEST_CASE_TEMPLATE("spans view the live particles and write through", R, float, double) {
  ParticleSystem<R, damping::None, position::Euler, features::ForceAccumulator> system(10);
  for (int i = 0; i < 3; ++i) system.spawn({R(i), R(2 * i), R(3 * i)}, {});
  CHECK(system.template column<pointmass::Column::position_y>().size() == 3);
  CHECK(system.template column<pointmass::Column::position_y>()[2] == R(4));
  system.template column<pointmass::Column::velocity_x>()[1] = R(10);
  system.step(R(0.5));
  CHECK(system.position(1).x == R(1) + R(10) * R(0.5));
  system.template column<Column::inverse_mass>()[1] = R(0);  // immovable from now on
  system.step(R(0.5));
  CHECK(system.position(1).x == R(6));
  // Read through a const system, each span is its own column.
  ParticleSystem<R> drawn;
  drawn.spawn({R(1), R(2), R(3)}, {R(4), R(5), R(6)});
  const auto& seen = drawn;
  CHECK(seen.template column<pointmass::Column::position_x>()[0] == R(1));
  CHECK(seen.template column<pointmass::Column::position_y>()[0] == R(2));
  CHECK(seen.template column<pointmass::Column::position_z>()[0] == R(3));
  CHECK(seen.template column<pointmass::Column::velocity_x>()[0] == R(4));
  CHECK(seen.template column<pointmass::Column::velocity_y>()[0] == R(5));
  CHECK(seen.template column<pointmass::Column::velocity_z>()[0] == R(6));
  CHECK(seen.template column<pointmass::Column::velocity_z>().size() == 1);
}

TEST_CASE("a user column follows its particle through kills, kill_if and expiry (10,000)") {
  std::mt19937 random(15);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Recorded system(10000);
  system.set_acceleration({0, -9.8, 0});
  Model model;
  std::uint64_t next_id = 0;
  const auto spawn = [&] {
    const Vector3<double> p{unit(random), unit(random), unit(random)};
    const Vector3<double> v{unit(random) - 0.5, unit(random) * 10, unit(random) - 0.5};
    const double life = 0.05 + unit(random) * 2;
    const std::size_t i = system.spawn(p, v, next_id);
    system.set_lifetime(i, life);
    model.add(next_id, p, v, life);
    ++next_id;
  };
  for (int n = 0; n < 10000; ++n) spawn();
  REQUIRE(same_as_model(system, model));
  std::size_t expired_total = 0;
  for (int frame = 0; frame < 120; ++frame) {
    for (int n = 0; n < 60; ++n) spawn();
    for (int n = 0; n < 20 && system.size() > 0; ++n) {  // random kills by index
      const std::size_t i = random() % system.size();
      system.kill(i);
      model.remove(i);
    }
    // kill_if on a property of the particle's own identity (every 37th spawn, at frame 7k).
    if (frame % 7 == 0) {
      const auto doomed = [&](std::uint64_t id) { return (id + std::uint64_t(frame)) % 37 == 0; };
      const std::size_t killed =
          system.kill_if([&](std::size_t i) { return doomed(system.column<SpawnTag>(i)); });
      const std::size_t before = model.spawn.size();
      model.remove_if([&](std::size_t i) { return doomed(model.spawn[i]); });
      CHECK(killed == before - model.spawn.size());
    }
    const std::size_t before = system.size();
    system.step(1.0 / 60);
    model.step(1.0 / 60);
    expired_total += before - system.size();
    REQUIRE(same_as_model(system, model));
  }
  CHECK(expired_total > 1000);  // the expiry path was really exercised
  // The identities are the ones the model holds, each once.
  std::set<std::uint64_t> ids(system.column<SpawnTag>().begin(), system.column<SpawnTag>().end());
  CHECK(ids.size() == system.size());
}

TEST_CASE("user columns: given at spawn, T{} otherwise, written by span and index, copied") {
  using Painted =
      ParticleSystem<float, damping::None, position::Euler, features::Column<ColourTag, Colour>,
                     features::Column<SpawnTag, int>>;
  static_assert(Painted::storage_bytes_per_particle == 24 + 4 + 4);
  static_assert(pointmass::detail::SystemAccess::Layout<Painted>::array_count == 8);
  Painted system;
  const std::size_t red = system.spawn({1, 0, 0}, {}, Colour{255, 0, 0, 255}, 7);
  const std::size_t plain = system.spawn({2, 0, 0}, {});
  CHECK(system.column<ColourTag>(red).r == 255);
  CHECK(system.column<SpawnTag>(red) == 7);
  CHECK(system.column<ColourTag>(plain).r == 0);
  CHECK(system.column<SpawnTag>(plain) == 0);
  system.column<SpawnTag>()[plain] = 9;
  system.set_column<ColourTag>(plain, Colour{0, 0, 255, 255});
  // Growth and copies keep them.
  for (int n = 0; n < 100; ++n) system.spawn({}, {}, Colour{1, 2, 3, 4}, 100 + n);
  const Painted copy = system;
  CHECK(copy.column<SpawnTag>(plain) == 9);
  CHECK(copy.column<ColourTag>(plain).b == 255);
  CHECK(copy.column<SpawnTag>(2) == 100);  // the 100 spawned after them: 100 .. 199
  CHECK(copy.column<SpawnTag>(101) == 199);
  system.kill(red);  // the last (spawn 199) moves into red's index
  CHECK(system.column<SpawnTag>(red) == 199);
  CHECK(system.column<ColourTag>(red).a == 4);
}

namespace {
struct FuseTag {};
// Trivially copyable, with a default constructor that throws while `refuse` is set (as one
// that allocates, or checks a global, may).
bool refuse = false;
struct Fuse {
  Fuse() : seconds(1.5f) {
    if (refuse) throw std::runtime_error("no default fuse");
  }
  explicit Fuse(float s) : seconds(s) {}
  float seconds;
};
static_assert(std::is_trivially_copyable_v<Fuse>);
}  // namespace

TEST_CASE("spawn is all or nothing when a user column's default constructor throws") {
  using Shells = ParticleSystem<float, damping::None, position::Euler, features::Handles,
                                features::Column<FuseTag, Fuse>>;
  Shells system;
  system.spawn({1, 0, 0}, {});
  const Shells::Handle first = system.handle(0);
  const Shells before = system;
  refuse = true;
  CHECK_THROWS_AS(system.spawn({2, 0, 0}, {}), std::runtime_error);
  CHECK(system.size() == 1);  // no half-made particle
  CHECK(system.position(0) == before.position(0));
  // The failed spawn took no handle slot: the next particle takes slot 1. Given its value, it
  // makes no T{}, so it spawns while the default constructor still throws.
  const std::size_t given = system.spawn({3, 0, 0}, {}, Fuse(4.0f));  // no T{} made: no throw
  refuse = false;
  REQUIRE(given == 1);
  CHECK(system.column<FuseTag>(1).seconds == 4.0f);
  CHECK(system.find(first) == std::optional<std::size_t>(0));
  CHECK(system.handle(1).slot == 1);
  CHECK(system.column<FuseTag>(0).seconds == 1.5f);
}
