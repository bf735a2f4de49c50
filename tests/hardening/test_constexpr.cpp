// SPDX-License-Identifier: BSL-1.0
// A particle stepped at compile time. damping::None and damping::PerFrame call no maths
// function, so a whole trajectory is a constant expression with every position policy
// (position::Exact too, paired with None: its series are plain arithmetic). PerSecond and
// Exact too, damping value and all: ln d, taken when it is set, and d^t are the library's own
// logarithm and exponential, constexpr. AccelerateThenDamp calls the C library's pow, never
// constexpr.
//
// The static_asserts check physics, not recorded numbers: with dyadic inputs (powers of two)
// every operation is exact in float and in double, so the discrete scheme's closed forms hold
// with ==. The runtime test checks that the compile-time trajectory and the same one computed
// at run time agree bit for bit, with inputs that round.
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <limits>

#include <pointmass/particle.hpp>

namespace {

using namespace pointmass;

/// Ballistic shot: n steps of t from p0 with v0 under a; returns the final particle.
template <class R, class D, class P>
constexpr Particle<R, D, P> shot(Vector3<R> p0, Vector3<R> v0, Vector3<R> a, R damping, R t,
                                 int n) {
  Particle<R, D, P> particle;
  particle.set_position(p0);
  particle.set_velocity(v0);
  particle.set_acceleration(a);
  particle.set_mass(R(2));
  if constexpr (Particle<R, D, P>::stores_damping) particle.set_damping(damping);
  for (int k = 0; k < n; ++k) {
    particle.add_force({R(0), R(1), R(0)});  // 1 N on 2 kg: a further 0.5 m/s^2 up
    particle.integrate(t);
  }
  return particle;
}

template <class R>
constexpr Vector3<R> origin{R(0), R(4), R(0)};
template <class R>
constexpr Vector3<R> launch{R(8), R(16), R(-2)};
template <class R>
constexpr Vector3<R> gravity{R(0), R(-16.5), R(0)};  // -16 once the 0.5 up is added

// None + ConstantAcceleration is exact for constant acceleration: after 64 steps of 1/64 s (T = 1 s),
// p = p0 + v0 T + a T^2 / 2 and v = v0 + a T, exactly.
template <class R>
constexpr bool kinematic_is_exact() {
  const auto p = shot<R, damping::None, position::ConstantAcceleration>(
      origin<R>, launch<R>, gravity<R>, R(1), R(1) / R(64), 64);
  return p.position() == Vector3<R>{R(8), R(4 + 16 - 8), R(-2)} &&
         p.velocity() == Vector3<R>{R(8), R(16 - 16), R(-2)};
}
static_assert(kinematic_is_exact<float>());
static_assert(kinematic_is_exact<double>());

// position::Exact with damping::None is the same closed form.
template <class R>
constexpr bool exact_without_damping_is_exact() {
  const auto p = shot<R, damping::None, position::Exact>(origin<R>, launch<R>, gravity<R>, R(1),
                                                         R(1) / R(64), 64);
  return p.position() == Vector3<R>{R(8), R(12), R(-2)} && p.velocity().y == R(0);
}
static_assert(exact_without_damping_is_exact<float>());
static_assert(exact_without_damping_is_exact<double>());

// None + Euler: p_n = p0 + v0 n t + a t^2 n (n - 1) / 2 (the velocity lags a step).
template <class R>
constexpr bool euler_lags_a_step() {
  const auto p = shot<R, damping::None, position::Euler>(origin<R>, launch<R>, gravity<R>, R(1),
                                                         R(1) / R(64), 64);
  constexpr R t = R(1) / R(64);
  return p.position().y == R(4) + R(16) - R(16) * t * t * R(64 * 63) / R(2);
}
static_assert(euler_lags_a_step<float>());
static_assert(euler_lags_a_step<double>());

// PerFrame, no acceleration (gravity cancelled by the force): v_n = v0 d^n; SemiImplicit
// moves by v_k t for k = 1..n, a geometric sum: p_n = p0 + v0 t d (1 - d^n) / (1 - d).
template <class R>
constexpr bool per_frame_is_geometric() {
  const auto p = shot<R, damping::PerFrame, position::SemiImplicit>(
      origin<R>, launch<R>, Vector3<R>{R(0), R(-0.5), R(0)}, R(0.5), R(0.25), 10);
  const R d_n = R(1) / R(1024);
  return p.velocity() == launch<R> * d_n &&
         p.position() == origin<R> + launch<R> * (R(0.25) * R(0.5) * (R(1) - d_n) / R(0.5));
}
static_assert(per_frame_is_geometric<float>());
static_assert(per_frame_is_geometric<double>());

// An immovable particle (mass set to infinity) does not move, at compile time too.
template <class R>
constexpr bool immovable_stays() {
  Particle<R, damping::PerFrame, position::ConstantAcceleration> p;
  p.set_position(origin<R>);
  p.set_velocity(launch<R>);
  p.set_mass(std::numeric_limits<R>::infinity());
  p.add_force({R(100), R(0), R(0)});
  p.integrate(R(0.5));
  return p.position() == origin<R> && p.force_accumulator() == Vector3<R>{};
}
static_assert(immovable_stays<float>());
static_assert(immovable_stays<double>());

// PerSecond and Exact step at compile time too: d^t is the library's own exponential
// (detail/exponential.hpp), constexpr. With the default damping, d = 1, a particle follows
// None's trajectory, bit for bit, through the whole exponential (e^0 is computed, not
// skipped).
template <class R, class D, class P>
constexpr bool default_damping_steps_as_none() {
  auto start = [](auto particle) {
    particle.set_position(origin<R>);
    particle.set_velocity(launch<R>);
    particle.set_acceleration(gravity<R>);
    particle.set_mass(R(2));
    return particle;
  };
  auto damped = start(Particle<R, D, P>{});
  auto undamped = start(Particle<R, damping::None, P>{});
  for (int k = 0; k < 64; ++k) {
    damped.add_force({R(0), R(1), R(0)});
    undamped.add_force({R(0), R(1), R(0)});
    damped.integrate(R(1) / R(64));
    undamped.integrate(R(1) / R(64));
  }
  return damped.position() == undamped.position() && damped.velocity() == undamped.velocity();
}
static_assert(
    default_damping_steps_as_none<float, damping::PerSecond, position::ConstantAcceleration>());
static_assert(default_damping_steps_as_none<double, damping::PerSecond, position::Euler>());
static_assert(default_damping_steps_as_none<float, damping::PerSecond, position::SemiImplicit>());
static_assert(default_damping_steps_as_none<float, damping::Exact, position::Exact>());
static_assert(default_damping_steps_as_none<double, damping::Exact, position::Exact>());

// And with a damping value set at compile time (its logarithm is the library's own,
// detail::split_log): d = 1/4 over 1/2 s keeps d^t = 1/2 of the velocity, and d = 1/2 over
// 2 s a quarter, exactly (the exponential rounds to those powers of two).
template <class R, class D, class P>
constexpr Vector3<R> velocity_after_one_step(R damping, R t) {
  Particle<R, D, P> particle;
  particle.set_velocity({R(8), R(4), R(2)});
  particle.set_damping(damping);
  particle.integrate(t);
  return particle.velocity();
}
static_assert(velocity_after_one_step<float, damping::PerSecond, position::Euler>(0.25f, 0.5f) ==
              Vector3<float>{4.0f, 2.0f, 1.0f});
static_assert(velocity_after_one_step<double, damping::PerSecond, position::ConstantAcceleration>(
                  0.25, 0.5) == Vector3<double>{4.0, 2.0, 1.0});
static_assert(velocity_after_one_step<double, damping::PerSecond, position::Euler>(0.5, 2.0) ==
              Vector3<double>{2.0, 1.0, 0.5});
static_assert(velocity_after_one_step<float, damping::Exact, position::Exact>(0.25f, 0.5f) ==
              Vector3<float>{4.0f, 2.0f, 1.0f});
static_assert(velocity_after_one_step<double, damping::Exact, position::Exact>(0.25, 0.5) ==
              Vector3<double>{4.0, 2.0, 1.0});

/// Damping values whose logarithms the compile-time and run-time test compares.
template <class R>
inline constexpr R log_inputs[] = {
    R(0.97), R(0.5), R(1e-3), R(0.999999), R(0.70710677), std::numeric_limits<R>::denorm_min()};
template <class R>
inline constexpr auto compile_time_logs = [] {
  std::array<detail::SplitLog<R>, std::size(log_inputs<R>)> logs{};
  for (std::size_t i = 0; i < logs.size(); ++i) logs[i] = detail::split_log(log_inputs<R>[i]);
  return logs;
}();

template <class R, class D, class P>
constexpr Particle<R, D, P> rounding_shot(R t) {
  return shot<R, D, P>({R(1.1), R(2.3), R(0.7)}, {R(3.3), R(9.1), R(-1.7)},
                       {R(0.3), R(-9.807), R(0.1)}, R(0.97), t, 120);
}

template <class R, class D, class P>
void check_compile_time_equals_run_time() {
  constexpr auto at_compile_time = rounding_shot<R, D, P>(R(1) / R(60));
  volatile R step = R(1) / R(60);  // keeps the run-time trajectory at run time
  const auto at_run_time = rounding_shot<R, D, P>(step);
  CHECK(at_compile_time.position() == at_run_time.position());
  CHECK(at_compile_time.velocity() == at_run_time.velocity());
  // Not trivially equal: the inputs round, so the trajectory is not exact.
  CHECK(at_run_time.position().x != R(0));
}

}  // namespace

