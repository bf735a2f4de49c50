// SPDX-License-Identifier: BSL-1.0
// The names of 0.1 that 0.2 replaced (system/deprecated.hpp) still do what their
// replacements do, for the one minor version they are kept: each is compared with its
// replacement on the same system. (That using one warns is tests/compile-fail's
// system_deprecated_name.)
#include <doctest/doctest.h>

#include <cstddef>
#include <utility>
#include <vector>

#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif

namespace {
using namespace pointmass;
using pointmass::test::random_vector;
using pointmass::test::same_bits;

using Game = ParticleSystem<float, damping::PerSecond, position::Euler, features::Lifetime,
                            features::PerParticleDamping, features::ForceAccumulator,
                            features::Interpolation, features::Handles>;

Game scene() {
  std::mt19937 engine(7);
  Game system;
  for (int i = 0; i < 40; ++i) {
    const std::size_t k = system.spawn(random_vector(engine, 10.0f), random_vector(engine, 5.0f));
    system.set_damping(k, 0.5f);
    system.set_lifetime(k, 0.1f * static_cast<float>(i % 7 + 1));
  }
  return system;
}
}  // namespace

TEST_CASE("the traits of 0.1 say what has<Feature> says") {
  static_assert(Game::has_lifetime == Game::has<features::Lifetime>);
  static_assert(Game::has_forces == Game::has<features::ForceAccumulator>);
  static_assert(Game::has_handles == Game::has<features::Handles>);
  static_assert(Game::has_interpolation == Game::has<features::Interpolation>);
  static_assert(Game::per_particle_damping == Game::has<features::PerParticleDamping>);
  static_assert(!ParticleSystem<float>::per_particle_acceleration);
  static_assert(ParticleSystem<float>::array_count == 6);
  static_assert(std::is_same_v<Game::Arrays, Game::StepView::Arrays>);
  static_assert(std::is_same_v<Game::StepParameters, Game::StepView::Parameters>);
  CHECK(Game::expired(1.0f, 1.0f));
  CHECK_FALSE(Game::expired(2.0f, real_infinity<float>));
}

TEST_CASE("the named spans of 0.1 are the columns") {
  Game system = scene();
  CHECK(system.position_x().data() == system.column<Column::position_x>().data());
  CHECK(system.position_y().data() == system.column<Column::position_y>().data());
  CHECK(system.position_z().data() == system.column<Column::position_z>().data());
  CHECK(system.velocity_x().data() == system.column<Column::velocity_x>().data());
  CHECK(system.velocity_y().data() == system.column<Column::velocity_y>().data());
  CHECK(system.velocity_z().data() == system.column<Column::velocity_z>().data());
  CHECK(std::as_const(system).position_x().size() == system.size());
  CHECK(system.arrays().position_x == system.column<Column::position_x>().data());
  std::vector<Vector3<float>> old_way(system.size()), new_way(system.size());
  const Vector3<float> camera{1.0f, 2.0f, 3.0f};
  system.positions_relative_to(camera, old_way);
  system.copy_positions(std::span(new_way), camera);
  CHECK(old_way == new_way);
}

TEST_CASE("the loop of one's own of 0.1 steps as step does") {
  Game stepped = scene();
  Game own = stepped;
  Game own_with_callback = stepped;
  std::size_t expired = 0;
  for (int step = 0; step < 8; ++step) {
    stepped.step(0.05f);
    for (Game* system : {&own, &own_with_callback}) {
      REQUIRE(system->begin_step(0.05f));
      const Game::StepParameters parameters = system->step_parameters(0.05f);
      Game::step_range(system->arrays(), 0, system->size() / 2, parameters);
      for (std::size_t i = system->size() / 2; i < system->size(); ++i) {
        Game::step_particle(system->arrays(), i, parameters);
      }
    }
    own.finish_step();
    own_with_callback.finish_step([&](std::size_t) { ++expired; });
    REQUIRE(own.size() == stepped.size());
    REQUIRE(own_with_callback.size() == stepped.size());
    for (std::size_t i = 0; i < stepped.size(); ++i) {
      REQUIRE(same_bits(own.position(i), stepped.position(i)));
      REQUIRE(same_bits(own_with_callback.velocity(i), stepped.velocity(i)));
    }
  }
  CHECK(expired == 40 - stepped.size());
  own.arrays_changed();  // says the arrays were written from outside: the next step is the same
  own.step(0.05f);
  stepped.step(0.05f);
  CHECK(same_bits(own.position(0), stepped.position(0)));
}

TEST_CASE("position::Kinematic and StiffSpring::advance of 0.1 are their new names") {
  static_assert(std::is_same_v<position::Kinematic, position::ConstantAcceleration>);
  Particle<double> by_integrate;
  by_integrate.set_position({1.0, 0.0, 0.0});
  by_integrate.set_velocity({0.0, 2.0, 0.0});
  Particle<double> by_advance = by_integrate;
  const forces::StiffSpring<double> spring({0.0, 0.0, 0.0}, 50.0, 0.5);
  spring.integrate(by_integrate, 0.1);
  spring.advance(by_advance, 0.1);
  CHECK(same_bits(by_integrate.position(), by_advance.position()));
  CHECK(same_bits(by_integrate.velocity(), by_advance.velocity()));
  CHECK_FALSE(same_bits(by_integrate.position(), Vector3<double>{1.0, 0.0, 0.0}));
}
