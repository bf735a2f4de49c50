// SPDX-License-Identifier: BSL-1.0
// Built with the flags that let a compiler reorder floating-point arithmetic (-ffast-math;
// -fassociative-math -fno-signed-zeros -fno-trapping-math; -freciprocal-math): the results
// that depend on error-free steps hold (real.hpp says how). Reordered, damping 0.5 per second
// keeps all the velocity and a far compensated position stops moving: these checks catch it.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <pointmass/pointmass.hpp>

#include "log_oracle.hpp"
#include "ulp.hpp"

using namespace pointmass;
using pointmass::test::ulp_distance;

namespace {

// A value the optimiser cannot fold (read from volatile storage).
template <class R>
R opaque(R value) {
  volatile R stored = value;
  return stored;
}

// The fraction of the velocity kept after 1 s of 60 Hz steps at damping 0.5 per second.
template <class R, class D>
R particle_kept() {
  Particle<R, D> particle;
  particle.set_velocity({R(1), R(0), R(0)});
  particle.set_damping(opaque(R(0.5)));
  for (int frame = 0; frame < 60; ++frame) particle.integrate(opaque(R(1) / R(60)));
  return particle.velocity().x;
}
template <class R, class D>
R system_kept() {
  ParticleSystem<R, D> system;
  system.set_damping(opaque(R(0.5)));
  for (int i = 0; i < 9; ++i) system.spawn({R(i), R(0), R(0)}, {R(1), R(0), R(0)});
  for (int frame = 0; frame < 60; ++frame) system.step(opaque(R(1) / R(60)));
  return system.velocity(8).x;
}

// Where a compensated position 1e6 m out is after 1 s at 100 m/s (60 Hz steps).
template <class R, class S>
double far_flight() {
  using P = position_value_t<S>;  // double, or long double for a pair of doubles
  Particle<S, damping::None> particle;
  particle.set_position({opaque(P(1e6)), P(0), P(0)});
  particle.set_velocity({opaque(R(100)), R(0), R(0)});
  for (int frame = 0; frame < 60; ++frame) particle.integrate(opaque(R(1) / R(60)));
  return static_cast<double>(particle.position().x) - 1e6;
}
template <class R, class S>
double far_flight_system() {
  using P = position_value_t<S>;
  ParticleSystem<S, damping::None> system;
  for (int i = 0; i < 9; ++i)
    system.spawn({opaque(P(1e6)), P(0), P(0)}, {opaque(R(100)), R(0), R(0)});
  for (int frame = 0; frame < 60; ++frame) system.step(opaque(R(1) / R(60)));
  return static_cast<double>(system.position(8).x) - 1e6;
}

// The bound docs/numerics.md states for d^t, d^t - 1 (d in [1e-3, 1], t in [0, 1] s), e^x
// and e^x - 1, as tests/test_exponential.cpp checks it in an ordinary build.
constexpr long long stated_ulps = 4;

template <class R>
constexpr R tolerance = std::is_same_v<R, float> ? R(1e-5) : R(1e-13);

}  // namespace

TEST_CASE_TEMPLATE("damping 0.5 per second keeps half the velocity over 1 s", R, float, double) {
  CHECK(std::fabs(particle_kept<R, damping::PerSecond>() - R(0.5)) < tolerance<R>);
  CHECK(std::fabs(particle_kept<R, damping::Exact>() - R(0.5)) < tolerance<R>);
  CHECK(std::fabs(system_kept<R, damping::PerSecond>() - R(0.5)) < tolerance<R>);
  CHECK(std::fabs(system_kept<R, damping::Exact>() - R(0.5)) < tolerance<R>);
}

TEST_CASE("a compensated position 1e6 m out moves 100 m in 1 s at 100 m/s") {
  using FloatPair = Precision<float, Compensated<float>>;
  using DoublePair = Precision<double, Compensated<double>>;
  CHECK(std::fabs(far_flight<float, FloatPair>() - 100.0) < 1e-3);
  CHECK(std::fabs(far_flight<double, DoublePair>() - 100.0) < 1e-9);
  CHECK(std::fabs(far_flight_system<float, FloatPair>() - 100.0) < 1e-3);
  CHECK(std::fabs(far_flight_system<double, DoublePair>() - 100.0) < 1e-9);
}

