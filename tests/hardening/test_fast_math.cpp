// SPDX-License-Identifier: BSL-1.0
// Built with -ffast-math (which implies -ffinite-math-only): the compilers then fold
// isnan(x) and isinf(x) to false, so validation that used them accepted NaN silently. The
// library tells NaN and infinity by bit pattern, so every check below still rejects.
#include <doctest/doctest.h>

#include <limits>
#include <stdexcept>

#include <pointmass/pointmass.hpp>

using namespace pointmass;

#if !defined(__FINITE_MATH_ONLY__) || !__FINITE_MATH_ONLY__
#error "test_fast_math.cpp must be compiled with -ffast-math"
#endif

namespace {

// A NaN and an infinity the optimiser cannot see through (read from volatile storage).
template <class R>
R opaque(R value) {
  volatile R stored = value;
  return stored;
}

}  // namespace

TEST_CASE_TEMPLATE("validation holds under -ffast-math", R, float, double) {
  const R nan = opaque(std::numeric_limits<R>::quiet_NaN());
  const R inf = opaque(std::numeric_limits<R>::infinity());
  CHECK(real_isnan(nan));
  CHECK_FALSE(real_isfinite(nan));
  CHECK_FALSE(real_isfinite(inf));
  CHECK(real_isfinite(opaque(R(1))));

  Particle<R> particle;
  CHECK_THROWS_AS(particle.set_position({nan, R(0), R(0)}), std::invalid_argument);
  CHECK_THROWS_AS(particle.set_velocity({R(0), inf, R(0)}), std::invalid_argument);
  CHECK_THROWS_AS(particle.set_damping(nan), std::invalid_argument);
  CHECK_THROWS_AS(particle.set_mass(nan), std::invalid_argument);
  CHECK(particle.position() == Vector3<R>{});
  CHECK(particle.damping() == R(1));

  ParticleSystem<R> system;
  CHECK_THROWS_AS(system.spawn({nan, R(0), R(0)}, {}), std::invalid_argument);
  CHECK_THROWS_AS(system.set_damping(nan), std::invalid_argument);
  CHECK(system.size() == 0);
}

TEST_CASE_TEMPLATE("infinite masses and lifetimes hold under -ffast-math", R, float, double) {
  Particle<R> immovable;
  immovable.set_inverse_mass(opaque(R(0)));
  immovable.add_force({R(1), R(0), R(0)});
  immovable.integrate(opaque(R(0.5)));
  CHECK(immovable.position() == Vector3<R>{});
  CHECK_FALSE(immovable.has_finite_mass());
  CHECK_FALSE(real_isfinite(immovable.mass()));

  ParticleSystem<R, damping::None, position::Euler, features::Lifetime> system;
  system.spawn({}, {R(1), R(0), R(0)});
  system.set_lifetime(0, opaque(std::numeric_limits<R>::infinity()));
  for (int frame = 0; frame < 10; ++frame) system.step(opaque(R(1000)));
  CHECK(system.size() == 1);
}