TEST_CASE_TEMPLATE(
    "a damping value's logarithm taken at compile time is the run-time one, bit for bit", R, float,
    double) {
  for (std::size_t i = 0; i < std::size(log_inputs<R>); ++i) {
    volatile R d = log_inputs<R>[i];  // keeps the run-time logarithm at run time
    const detail::SplitLog<R> at_run_time = detail::split_log(static_cast<R>(d));
    CAPTURE(log_inputs<R>[i]);
    CHECK(compile_time_logs<R>[i].hi == at_run_time.hi);
    CHECK(compile_time_logs<R>[i].lo == at_run_time.lo);
    CHECK(at_run_time.lo != R(0));  // not trivially equal
  }
}

TEST_CASE_TEMPLATE("a trajectory computed at compile time equals the run-time one, bit for bit", R,
                   float, double) {
  check_compile_time_equals_run_time<R, damping::None, position::Euler>();
  check_compile_time_equals_run_time<R, damping::None, position::ConstantAcceleration>();
  check_compile_time_equals_run_time<R, damping::None, position::SemiImplicit>();
  check_compile_time_equals_run_time<R, damping::None, position::Exact>();
  check_compile_time_equals_run_time<R, damping::PerFrame, position::Euler>();
  check_compile_time_equals_run_time<R, damping::PerFrame, position::ConstantAcceleration>();
  check_compile_time_equals_run_time<R, damping::PerFrame, position::SemiImplicit>();
  // The damping value 0.97 is set in the constant expression too: its logarithm as well.
  check_compile_time_equals_run_time<R, damping::PerSecond, position::Euler>();
  check_compile_time_equals_run_time<R, damping::PerSecond, position::ConstantAcceleration>();
  check_compile_time_equals_run_time<R, damping::PerSecond, position::SemiImplicit>();
  check_compile_time_equals_run_time<R, damping::Exact, position::Exact>();
}
