// SPDX-License-Identifier: BSL-1.0
// FlushDenormals: subnormal results and operands are zero while a guard lives, the previous
// modes come back when it dies (nested guards too) and the exception flags raised meanwhile
// stay, and particles whose velocities have decayed into the subnormal range come to rest, a
// Particle and a ParticleSystem alike.
#include <doctest/doctest.h>

#include <bit>
#include <cfenv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include <pointmass/denormals.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include "ulp.hpp"

using pointmass::FlushDenormals;
using pointmass::test::same_bits;

namespace {

// Volatile operands, so that the compiler cannot fold the operation at compile time (where the
// processor's modes do not apply).
template <class R>
R half_of_smallest_normal() {
  volatile R smallest = std::numeric_limits<R>::min();
  volatile R half = R(0.5);
  return smallest * half;  // subnormal, unless flushed to zero
}
template <class R>
R scaled_smallest_subnormal() {
  volatile R tiny = std::numeric_limits<R>::denorm_min();
  volatile R scale = R(1u << 30);
  return tiny * scale;  // a normal result of a subnormal operand, unless that reads as zero
}

/// The bits of x. A comparison would read a subnormal as zero under denormals-are-zero alone;
/// the bits tell a result flushed to zero from a subnormal one.
template <class R>
auto bits(R x) {
  using Bits = std::conditional_t<sizeof(R) == 4, std::uint32_t, std::uint64_t>;
  return std::bit_cast<Bits>(x);
}

}  // namespace

TEST_CASE_TEMPLATE("FlushDenormals: subnormal results and operands are zero while it lives", R,
                   float, double) {
  if (!FlushDenormals::supported) {
    CHECK_FALSE(FlushDenormals::active());
    return;
  }
  REQUIRE_FALSE(FlushDenormals::active());  // the default modes: gradual underflow
  const R subnormal = half_of_smallest_normal<R>();
  CHECK(bits(subnormal) == bits(std::numeric_limits<R>::min() / R(2)));
  CHECK(scaled_smallest_subnormal<R>() == std::numeric_limits<R>::denorm_min() * R(1u << 30));
  {
    FlushDenormals flush;
    CHECK(FlushDenormals::active());
    CHECK(bits(half_of_smallest_normal<R>()) == bits(R(0)));    // flush to zero: the result
    CHECK(bits(-half_of_smallest_normal<R>()) == bits(-R(0)));  // ... keeping its sign
    CHECK(bits(scaled_smallest_subnormal<R>()) == bits(R(0)));  // denormals are zero: operands
  }
  CHECK_FALSE(FlushDenormals::active());
  CHECK(bits(half_of_smallest_normal<R>()) == bits(subnormal));  // the previous modes are back
}

TEST_CASE("FlushDenormals: a nested guard restores the modes the outer one set" *
          doctest::skip(!FlushDenormals::supported)) {
  if (!FlushDenormals::supported) return;  // (only run with --no-skip)
  REQUIRE_FALSE(FlushDenormals::active());
  {
    FlushDenormals outer;
    {
      FlushDenormals inner;
      CHECK(FlushDenormals::active());
    }
    CHECK(FlushDenormals::active());  // still the outer guard's
    CHECK(bits(half_of_smallest_normal<float>()) == 0u);
  }
  CHECK_FALSE(FlushDenormals::active());
}

TEST_CASE("FlushDenormals: exception flags raised while it lives stay raised after" *
          doctest::skip(!FlushDenormals::supported)) {
  if (!FlushDenormals::supported) return;  // (only run with --no-skip)
  std::feclearexcept(FE_ALL_EXCEPT);
  {
    FlushDenormals flush;
    volatile float one = 1.0f;
    volatile float three = 3.0f;
    volatile float third = one / three;  // inexact, raised by a vector unit's division
    static_cast<void>(third);
    REQUIRE(std::fetestexcept(FE_INEXACT) != 0);
  }
  CHECK(std::fetestexcept(FE_INEXACT) != 0);  // the guard restores its modes, nothing else
  std::feclearexcept(FE_ALL_EXCEPT);
}

