// SPDX-License-Identifier: BSL-1.0
// Every policy combination, float and double, at 1/30, 1/60, 1/120 and 1/240 s, against the
// continuous model it approximates (closed form without a spring, Odeint with one):
//   * double: the error at each finer step is at most twice the error at 1/30 s scaled by
//     (h / h0)^order, order = the pair's order_v (accuracy::convergence_bound, as Boost.Odeint
//     calibrates its own convergence tests), and each halving's observed order lies in
//     accuracy::order_interval; where the step is the model's exact flow the error is rounding;
//   * float: the error is at most the double error plus the derived rounding term
//     accuracy::float_rounding_bound (the run's rounding carried by the step's own matrix).
#include <cmath>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "accuracy.hpp"
#include "tolerance.hpp"

using namespace pointmass;
using namespace pointmass::accuracy;

namespace {

/// The convergence scenes: free flight, the four shots, and the spring over one period,
/// undamped and damped: the scene's 1 s-period spring, and a softer one (stiffness 1 N/m,
/// period 2 pi s) whose error is in its asymptotic regime at every frame time.
std::vector<Scene> convergence_scenes() {
  std::vector<Scene> scenes{free_flight()};
  for (const auto& shot : ballistic_scenes()) scenes.push_back(shot);
  scenes.push_back(spring(false, 1));
  scenes.push_back(spring(true, 1));
  for (const bool damped : {false, true}) {
    Scene soft = spring(damped, 2 * std::acos(-1.0), 1.0);
    soft.name = "soft " + soft.name;
    scenes.push_back(soft);
  }
  return scenes;
}

/// One combination on one scene at every standard frame time: the errors of the double and
/// float runs, the reference's extent, and the float rounding term.
struct Errors {
  std::vector<double> doubles, floats, rounding;
};
template <class D, class P>
Errors errors_of(const Scene& s) {
  Errors out;
  for (const double h : scenes::standard_frame_times) {
    const long steps = steps_for(s, h);
    const auto ref = reference_trajectory<D>(s, h, steps);
    out.doubles.push_back(global_error(simulate<double, D, P>(s, h, steps), ref).position);
    out.floats.push_back(global_error(simulate<float, D, P>(s, h, steps), ref).position);
    out.rounding.push_back(float_rounding_bound<D, P>(s, extent(ref), h));
  }
  return out;
}

template <class R>
void check_scene(const Scene& s) {
  const auto& frame_times = scenes::standard_frame_times;
  for_each_combination([&]<class D, class P>() {
    const std::string name = combination_name<D, P>();
    INFO("scene: ", s.name, ", combination: ", name,
         ", real: ", std::string(sizeof(R) == 4 ? "float" : "double"));
    const Errors e = errors_of<D, P>(s);
    const bool exact = is_exact_for<D, P>(s);
    constexpr int order = order_v<D, P>;
    for (std::size_t i = 0; i < frame_times.size(); ++i) {
      const double h = frame_times[i];
      INFO("frame time 1/", 1 / h, " s: double error ", e.doubles[i], " m, float error ",
           e.floats[i], " m, float rounding term ", e.rounding[i], " m");
      if constexpr (std::is_same_v<R, float>) {
        CHECK(e.floats[i] <= e.doubles[i] + e.rounding[i]);
      } else if (exact) {
        const auto ref = reference_trajectory<D>(s, h, steps_for(s, h));
        CHECK(e.doubles[i] <= double_rounding_bound(extent(ref), s.duration, h));
      } else if (i > 0) {
        const double bound = convergence_bound(e.doubles[0], frame_times[0], h, order);
        INFO("bound ", bound, " m (order ", order, ")");
        CHECK(e.doubles[i] <= bound);
        const double observed = observed_order(e.doubles[i - 1], e.doubles[i]);
        const OrderInterval allowed =
            order_interval(s, frame_times[i - 1], order, i + 1 == frame_times.size());
        INFO("order between 1/", 1 / frame_times[i - 1], " and 1/", 1 / h, " s: ", observed,
             ", allowed [", allowed.low, ", ", allowed.high, "]");
        CHECK(observed >= allowed.low);
        CHECK(observed <= allowed.high);
      }
    }
  });
}

}  // namespace

TEST_CASE_TEMPLATE("every combination converges to its continuous model at its order", R, float,
                   double) {
  for (const Scene& s : convergence_scenes()) check_scene<R>(s);
}

TEST_CASE("the error bounds are not vacuous on any scene: a run twice as wrong fails") {
  // A bound far above every error would pass a broken integrator too. On every convergence
  // scene, for every combination (the float term: every first-order one):
  //   * double, every frame time: the error is at least a quarter of its convergence bound
  //     (so a run with twice the error of the true method fails at the next halving);
  //   * float, at 1/30 s on every scene and at every frame time on the springs: the rounding
  //     term is at most the double error (half of it on the springs), so a float run with
  //     twice the double error fails. At finer steps without a spring the term, summed over
  //     more steps without cancellation, outgrows the shrinking truncation error.
  const auto& frame_times = scenes::standard_frame_times;
  for (const Scene& s : convergence_scenes()) {
    for_each_combination([&]<class D, class P>() {
      if (is_exact_for<D, P>(s)) return;
      INFO("scene: ", s.name, ", combination: ", combination_name<D, P>());
      const Errors e = errors_of<D, P>(s);
      for (std::size_t i = 0; i < frame_times.size(); ++i) {
        const double h = frame_times[i];
        const double bound = convergence_bound(e.doubles[0], frame_times[0], h, order_v<D, P>);
        INFO("frame time 1/", 1 / h, " s: double error ", e.doubles[i], " m, bound ", bound,
             " m, float rounding term ", e.rounding[i], " m");
        // (At the coarsest step the bound is made from this error itself: nothing to check.)
        if (i > 0) CHECK(e.doubles[i] >= bound / 4);
        // (A second-order step's truncation error falls below float's rounding: its float
        // runs are held by the rounding term alone, in check_scene.)
        if (order_v < D, P >> 1) continue;
        if (s.has_spring()) {
          CHECK(e.rounding[i] <= e.doubles[i] / 2);
        } else if (i == 0) {
          CHECK(e.rounding[i] <= e.doubles[i]);
        }
      }
    });
  }
}

TEST_CASE(
    "per-frame damping calibrated per second is the per-second model, fixed per frame it is not") {
  // d per frame kept fixed: the drag rate ln(d)/h is 8 times stronger at 240 fps than at
  // 30 fps, so the 5 s positions differ by far more than either method's error.
  Scene s = ballistic_scenes()[0];
  const auto end_position = [&](double h) {
    Particle<double, damping::PerFrame, position::Euler> p;
    p.set_velocity(s.start_velocity);
    p.set_damping(s.damping);
    for (long n = 0; n < steps_for(s, h); ++n) p.integrate(h);
    return p.position();
  };
  const double difference = magnitude(end_position(1.0 / 30) - end_position(1.0 / 240));
  // Per-frame damping set per second (d^h): its error against the per-second model at 1/30 s.
  const double h = 1.0 / 30;
  const double calibrated =
      global_error(simulate<double, damping::PerFrame, position::Euler>(s, h, steps_for(s, h)),
                   reference_trajectory<damping::PerFrame>(s, h, steps_for(s, h)))
          .position;
  CHECK(difference > 10 * calibrated);
}