TEST_CASE_TEMPLATE("the exponential keeps its ulp bound", R, float, double) {
  if constexpr (!wider_than_double_v<long double> && std::is_same_v<R, double>) {
    MESSAGE("no oracle wider than double here");
    return;
  }
  long long worst = 0;
  const auto note = [&](long long ulps) { worst = ulps > worst ? ulps : worst; };
  for (int i = 0; i <= 60; ++i) {
    const R d = opaque(static_cast<R>(std::pow(1e-3L, static_cast<long double>(i) / 60)));
    const auto ln_d = detail::split_log(d);
    for (int j = 0; j <= 40; ++j) {
      const R t = opaque(static_cast<R>(static_cast<long double>(j) / 40));
      const long double x = static_cast<long double>(t) * std::log(static_cast<long double>(d));
      note(ulp_distance(detail::pow_unit(ln_d, t), static_cast<R>(std::exp(x))));
      note(ulp_distance(detail::pow_unit_scalar(ln_d, t), static_cast<R>(std::exp(x))));
      note(ulp_distance(detail::exp_unit(ln_d, t).kept_minus_one, static_cast<R>(std::expm1(x))));
    }
  }
  // e^x where it is a normal number: -ffast-math's start-up code flushes subnormals to 0.
  for (int i = -400; i <= 400; ++i) {
    const R x = opaque(static_cast<R>(i) * (sizeof(R) == 4 ? R(0.2113) : R(1.77)));
    const long double lx = static_cast<long double>(x);
    note(ulp_distance(detail::exp(x), static_cast<R>(std::exp(lx))));
    note(ulp_distance(detail::expm1(x), static_cast<R>(std::expm1(lx))));
  }
  // Near 0, where e^x - 1 keeps its relative accuracy by (2^n - 1) + 2^n s.
  for (int i = -200; i <= 200; ++i) {
    const R x = opaque(static_cast<R>(i) * R(0.0037));
    const long double lx = static_cast<long double>(x);
    note(ulp_distance(detail::expm1(x), static_cast<R>(std::expm1(lx))));
  }
#if !defined(__FAST_MATH__)
  // Subnormal results (which -ffast-math flushes to 0), rounded once: (1 + s) 2^m1, then 2^m2.
  for (int i = 0; i <= 200; ++i) {
    const R x = opaque(sizeof(R) == 4 ? R(-87.5) - R(0.08) * static_cast<R>(i)
                                      : R(-708.5) - R(0.18) * static_cast<R>(i));
    note(ulp_distance(detail::exp(x), static_cast<R>(std::exp(static_cast<long double>(x)))));
  }
#endif
  CAPTURE(worst);
  CHECK(worst <= stated_ulps);
}

TEST_CASE("split_log for double is ln d to 2^-72 against correctly rounded values") {
  double worst = 0;
  for (const pointmass::test::LogOracle& oracle : pointmass::test::log_oracle_double) {
    if (oracle.d < std::numeric_limits<double>::min()) continue;  // -ffast-math reads 0
    const auto ln_d = detail::split_log(opaque(oracle.d));
    const double error =
        std::fabs((ln_d.hi - oracle.hi) + (ln_d.lo - oracle.lo)) / std::fabs(oracle.hi);
    worst = error > worst ? error : worst;
  }
  CAPTURE(worst);
  CHECK(worst <= 0x1p-72);
}

TEST_CASE("an offset rounded once to float: a double position at a float midpoint") {
  // 1 + 2^-24 - (-2^-80): the double difference rounds to the midpoint 1 + 2^-24, and its
  // error term (2^-80) says which float is nearer: 1 + 2^-23.
  Particle<Precision<float, double>, damping::None> particle;
  particle.set_position({opaque(1.0 + 0x1p-24), 0.0, 0.0});
  CHECK(particle.position_relative_to({opaque(-0x1p-80), 0.0, 0.0}).x == 1.0f + 0x1p-23f);
}

TEST_CASE("a far compensated position's offset from a camera is exact") {
  // A step of 1e-20 m from 1e6 m: hi stays 1e6, lo holds the step, and hi + lo is no double.
  Particle<Precision<float, Compensated<float>>, damping::None> particle;
  particle.set_position({opaque(1e6), 0.0, 0.0});
  particle.set_velocity({opaque(1e-18f), 0.0f, 0.0f});
  particle.integrate(opaque(0.01f));
  const float step = opaque(1e-18f) * opaque(0.01f);
  CHECK(particle.position_relative_to({opaque(1e6), 0.0, 0.0}).x == step);
}

TEST_CASE("a float age far from zero still grows by each step") {
  // Kahan's count (detail::count_age): reordered, its error term would be 0 and an age of
  // 2^19 s would stop growing at 60 Hz.
  ParticleSystem<float, damping::None, position::Euler, features::Lifetime> system(1);
  system.spawn({}, {});
  system.column<Column::age>()[0] = 0x1p19f;
  const float step = opaque(1.0f / 60.0f);
  for (int n = 0; n < 600; ++n) system.step(step);
  CHECK(double(system.age(0)) - 0x1p19 == doctest::Approx(600.0 * double(step)).epsilon(1e-4));
}
