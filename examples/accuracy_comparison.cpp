// SPDX-License-Identifier: BSL-1.0
// accuracy_comparison — every compile-time variant on the same scenes: how far from the true
// motion it goes, and what a step costs. The README's main command (scripts/demo.sh).
//
// Each variant (precision x damping x position policy) flies the scene at each frame time:
// float and double with every policy pair, and float arithmetic with wide positions
// (Precision<float, double>, "float/double-pos"; Precision<float, Compensated<float>>,
// "float/compensated-pos") with PerSecond + Euler and Exact + Exact. Printed:
//   1. per ballistic shot, the error of every policy combination at 1/30 .. 1/240 s against
//      the continuous model it approximates, and the observed order as the frame time halves
//      (the same tables as docs/results/accuracy.md);
//   2. one row per variant and frame time: the error against the scene's own motion, drag
//      included (the closed form for the ballistic shots, Boost.Odeint for the spring;
//      tests/support/accuracy.hpp), largest over the scene, in metres; the time per
//      particle-step; the time to simulate the scene's whole span with it (time per step
//      times the steps the span takes at that frame time: what a user pays for that error);
//      and whether the row is on the Pareto front of error against that time (no other row
//      simulates the span both faster and more accurately). A variant that ignores the drag
//      is charged for it;
//   3. with --scene far (the ballistic shots launched from (1e6, 1e6 + 1.5, 1e6) m, errors taken
//      relative to the launch frame, against the same reference): per wide pair and frame
//      time, float's error near the origin and each precision's error far from it, and the
//      check that the wide positions keep, far from the origin, the error float has near it
//      (within a factor far_tolerance) while float's own error there is far larger.
// Times are measured here with a steady clock (median of repetitions): rough on a busy
// machine. `--times FILE` takes them instead from a CSV "variant,ns_per_step" (what
// scripts/sweep.sh makes from the Google Benchmark run, for the plot in docs/performance.md).
//
//   accuracy_comparison [--scene ballistic|spring|far] [--frame-times 30,60,120,240]
//                       [--times FILE] [--csv FILE] [--summary-only] [--quick]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy.hpp"

namespace accuracy = pointmass::accuracy;

namespace {

struct Options {
  std::string scene = "ballistic";
  std::vector<double> frame_rates{30, 60, 120, 240};
  std::map<std::string, double> times;  // from --times
  const char* csv_path = nullptr;
  bool summary_only = false;
  int repetitions = 7;
};

struct Row {
  std::string variant;
  double frame_time;
  double error;        // metres
  double ns_per_step;  // per particle-step
  double us_per_span;  // to simulate the scene's span, one particle: ns_per_step x steps
  bool on_front = false;
};

std::vector<accuracy::Scene> scenes_named(const std::string& name) {
  if (name == "spring") return {accuracy::spring(false, 10), accuracy::spring(true, 10)};
  if (name == "far") return accuracy::far_ballistic_scenes();
  return accuracy::ballistic_scenes();
}

/// The scene's span: the longest duration among its scenes, s.
double scenes_span(const std::vector<accuracy::Scene>& scenes) {
  double span = 0;
  for (const auto& s : scenes) span = std::max(span, s.duration);
  return span;
}

/// Median nanoseconds per particle-step of variant (S, D, P) on the scenes at 1/60 s.
template <class S, class D, class P>
double measure_time(const std::vector<accuracy::Scene>& scenes, int repetitions) {
  using R = pointmass::real_of_t<S>;
  const double h = 1.0 / 60;
  const R frame = static_cast<R>(h);
  std::vector<double> samples;
  double sink = 0;
  for (int repetition = 0; repetition < repetitions; ++repetition) {
    long steps_done = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const auto& s : scenes) {
      auto particle = accuracy::make_particle<S, D, P>(s, h);
      const long steps = accuracy::steps_for(s, h);
      for (long n = 0; n < steps; ++n) accuracy::step(particle, s, frame);
      sink += static_cast<double>(particle.position().z);
      steps_done += steps;
    }
    const std::chrono::duration<double, std::nano> elapsed =
        std::chrono::steady_clock::now() - start;
    samples.push_back(elapsed.count() / static_cast<double>(steps_done));
  }
  if (sink == 0.125) std::puts("");  // uses the result, so the runs cannot be dropped
  const auto middle = samples.begin() + static_cast<std::ptrdiff_t>(samples.size() / 2);
  std::nth_element(samples.begin(), middle, samples.end());
  return *middle;
}

