// SPDX-License-Identifier: BSL-1.0
// Stress tests of numerical stability. Every run happens with the floating-point exceptions
// invalid, divide-by-zero and overflow trapped (fp_traps.hpp): finite, in-range input must
// never make a NaN or an infinity. Results are checked after the guard is gone.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "accuracy.hpp"
#include "fp_traps.hpp"
#include "tolerance.hpp"

using namespace pointmass;
using namespace pointmass::accuracy;
using pointmass::test::TrapFloatingPointExceptions;

namespace {

bool finite(const reference::Sample& x) { return is_finite(x.position) && is_finite(x.velocity); }

/// Runs every combination on scene s at frame time h in R (exceptions trapped); checks all
/// samples are finite and that the combinations exact for the scene match the closed form:
/// double to 1e-12 relative, float to N 8 eps (about 8 rounded operations a step).
template <Real R>
void check_finite_and_exact(const Scene& s, double h) {
  for_each_combination([&]<class D, class P>() {
    INFO(s.name, ", ", combination_name<D, P>(), ", frame time ", h, ", ",
         sizeof(R) == 4 ? "float" : "double");
    const long steps = steps_for(s, h);
    std::vector<reference::Sample> run;
    {
      TrapFloatingPointExceptions trap;
      run = simulate<R, D, P>(s, h, steps);
      CHECK_FALSE(TrapFloatingPointExceptions::raised());
    }
    bool all_finite = true;
    for (const auto& x : run) all_finite = all_finite && finite(x);
    CHECK(all_finite);
    if (!is_exact_for<D, P>(s)) return;
    const double eps = static_cast<double>(std::numeric_limits<R>::epsilon());
    const double tol = std::is_same_v<R, double> ? 1e-12 : 8 * eps * static_cast<double>(steps);
    Scene stored = s;  // the inputs as R holds them
    stored.start_position = widen(cast<R>(s.start_position));
    stored.start_velocity = widen(cast<R>(s.start_velocity));
    stored.gravity = widen(cast<R>(s.gravity));
    stored.damping = static_cast<double>(static_cast<R>(s.damping));
    const double hr = static_cast<double>(static_cast<R>(h));
    const auto exact =
        reference::analytic_ballistic(stored.start_position, stored.start_velocity, stored.gravity,
                                      damping_rate<D>(stored), hr * static_cast<double>(steps));
    const double scale = std::max(magnitude(exact.position), magnitude(s.start_position));
    CHECK(magnitude(run.back().position - exact.position) <= tol * scale);
  });
}

}  // namespace

TEST_CASE_TEMPLATE("huge frame times (1 s, 10 s): finite, and exact where the method is exact", R,
                   float, double) {
  for (Scene s : ballistic_scenes()) {
    s.duration = 10;
    for (const double h : {1.0, 10.0}) check_finite_and_exact<R>(s, h);
  }
}

TEST_CASE_TEMPLATE("huge accelerations (1e6 m/s^2): finite, and exact where the method is exact", R,
                   float, double) {
  for (Scene s : ballistic_scenes()) {
    s.gravity = {0, -1e6, 3e5};
    s.duration = 10;
    check_finite_and_exact<R>(s, 1.0 / 60);
  }
}

