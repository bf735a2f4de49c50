// accuracy_comparison — every compile-time variant on the same scene: how far from the
// true motion it ends, and what a step costs.
//
// The scene: the reference engine's four ballistic shots (pistol, artillery, fireball,
// laser), 5 s of flight each, at frame times 1/30 .. 1/240 s. Each variant is compared with
// the exact solution of the continuous model it approximates,
//   dv/dt = a + k v,   k = ln d per second (k = ln(d) / frame time for per-frame damping),
// whose closed form is v(t) = v0 e^{kt} + a t phi1(kt), p(t) = p0 + v0 t phi1(kt) +
// a t^2 phi2(kt) with phi1(x) = (e^x - 1) / x and phi2(x) = (e^x - 1 - x) / x^2.
//
// The error is the largest distance, over the four shots, between the final position and
// the exact one, in metres. The time is the median over repetitions of nanoseconds per
// particle-step on this machine (a rough figure: the benchmarks measure it properly). A row
// is on the Pareto front when no other row is both faster and more accurate.
//
//   accuracy_comparison              the table
//   accuracy_comparison --csv FILE   also write it as CSV
//   accuracy_comparison --quick      one timing repetition (for a quick check)
#include <pointmass/pointmass.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace pointmass;

struct Row {
  std::string variant;
  double frame_time;
  double error;        // metres
  double ns_per_step;  // nanoseconds per particle-step
  bool on_front = false;
};

// phi1 and phi2 in long double: a series where x is small, expm1 elsewhere.
long double phi1(long double x) {
  if (std::fabs(x) < 1e-4L) return 1 + x / 2 + x * x / 6 + x * x * x / 24;
  return std::expm1(x) / x;
}
long double phi2(long double x) {
  if (std::fabs(x) < 1e-4L) return 0.5L + x / 6 + x * x / 24 + x * x * x / 120;
  return (std::expm1(x) - x) / (x * x);
}

template <class T>
Vector3<long double> widen(const Vector3<T>& v) {
  return {static_cast<long double>(v.x), static_cast<long double>(v.y),
          static_cast<long double>(v.z)};
}

/// The exact position after `time` of a shot whose damping rate is k per second.
Vector3<long double> exact_position(const scenes::BallisticShot<double>& shot, long double k,
                                    long double time) {
  const long double f1 = time * phi1(k * time);
  const long double f2 = time * time * phi2(k * time);
  return widen(scenes::ballistic_origin<double>) + widen(shot.velocity) * f1 +
         widen(shot.acceleration) * f2;
}

int repetitions = 9;  // timing repetitions; the median is reported
int rounds = 20;      // flights per repetition

template <class R, class D, class P>
Row measure(const char* name, double frame_time) {
  using Body = Particle<R, D, P>;
  const int steps = static_cast<int>(std::lround(scenes::ballistic_duration<double> / frame_time));
  const R dt = R(frame_time);
  const long double time = static_cast<long double>(dt) * steps;

  // Accuracy: each shot flown once.
  double error = 0;
  for (const auto& shot : scenes::ballistic_shots<double>) {
    Body body;
    scenes::launch(body, shot);
    for (int i = 0; i < steps; ++i) body.integrate(dt);
    long double k = 0;
    if constexpr (std::is_same_v<D, damping::PerFrame>) {
      k = std::log(static_cast<long double>(R(shot.damping))) / static_cast<long double>(dt);
    } else if constexpr (Body::stores_damping) {
      k = std::log(static_cast<long double>(R(shot.damping)));
    }
    const auto exact = exact_position(shot, k, time);
    const auto miss = widen(body.position()) - exact;
    error = std::max(error, static_cast<double>(magnitude(miss)));
  }

  // Time: the four shots stepped together, repeated; the median of the repetitions.
  std::vector<Body> bodies(4);
  std::vector<double> samples;
  for (int repetition = 0; repetition < repetitions; ++repetition) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      scenes::launch(bodies[i], scenes::ballistic_shots<double>[i]);
    }
    const auto start = std::chrono::steady_clock::now();
    for (int round = 0; round < rounds; ++round) {
      for (int i = 0; i < steps; ++i) {
        for (auto& body : bodies) body.integrate(dt);
      }
    }
    const auto stop = std::chrono::steady_clock::now();
    const double ns = std::chrono::duration<double, std::nano>(stop - start).count();
    samples.push_back(ns / (rounds * steps * static_cast<double>(bodies.size())));
  }
  // Use the result, so the timed loop cannot be dropped.
  if (!is_finite(bodies[0].position())) std::puts("non-finite position");
  const auto middle = samples.begin() + static_cast<std::ptrdiff_t>(samples.size() / 2);
  std::nth_element(samples.begin(), middle, samples.end());
  return {name, frame_time, error, *middle};
}