/// The largest position error of variant (S, D, P) over the scenes at frame time h, m,
/// against the scene's own motion (with its drag), whatever the variant models: a variant
/// that ignores the drag (damping::None) is charged for it.
template <class S, class D, class P>
double largest_error(const std::vector<accuracy::Scene>& scenes, double h) {
  double error = 0;
  for (const auto& s : scenes) {
    const long steps = accuracy::steps_for(s, h);
    const auto reference =
        accuracy::reference_trajectory<pointmass::damping::PerSecond>(s, h, steps);
    const auto flown = accuracy::simulate<S, D, P>(s, h, steps);
    error = std::max(error, accuracy::global_error(flown, reference).position);
  }
  return error;
}

/// The rows of precision S with the policy pairs for_each names (accuracy::
/// for_each_combination or for_each_wide_combination).
template <class S, class ForEach>
void measure_variants(const Options& options, const std::vector<accuracy::Scene>& scenes,
                      std::vector<Row>& rows, ForEach for_each) {
  for_each([&]<class D, class P>() {
    const std::string variant = accuracy::variant_name<S, D, P>();
    const auto given = options.times.find(variant);
    const double ns = given != options.times.end()
                          ? given->second
                          : measure_time<S, D, P>(scenes, options.repetitions);
    for (const double rate : options.frame_rates) {
      const double h = 1 / rate;
      const double error = largest_error<S, D, P>(scenes, h);
      const double steps = static_cast<double>(std::lround(scenes_span(scenes) / h));
      rows.push_back({variant, h, error, ns, ns * steps / 1000});
    }
  });
}

/// Far from the origin, the wide positions must keep the error float has near it: at most
/// far_tolerance times float's error near the origin (the same float velocities, only the
/// position's roundings differ: float's at 1.5 to a few hundred metres, the wide storage's
/// at 1e6 m)...
constexpr double far_tolerance = 2;
/// ...while float's own error far from the origin, at the finest frame time, is at least
/// far_float_excess times its error near it (so the scene shows what the storage is for).
constexpr double far_float_excess = 10;

/// Prints, per wide pair and frame time, float's error near the origin and each precision's
/// error far from it; returns false when a wide precision exceeds far_tolerance times float's
/// near error, or float far from the origin does not exceed far_float_excess times it at the
/// finest frame time.
bool report_far(const Options& options) {
  const auto near = accuracy::ballistic_scenes();
  const auto far = accuracy::far_ballistic_scenes();
  bool kept = true, float_worse = true;
  double least_excess = std::numeric_limits<double>::infinity();
  const double finest = *std::max_element(options.frame_rates.begin(), options.frame_rates.end());
  std::printf(
      "## far from the origin: the shots from (%.0e, %.0e + 1.5, %.0e) m, errors relative\n"
      "## to the launch frame (m), against float's near the origin\n\n",
      far.front().offset.x, far.front().offset.y, far.front().offset.z);
  std::printf("%-20s %7s %11s %11s %11s %11s %11s  %s\n", "pair", "frame", "float near",
              "float far", "double-pos", "compensated", "double far", "wide / float near");
  accuracy::for_each_wide_combination([&]<class D, class P>() {
    for (const double rate : options.frame_rates) {
      const double h = 1 / rate;
      const double float_near = largest_error<float, D, P>(near, h);
      const double float_far = largest_error<float, D, P>(far, h);
      const double wide = largest_error<accuracy::FloatWithDoublePositions, D, P>(far, h);
      const double pair = largest_error<accuracy::FloatWithCompensatedPositions, D, P>(far, h);
      const double twin = largest_error<double, D, P>(far, h);
      const double ratio = std::max(wide, pair) / float_near;
      const bool row_kept = ratio <= far_tolerance;
      const bool row_worse = rate != finest || float_far >= far_float_excess * float_near;
      if (rate == finest) least_excess = std::min(least_excess, float_far / float_near);
      kept = kept && row_kept;
      float_worse = float_worse && row_worse;
      std::printf("%-20s   1/%-4.0f %11.3e %11.3e %11.3e %11.3e %11.3e  %.3f%s%s\n",
                  accuracy::combination_name<D, P>().c_str(), rate, float_near, float_far, wide,
                  pair, twin, ratio, row_kept ? "" : "  <- NOT KEPT",
                  row_worse ? "" : "  <- float NOT worse far away");
    }
  });
  std::printf(
      "\nfar from the origin, the wide positions %s float's near-origin error (within "
      "a factor %g)\n",
      kept ? "keep" : "do NOT keep", far_tolerance);
  std::printf("float far from the origin: %.0f times its near-origin error at 1/%.0f s (%s %g)\n\n",
              least_excess, finest, float_worse ? "at least" : "NOT at least", far_float_excess);
  return kept && float_worse;
}

void mark_pareto_front(std::vector<Row>& rows) {
  for (auto& row : rows) {
    row.on_front = std::none_of(rows.begin(), rows.end(), [&](const Row& other) {
      return other.us_per_span <= row.us_per_span && other.error <= row.error &&
             (other.us_per_span < row.us_per_span || other.error < row.error);
    });
  }
}

