// SPDX-License-Identifier: BSL-1.0
// gravity.hpp: gravity() and Millington's values of g, an acceleration the same for any mass.
#include <doctest/doctest.h>

#include <pointmass/gravity.hpp>
#include <pointmass/particle.hpp>

using namespace pointmass;

TEST_CASE_TEMPLATE("gravity helpers", R, float, double) {
  CHECK(gravity<R>() == Vector3<R>{R(0), R(-9.807), R(0)});
  CHECK(gravity(shooter_gravity<R>) == Vector3<R>{R(0), R(-15), R(0)});
  CHECK(gravity(driving_gravity<R>) == Vector3<R>{R(0), R(-20), R(0)});
  CHECK(gravity(R(3.7)) == Vector3<R>{R(0), R(-3.7), R(0)});
  // f = m g gives the same acceleration for any mass.
  for (const R mass : {R(0.1), R(2), R(200)}) {
    Particle<R, damping::None, position::ConstantAcceleration> p;
    p.set_mass(mass);
    p.set_acceleration(gravity<R>());
    p.integrate(R(1));
    CHECK(p.velocity().y == R(-9.807));
  }
}
