// SPDX-License-Identifier: BSL-1.0
// What a game needs of the batch: user columns that follow their particles through every
// swap-remove, the expiry callback and spawning inside it, previous positions and
// interpolation, bursts and the renderer's copy-out; and that none of it costs a
// configuration that does not choose it.
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

#include <pointmass/fixed_step.hpp>  // interpolate
#include <pointmass/gravity.hpp>
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
  std::vector<double> age, lifetime;

  void add(std::uint64_t id, const Vector3<double>& p, const Vector3<double>& v, double life) {
    spawn.push_back(id);
    body.emplace_back();
    body.back().set_position(p);
    body.back().set_velocity(v);
    body.back().set_acceleration({0, -9.8, 0});
    age.push_back(0);
    lifetime.push_back(life);
  }
  void remove(std::size_t i) {
    const std::size_t last = spawn.size() - 1;
    spawn[i] = spawn[last];
    body[i] = body[last];
    age[i] = age[last];
    lifetime[i] = lifetime[last];
    spawn.pop_back();
    body.pop_back();
    age.pop_back();
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
      age[i] += t;
    }
    remove_if([&](std::size_t i) { return age[i] >= lifetime[i]; });
  }
};

bool same_as_model(const Recorded& system, const Model& model) {
  if (system.size() != model.spawn.size()) return false;
  for (std::size_t i = 0; i < system.size(); ++i) {
    if (system.column<SpawnTag>(i) != model.spawn[i]) return false;
    if (!same_bits(system.position(i), model.body[i].position())) return false;
    if (!same_bits(system.velocity(i), model.body[i].velocity())) return false;
    if (!same_bits(system.age(i), model.age[i])) return false;
  }
  return true;
}

}  // namespace

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

TEST_CASE_TEMPLATE("interpolation: alpha 0 is the previous position, 1 the current, bit for bit", R,
                   float, double) {
  // ConstantAcceleration: its last addition (a t^2 / 2) leaves positions off the grid of the previous ones.
  using Drawn = ParticleSystem<R, damping::PerSecond, position::ConstantAcceleration,
                               features::Interpolation>;
  std::mt19937 random(5);
  Drawn system;
  system.set_acceleration(gravity<R>());
  system.set_damping(R(0.9));
  for (int n = 0; n < 100; ++n) {
    system.spawn(test::random_vector<R>(random, R(1000)), test::random_vector<R>(random, R(50)));
  }
  system.spawn({-R(0), R(0), -R(0)}, {});  // signed zeros must come back as they are
  // Large steps that end near 0: previous + (current - previous) rounds away from current.
  for (const R start : {R(1000.3), R(-77.7), R(123456.7)}) {
    system.spawn({start, -start, start},
                 {-start * R(60) * R(0.999987), start * R(60) * R(0.99993), -start * R(59.99)});
  }
  for (int frame = 0; frame < 3; ++frame) {
    std::vector<Vector3<R>> before;
    for (std::size_t i = 0; i < system.size(); ++i) before.push_back(system.position(i));
    system.step(R(1) / R(60));
    std::vector<R> packed(system.size() * 3), interleaved(system.size() * 5, R(-7));
    for (const R alpha : {R(0), R(1)}) {
      system.copy_interpolated_positions(alpha, std::span<R>(packed));
      system.copy_interpolated_positions(alpha, std::span<R>(interleaved).subspan(1), 5);
      for (std::size_t i = 0; i < system.size(); ++i) {
        const Vector3<R> expected = alpha > R(0) ? system.position(i) : before[i];
        CHECK(same_bits(system.previous_position(i), before[i]));
        CHECK(same_bits(system.interpolated_position(i, alpha), expected));
        CHECK(same_bits(Vector3<R>{packed[3 * i], packed[3 * i + 1], packed[3 * i + 2]}, expected));
        CHECK(same_bits(
            Vector3<R>{interleaved[5 * i + 1], interleaved[5 * i + 2], interleaved[5 * i + 3]},
            expected));
        CHECK(interleaved[5 * i] == R(-7));  // the other attributes are left alone
        CHECK(interleaved[5 * i + 4] == R(-7));
      }
    }
    // Half way: between the two, at the midpoint up to rounding.
    for (std::size_t i = 0; i < system.size(); ++i) {
      const Vector3<R> half = system.interpolated_position(i, R(0.5));
      const Vector3<R> mid = (before[i] + system.position(i)) * R(0.5);
      CHECK(magnitude(half - mid) <=
            R(4) * std::numeric_limits<R>::epsilon() * (magnitude(mid) + R(1)));
    }
  }
  // A jump by set_position does not streak: both ends move.
  system.set_position(0, {R(1), R(2), R(3)});
  CHECK(system.interpolated_position(0, R(0.25)) == Vector3<R>{R(1), R(2), R(3)});
  // interpolate(), for a lone Particle's loop.
  const Vector3<R> a{-R(0), R(1), R(2)}, b{R(3), R(4), R(5)};
  CHECK(same_bits(interpolate(a, b, R(0)), a));
  CHECK(same_bits(interpolate(a, b, R(1)), b));
}