TEST_CASE_TEMPLATE("damping 1 is no damping, bit for bit, damping 0 keeps only this step's push", R,
                   float, double) {
  Scene s = ballistic_scenes()[1];  // artillery
  const auto compare_with_none = [&]<class D, class P>() {
    if constexpr (!std::is_same_v<D, damping::None>) {
      INFO(combination_name<D, P>());
      s.damping = 1;
      std::vector<reference::Sample> damped, undamped;
      {
        TrapFloatingPointExceptions trap;
        damped = simulate<R, D, P>(s, 1.0 / 60, 300);
        undamped = simulate<R, damping::None, P>(s, 1.0 / 60, 300);
      }
      CHECK(damped.back().position == undamped.back().position);
      CHECK(damped.back().velocity == undamped.back().velocity);

      s.damping = 0;
      std::vector<reference::Sample> stopped;
      {
        TrapFloatingPointExceptions trap;
        stopped = simulate<R, D, P>(s, 1.0 / 60, 300);
      }
      const Vector3<R> push = cast<R>(s.gravity) * (R(1) / R(60));
      // v1 = v0 d + a t (PerFrame, PerSecond): a t; (v0 + a t) d^t: 0; exact: a t phi1(-inf) = 0.
      // VelocityVerlet damps between its half kicks: the second, a t / 2 on credit, is kept.
      const bool keeps_push =
          std::is_same_v<D, damping::PerFrame> || std::is_same_v<D, damping::PerSecond>;
      for (const auto& x : stopped) CHECK(finite(x));
      if constexpr (pointmass::detail::kicks_v<P>) {
        CHECK(cast<R>(stopped.back().velocity) == push * R(0.5));
      } else {
        CHECK(cast<R>(stopped.back().velocity) == (keeps_push ? push : Vector3<R>{}));
      }
    }
  };
  for_each_combination(compare_with_none);
}

TEST_CASE_TEMPLATE("tiny and huge masses under a force, infinite mass never moves", R, float,
                   double) {
  for (const R mass : {R(1e-6), R(1e9)}) {
    Particle<R, damping::None, position::ConstantAcceleration> p;  // exact for a constant force
    p.set_mass(mass);
    const Vector3<R> force{R(0), R(1), R(-2)};
    {
      TrapFloatingPointExceptions trap;
      for (int n = 0; n < 60; ++n) {
        p.add_force(force);
        p.integrate(R(1) / R(60));
      }
    }
    // After 1 s: v = F/m, p = F/(2m), each within the rounding of 60 steps (4 eps each).
    const R time = R(60) * (R(1) / R(60));
    CHECK(pointmass::test::close(p.velocity(), force * (time / mass), R(240), R(0)));
    CHECK(
        pointmass::test::close(p.position(), force * (time * time / (R(2) * mass)), R(240), R(0)));
  }
  Particle<R> wall;
  wall.set_position({R(1), R(2), R(3)});
  wall.set_velocity({R(4), R(5), R(6)});
  wall.set_inverse_mass(R(0));
  {
    TrapFloatingPointExceptions trap;
    wall.add_force({R(1e30), R(-1e30), R(0)});
    wall.integrate(R(1) / R(60));
    wall.integrate(R(10));
  }
  CHECK(wall.position() == Vector3<R>{R(1), R(2), R(3)});
  CHECK(wall.velocity() == Vector3<R>{R(4), R(5), R(6)});
}

TEST_CASE("float far from the origin (1e6 m): drift after 10^6 steps, measured and bounded") {
  // Free flight at (10, 0, 5) m/s from (1e6, 0, 0) for 10^6 steps of 1/60 s, float against
  // double. Each float step rounds p + v h once: at most half an ulp of the largest |p|
  // (ulp(1.17e6) = 2^-3 m), plus the rounding of h itself moving every step by |v| |dh|:
  //   bound = N (ulp(P) / 2 + |v| |float(h) - h|).
  const long steps = 1'000'000;
  FarFlight flight;
  {
    TrapFloatingPointExceptions trap;
    flight = fly_far_from_origin(steps);
  }
  const double h = flight.h;
  const double drift = magnitude(flight.single - flight.twin);
  const double largest = magnitude(flight.twin);
  const double ulp = std::ldexp(1.0, std::ilogb(largest) - 23);
  const double bound = static_cast<double>(steps) *
                       (ulp / 2 + magnitude(Vector3<double>{10, 0, 5}) *
                                      std::abs(static_cast<double>(static_cast<float>(h)) - h));
  MESSAGE("float drift after 10^6 steps at 1e6 m: ", drift, " m (bound ", bound, " m)");
  CHECK(drift <= bound);
  // The double run itself is exact to its own rounding: N ulp_double(P) / 2.
  CHECK(std::abs(flight.twin.x - (1e6 + 10.0 * h * static_cast<double>(steps))) <=
        static_cast<double>(steps) * std::ldexp(1.0, std::ilogb(largest) - 52));
}