bool read_times(const char* path, std::map<std::string, double>& times) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    const auto comma = line.rfind(',');
    if (comma == std::string::npos || line.rfind("variant,", 0) == 0) continue;
    times[line.substr(0, comma)] = std::strtod(line.c_str() + comma + 1, nullptr);
  }
  return true;
}

int usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s [--scene ballistic|spring|far] [--frame-times 30,60,...] [--times FILE]\n"
               "          [--csv FILE] [--summary-only] [--quick]\n",
               program);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const bool has_value = i + 1 < argc;
    if (argument == "--scene" && has_value) {
      options.scene = argv[++i];
      if (options.scene != "ballistic" && options.scene != "spring" && options.scene != "far") {
        return usage(argv[0]);
      }
    } else if (argument == "--frame-times" && has_value) {
      options.frame_rates.clear();
      std::stringstream list(argv[++i]);
      for (std::string rate; std::getline(list, rate, ',');) {
        const double value = std::strtod(rate.c_str(), nullptr);
        if (!(value > 0)) return usage(argv[0]);
        options.frame_rates.push_back(value);
      }
    } else if (argument == "--times" && has_value) {
      if (!read_times(argv[++i], options.times)) {
        std::fprintf(stderr, "cannot read %s\n", argv[i]);
        return 1;
      }
    } else if (argument == "--csv" && has_value) {
      options.csv_path = argv[++i];
    } else if (argument == "--summary-only") {
      options.summary_only = true;
    } else if (argument == "--quick") {
      options.repetitions = 1;
    } else {
      return usage(argv[0]);
    }
  }
  const auto scenes = scenes_named(options.scene);

  if (!options.summary_only && options.scene == "ballistic") {
    std::puts(
        "pointmass: accuracy of every policy combination on Cyclone's ballistic "
        "shots");
    std::puts("(largest position error in metres over 5 s against the exact solution, double;");
    std::puts(" 'exact' = the step is the model's exact flow, the error is rounding)\n");
    for (const auto& s : scenes) {
      std::printf("## %s: mass %g kg, damping %g per second\n\n", s.name.c_str(), s.mass,
                  s.damping);
      std::fputs(accuracy::error_table(s).c_str(), stdout);
      std::puts("");
    }
  }

  const bool far_kept = options.scene != "far" || report_far(options);

  std::vector<Row> rows;
  const auto every_pair = [](auto&& f) { accuracy::for_each_combination(f); };
  const auto wide_pairs = [](auto&& f) { accuracy::for_each_wide_combination(f); };
  measure_variants<float>(options, scenes, rows, every_pair);
  measure_variants<double>(options, scenes, rows, every_pair);
  measure_variants<accuracy::FloatWithDoublePositions>(options, scenes, rows, wide_pairs);
  measure_variants<accuracy::FloatWithCompensatedPositions>(options, scenes, rows, wide_pairs);
  mark_pareto_front(rows);

  std::printf(
      "## every variant: error (largest over the %s scenes, m), time per particle-step,\n"
      "## and time to simulate the scene's span (%g s) with one particle\n\n",
      options.scene.c_str(), scenes_span(scenes));
  std::printf("%-40s %8s %11s %9s %11s  %s\n", "variant (precision Damping + Position)", "frame",
              "error (m)", "ns/step", "us/span", "front");
  for (const auto& row : rows) {
    std::printf("%-40s   1/%-4.0f %11.3e %9.2f %11.2f  %s\n", row.variant.c_str(),
                1 / row.frame_time, row.error, row.ns_per_step, row.us_per_span,
                row.on_front ? "*" : "");
  }
  std::puts(
      "\n* on the Pareto front: no other variant and frame time simulates the span both\n"
      "  faster and more accurately.");
  std::puts(options.times.empty()
                ? "Times: steady clock, median of repetitions on this machine (rough)."
                : "Times: from the given benchmark results.");
  std::puts("The run-time-against-error plot over 1/15 .. 1/480 s: docs/performance.md.");

  if (options.csv_path != nullptr) {
    std::FILE* csv = std::fopen(options.csv_path, "w");
    if (csv == nullptr) {
      std::fprintf(stderr, "cannot write %s\n", options.csv_path);
      return 1;
    }
    std::fprintf(csv, "scene,variant,frame_time,error_m,ns_per_step,us_per_span,on_front\n");
    for (const auto& row : rows) {
      std::fprintf(csv, "%s,%s,%.17g,%.6e,%.4f,%.4f,%d\n", options.scene.c_str(),
                   row.variant.c_str(), row.frame_time, row.error, row.ns_per_step, row.us_per_span,
                   row.on_front ? 1 : 0);
    }
    std::fclose(csv);
  }
  return far_kept ? 0 : 1;
}