template <class R>
void measure_all(std::vector<Row>& rows, const char* real_name, double frame_time) {
  const std::string r = real_name;
  auto add = [&](Row row) { rows.push_back(std::move(row)); };
  using namespace damping;
  using namespace position;
  add(measure<R, None, Euler>((r + " None Euler").c_str(), frame_time));
  add(measure<R, None, Kinematic>((r + " None Kinematic").c_str(), frame_time));
  add(measure<R, None, SemiImplicit>((r + " None SemiImplicit").c_str(), frame_time));
  add(measure<R, PerFrame, Euler>((r + " PerFrame Euler").c_str(), frame_time));
  add(measure<R, PerFrame, Kinematic>((r + " PerFrame Kinematic").c_str(), frame_time));
  add(measure<R, PerFrame, SemiImplicit>((r + " PerFrame SemiImplicit").c_str(), frame_time));
  add(measure<R, PerSecond, Euler>((r + " PerSecond Euler").c_str(), frame_time));
  add(measure<R, PerSecond, Kinematic>((r + " PerSecond Kinematic").c_str(), frame_time));
  add(measure<R, PerSecond, SemiImplicit>((r + " PerSecond SemiImplicit").c_str(), frame_time));
  add(measure<R, AccelerateThenDamp, Euler>((r + " AccelerateThenDamp Euler").c_str(), frame_time));
  add(measure<R, AccelerateThenDamp, Kinematic>((r + " AccelerateThenDamp Kinematic").c_str(),
                                                frame_time));
  add(measure<R, AccelerateThenDamp, SemiImplicit>(
      (r + " AccelerateThenDamp SemiImplicit").c_str(), frame_time));
  add(measure<R, damping::Exact, position::Exact>((r + " Exact Exact").c_str(), frame_time));
}

void mark_pareto_front(std::vector<Row>& rows) {
  for (auto& row : rows) {
    row.on_front = std::none_of(rows.begin(), rows.end(), [&](const Row& other) {
      return &other != &row && other.ns_per_step <= row.ns_per_step && other.error <= row.error &&
             (other.ns_per_step < row.ns_per_step || other.error < row.error);
    });
  }
}

}  // namespace

int main(int argc, char** argv) {
  const char* csv_path = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else if (std::strcmp(argv[i], "--quick") == 0) {
      repetitions = 1;
      rounds = 1;
    } else {
      std::fprintf(stderr, "usage: %s [--csv FILE] [--quick]\n", argv[0]);
      return 2;
    }
  }

  std::vector<Row> rows;
  for (const double frame_time : scenes::standard_frame_times) {
    measure_all<float>(rows, "float", frame_time);
    measure_all<double>(rows, "double", frame_time);
  }
  mark_pareto_front(rows);

  std::printf("Ballistic shots, 5 s of flight: error against the exact continuous model\n");
  std::printf("(largest over the four shots, metres) and time per particle-step.\n\n");
  std::printf("%-38s %8s %12s %9s  %s\n", "variant (Real Damping Position)", "frame",
              "error (m)", "ns/step", "front");
  for (const auto& row : rows) {
    std::printf("%-38s   1/%-4.0f %12.3e %9.2f  %s\n", row.variant.c_str(), 1 / row.frame_time,
                row.error, row.ns_per_step, row.on_front ? "*" : "");
  }
  std::printf("\n* on the Pareto front: no other variant is both faster and more accurate.\n");
  std::printf("The full run-time-against-error sweep and its plot: docs/performance.md.\n");

  if (csv_path != nullptr) {
    std::FILE* csv = std::fopen(csv_path, "w");
    if (csv == nullptr) {
      std::fprintf(stderr, "cannot write %s\n", csv_path);
      return 1;
    }
    std::fprintf(csv, "variant,frame_time,error_m,ns_per_step,on_front\n");
    for (const auto& row : rows) {
      std::fprintf(csv, "%s,%.17g,%.6e,%.4f,%d\n", row.variant.c_str(), row.frame_time, row.error,
                   row.ns_per_step, row.on_front ? 1 : 0);
    }
    std::fclose(csv);
  }
  return 0;
}