TEST_CASE(
    "springs at their stability limits: semi-implicit bounded below omega h = 2, explicit never") {
  const Scene s = spring(false, 1);
  const double omega = s.angular_frequency();
  const auto energy_ratios = [&]<class P>(double r, long steps) {
    const double h = r / omega;
    auto particle = make_particle<double, damping::None, P>(s, h);
    const double start = energy(s, {particle.position(), particle.velocity()});
    std::vector<double> ratios;
    TrapFloatingPointExceptions trap;
    for (long n = 0; n < steps; ++n) {
      step(particle, s, h);
      ratios.push_back(energy(s, {particle.position(), particle.velocity()}) / start);
      if (ratios.back() > 1e12) break;
    }
    return ratios;
  };
  SUBCASE("semi-implicit at omega h = 1.9 keeps its energy within (1 + r/2) / (1 - r/2)") {
    // It conserves Q = v^2 + w^2 x^2 - h w^2 x v exactly, and |h w^2 x v| <= (r/2)(v^2 + w^2 x^2).
    const double r = 1.9;
    const auto ratios = energy_ratios.template operator()<position::SemiImplicit>(r, 100000);
    REQUIRE(ratios.size() == 100000);
    const double largest = *std::max_element(ratios.begin(), ratios.end());
    CHECK(largest <= (1 + r / 2) / (1 - r / 2) * (1 + 1e-9));
    CHECK(largest > 1);  // it does swing (the modified energy is not the energy)
  }
  SUBCASE("semi-implicit past the limit (omega h = 2.1) grows a million-fold within 100 steps") {
    const auto ratios = energy_ratios.template operator()<position::SemiImplicit>(2.1, 100);
    CHECK(ratios.back() > 1e6);
  }
  SUBCASE("the default explicit form multiplies the energy by exactly 1 + (omega h)^2 a step") {
    const double r = 0.1;
    const auto ratios = energy_ratios.template operator()<position::Euler>(r, 1000);
    for (std::size_t n = 0; n < ratios.size(); n += 100) {
      CHECK(pointmass::test::close(ratios[n], std::pow(1 + r * r, static_cast<double>(n + 1)),
                                   static_cast<double>(16 * (n + 1))));
    }
  }
  SUBCASE("measured limits: semi-implicit 2; explicit forms shrink toward 0 as the run lengthens") {
    double semi = 0, euler_short = 0, euler_long = 0, kinematic = 0;
    {
      TrapFloatingPointExceptions trap;
      semi = stability_limit<damping::None, position::SemiImplicit>(s, 20000);
      euler_short = stability_limit<damping::None, position::Euler>(s, 20000);
      euler_long = stability_limit<damping::None, position::Euler>(s, 80000);
      kinematic = stability_limit<damping::None, position::ConstantAcceleration>(s, 20000);
    }
    MESSAGE("limits in omega h: semi-implicit ", semi, ", explicit ", euler_short, " (2e4 steps) ",
            euler_long, " (8e4 steps), kinematic ", kinematic);
    CHECK(std::abs(semi - 2) <= 1e-3);
    // Bounded over N steps needs (1 + r^2)^(N/4) <= 2, r <= sqrt(4 ln 2 / N): halves when N x4.
    CHECK(euler_short <= std::sqrt(4 * std::log(2.0) / 20000) * 1.01);
    CHECK(euler_long <= 0.55 * euler_short);
    CHECK(kinematic < 0.05);
  }
}

