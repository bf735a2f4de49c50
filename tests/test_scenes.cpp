// SPDX-License-Identifier: BSL-1.0
// extras/scenes.hpp: Cyclone's ballistic shots, and launch() setting a particle up for one.
#include <doctest/doctest.h>

#include <pointmass/extras/scenes.hpp>
#include <pointmass/particle.hpp>

using namespace pointmass;

TEST_CASE("the scenes hold Cyclone's shots") {
  const auto& shots = scenes::ballistic_shots<double>;
  REQUIRE(shots.size() == 4);
  CHECK(shots[0].name == "pistol");
  CHECK(shots[1].mass == 200.0);
  CHECK(shots[2].acceleration == Vector3<double>{0, 0.6, 0});
  CHECK(shots[3].velocity == Vector3<double>{0, 0, 100});
  Particle<double> p;
  scenes::launch(p, shots[1]);
  CHECK(p.position() == Vector3<double>{0, 1.5, 0});
  CHECK(p.velocity() == Vector3<double>{0, 30, 40});
  CHECK(p.mass() == 200.0);
  CHECK(p.damping() == 0.99);
}