TEST_CASE_TEMPLATE(
    "FlushDenormals: damped velocities in the subnormal range come to rest, a Particle and a "
    "ParticleSystem alike" *
        doctest::skip(!FlushDenormals::supported),
    R, float, double) {
  if (!FlushDenormals::supported) return;  // (only run with --no-skip)
  using Vector = pointmass::Vector3<R>;
  const R smallest = std::numeric_limits<R>::min();
  // Subnormal velocity components, and one just above the smallest normal number that one
  // step of damping takes below it.
  const std::vector<Vector> velocities{
      {smallest / R(4), -smallest / R(1024), R(0)},
      {smallest * R(1.0001), R(3), -std::numeric_limits<R>::denorm_min()},
  };
  const Vector start{R(1), R(2), R(3)};
  const R t = R(1) / R(60);
  const R damping = R(0.9);  // per second: a step keeps 0.9^(1/60) of a velocity

  const auto step_both = [&](std::vector<pointmass::Particle<R>>& particles,
                             pointmass::ParticleSystem<R>& system) {
    for (const Vector& v : velocities) {
      pointmass::Particle<R> particle;
      particle.set_position(start);
      particle.set_velocity(v);
      particle.set_damping(damping);
      particle.integrate(t);
      particles.push_back(particle);
      system.spawn(start, v);
    }
    system.set_damping(damping);
    system.step(t);
  };

  // Gradual underflow (the default): the velocities stay subnormal, and non-zero.
  std::vector<pointmass::Particle<R>> gradual;
  pointmass::ParticleSystem<R> gradual_system;
  step_both(gradual, gradual_system);
  CHECK(std::fpclassify(gradual[0].velocity().x) == FP_SUBNORMAL);
  CHECK(std::fpclassify(gradual[1].velocity().x) == FP_SUBNORMAL);

  std::vector<pointmass::Particle<R>> flushed;
  pointmass::ParticleSystem<R> flushed_system;
  {
    FlushDenormals flush;
    step_both(flushed, flushed_system);
  }
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    CAPTURE(i);
    const Vector v = flushed[i].velocity();
    CHECK(bits(std::abs(v.x)) == bits(R(0)));  // +0 or -0, by the signs' arithmetic
    CHECK(bits(std::abs(v.z)) == bits(R(0)));
    if (i == 0) CHECK(bits(std::abs(v.y)) == bits(R(0)));
    if (i == 1) CHECK(bits(v.y) == bits(gradual[1].velocity().y));  // normal: the same bits
    CHECK(same_bits(flushed[i].position(), gradual[i].position()));
    CHECK(same_bits(flushed_system.position(i), flushed[i].position()));
    CHECK(same_bits(flushed_system.velocity(i), v));
    CHECK(same_bits(gradual_system.velocity(i), gradual[i].velocity()));
  }
}

namespace {
// A step of a subnormal length under FlushDenormals, which reads it as zero: a Particle and a
// ParticleSystem of the pair D, P both leave every particle as it was.
template <class R, class D, class P>
void subnormal_step_changes_nothing() {
  using Vector = pointmass::Vector3<R>;
  volatile R tiny = std::numeric_limits<R>::min();
  const R subnormal = tiny / R(1024);  // computed before the guard: a subnormal
  pointmass::Particle<R, D, P> particle;
  pointmass::ParticleSystem<R, D, P> system;
  particle.set_velocity(Vector{R(1), R(2), R(3)});
  particle.set_acceleration(Vector{R(0), R(-10), R(0)});
  system.set_acceleration(Vector{R(0), R(-10), R(0)});
  if constexpr (pointmass::Particle<R, D, P>::stores_damping) {
    particle.set_damping(R(0.5));
    system.set_damping(R(0.5));
  }
  system.spawn(particle.position(), particle.velocity());
  {
    FlushDenormals flush;
    particle.integrate(subnormal);
    particle.integrate(subnormal);
    system.step(subnormal);
    system.step(subnormal);
  }
  CHECK(same_bits(particle.velocity(), Vector{R(1), R(2), R(3)}));
  CHECK(same_bits(particle.position(), Vector{}));
  CHECK(same_bits(system.velocity(0), particle.velocity()));
  CHECK(same_bits(system.position(0), particle.position()));
}
}  // namespace

TEST_CASE_TEMPLATE(
    "FlushDenormals: a step of subnormal length changes nothing, in a Particle as in a "
    "ParticleSystem, for every policy pair" *
        doctest::skip(!FlushDenormals::supported),
    R, float, double) {
  if (!FlushDenormals::supported) return;  // (only run with --no-skip)
  namespace damping = pointmass::damping;
  namespace position = pointmass::position;
  subnormal_step_changes_nothing<R, damping::None, position::Euler>();
  subnormal_step_changes_nothing<R, damping::PerFrame, position::Euler>();
  subnormal_step_changes_nothing<R, damping::PerSecond, position::Euler>();
  subnormal_step_changes_nothing<R, damping::AccelerateThenDamp, position::Euler>();
  subnormal_step_changes_nothing<R, damping::PerSecond, position::SemiImplicit>();
  subnormal_step_changes_nothing<R, damping::PerFrame, position::ConstantAcceleration>();
  subnormal_step_changes_nothing<R, damping::Exact, position::Exact>();
}