TEST_CASE_TEMPLATE(
    "interpolation: alpha is the fraction of the way from the previous position "
    "to the current one",
    R, float, double) {
  // Every number here is exact in binary, so the expected positions are exact: a step of
  // 0.25 s at (4, -8, 2) m/s moves (1, -2, 0.5) m, and a quarter and three quarters of that
  // are exact too. (Alpha 0, 0.5 and 1 cannot tell the two ends apart: a formula with the
  // ends swapped gives the same points there.)
  using Drawn = ParticleSystem<R, damping::None, position::Euler, features::Interpolation>;
  Drawn system;
  system.spawn({R(0), R(8), R(-4)}, {R(4), R(-8), R(2)});
  system.spawn({R(1), R(1), R(1)}, {});  // at rest: every alpha gives where it is
  system.step(R(0.25));
  REQUIRE(system.previous_position(0) == Vector3<R>{R(0), R(8), R(-4)});
  REQUIRE(system.position(0) == Vector3<R>{R(1), R(6), R(-3.5)});
  const Vector3<R> quarter{R(0.25), R(7.5), R(-3.875)};
  const Vector3<R> three_quarters{R(0.75), R(6.5), R(-3.625)};
  const Vector3<R> rest{R(1), R(1), R(1)};
  for (const auto& point : {std::pair{R(0.25), quarter}, std::pair{R(0.75), three_quarters}}) {
    const R alpha = point.first;
    const Vector3<R> expected = point.second;
    CAPTURE(alpha);
    CHECK(system.interpolated_position(0, alpha) == expected);
    CHECK(system.interpolated_position(1, alpha) == rest);
    std::vector<R> packed(6), strided(7, R(-7));
    system.copy_interpolated_positions(alpha, std::span<R>(packed));
    CHECK(Vector3<R>{packed[0], packed[1], packed[2]} == expected);
    CHECK(Vector3<R>{packed[3], packed[4], packed[5]} == rest);
    system.copy_interpolated_positions(alpha, std::span<R>(strided), 4);
    CHECK(Vector3<R>{strided[0], strided[1], strided[2]} == expected);
    CHECK(strided[3] == R(-7));
    CHECK(Vector3<R>{strided[4], strided[5], strided[6]} == rest);
    std::vector<Vector3<R>> vectors(2);
    system.copy_interpolated_positions(alpha, std::span<Vector3<R>>(vectors));
    CHECK(vectors[0] == expected);
    CHECK(vectors[1] == rest);
    // The free interpolate, for a lone Particle's loop.
    CHECK(interpolate(Vector3<R>{R(0), R(8), R(-4)}, Vector3<R>{R(1), R(6), R(-3.5)}, alpha) ==
          expected);
  }
}

TEST_CASE("copy_positions: packed, strided and into vectors with x, y, z") {
  ParticleSystem<double> system;
  for (int n = 0; n < 10; ++n) system.spawn({double(n), n + 0.5, -n - 0.25}, {});
  struct Vertex {
    float x, y, z;
  };
  std::vector<Vertex> vertices(10);
  system.copy_positions(std::span<Vertex>(vertices));
  std::vector<float> strided(9 * 6 + 3, -1.0f);
  system.copy_positions(std::span<float>(strided), 6);
  for (std::size_t i = 0; i < 10; ++i) {
    const Vector3<float> expected{float(i), float(i) + 0.5f, -float(i) - 0.25f};
    CHECK(Vector3<float>{vertices[i].x, vertices[i].y, vertices[i].z} == expected);
    CHECK(Vector3<float>{strided[6 * i], strided[6 * i + 1], strided[6 * i + 2]} == expected);
    if (i < 9) CHECK(strided[6 * i + 3] == -1.0f);
  }
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