TEST_CASE_TEMPLATE(
    "subnormal velocities after long damping: no NaN, monotone, down to the last ulps", R, float,
    double) {
  for_each_combination([&]<class D, class P>() {
    if constexpr (!std::is_same_v<D, damping::None>) {
      INFO(combination_name<D, P>());
      const R h = R(1) / R(60);
      auto p = Particle<R, D, P>{};
      const R start = std::is_same_v<R, float> ? R(1e-30) : R(1e-300);
      p.set_velocity({start, -start, start});
      p.set_damping(std::is_same_v<D, damping::PerFrame> ? std::pow(R(0.5), h) : R(0.5));
      bool monotone = true, finite_all = true, saw_subnormal = false;
      {
        TrapFloatingPointExceptions trap;
        R previous = start;
        for (int n = 0; n < 6000; ++n) {
          p.integrate(h);
          const R speed = p.velocity().x;
          monotone = monotone && speed <= previous && speed >= R(0);
          finite_all = finite_all && is_finite(p.position()) && is_finite(p.velocity());
          saw_subnormal = saw_subnormal || std::fpclassify(speed) == FP_SUBNORMAL;
          previous = speed;
        }
      }
      CHECK(monotone);
      CHECK(finite_all);
      CHECK(saw_subnormal);
      // v d^h rounds back to v once the step removes less than half an ulp: at m ulps with
      // m (1 - d^h) < 1/2. So the speed stops at most 1/(2 (1 - d^h)) + 1 ulps above zero.
      const double kept = std::pow(0.5, static_cast<double>(h));
      const double last =
          (0.5 / (1 - kept) + 1) * static_cast<double>(std::numeric_limits<R>::denorm_min());
      CHECK(static_cast<double>(p.velocity().x) <= last);
    }
  });
}

TEST_CASE_TEMPLATE("a long run: 10^6 steps of the undamped spring, semi-implicit, energy bounded",
                   R, float, double) {
  // Scene 4. At omega h = 2 pi / 240 the conserved Q bounds the energy within
  // [(1 - r/2)/(1 + r/2), (1 + r/2)/(1 - r/2)] (5% wide). Rounding changes Q by at most 8 u
  // relative a step (u the unit roundoff; four operations on p and v, squared in the energy);
  // the step being symplectic, these changes do not compound but walk at random: after N
  // steps about sqrt(N) 8 u, 4.8e-4 for float. Each precision is held to the band plus ten
  // times its walk (float 4.8e-3, a tenth of the band: a velocity gaining 3 ulps a step fails).
  const Scene s = spring(false, 1);
  const double h = 1.0 / 240, r = s.angular_frequency() * h;
  auto particle = make_particle<R, damping::None, position::SemiImplicit>(s, h);
  const double start = energy(s, {widen(particle.position()), widen(particle.velocity())});
  double low = 1, high = 1;
  {
    TrapFloatingPointExceptions trap;
    for (long n = 0; n < 1'000'000; ++n) {
      step(particle, s, static_cast<R>(h));
      const double ratio =
          energy(s, {widen(particle.position()), widen(particle.velocity())}) / start;
      low = std::min(low, ratio);
      high = std::max(high, ratio);
    }
  }
  MESSAGE("energy ratio over 10^6 steps: [", low, ", ", high, "]");
  const double u = static_cast<double>(std::numeric_limits<R>::epsilon()) / 2;
  const double slack = 10 * std::sqrt(1e6) * 8 * u;
  CHECK(high <= (1 + r / 2) / (1 - r / 2) + slack);
  CHECK(low >= (1 - r / 2) / (1 + r / 2) - slack);
}

TEST_CASE_TEMPLATE("a long run: 10^6 steps of the defaults settle at their terminal velocity", R,
                   float, double) {
  // The fireball rises against per-second damping 0.9: v* = a h / (1 - d^h), the fixed point
  // of v d^h + a h.
  Scene s = ballistic_scenes()[2];
  const double h = 1.0 / 60;
  auto particle = make_particle<R, damping::PerSecond, position::Euler>(s, h);
  {
    TrapFloatingPointExceptions trap;
    for (long n = 0; n < 1'000'000; ++n) particle.integrate(static_cast<R>(h));
  }
  CHECK(is_finite(particle.position()));
  const double terminal = s.gravity.y * h / (1 - std::pow(s.damping, h));
  const double tol = std::is_same_v<R, float> ? 1e-3 : 1e-9;
  CHECK(std::abs(static_cast<double>(particle.velocity().y) - terminal) <= tol * terminal);
}
