// SPDX-License-Identifier: BSL-1.0
// ballistics — Cyclone's ballistic demo as a terminal program.
//
// Four shots leave (0, 1.5, 0): pistol, artillery, fireball and laser (scenes.hpp has their
// mass, velocity, gravity and damping). Each flies on a fixed time step until it falls below
// the ground (y < 0), passes z = 200 m, or 5 s have gone by. The program prints where and
// when each round ends and, with --csv, writes every step's position for plotting
// (scripts/plot-ballistics.sh draws the side view with gnuplot).
//
// The particle uses the exact pair: per-second damping solved in closed form, so the
// trajectory is the true one at any step; --defaults flies the defaults instead
// (eq. 3.6 and p + v t) to compare.
//
//   ballistics [--dt SECONDS] [--defaults] [--csv FILE]
#include <pointmass/extras/scenes.hpp>
#include <pointmass/pointmass.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using namespace pointmass;

enum class Ending { landed, out_of_range, timed_out };

const char* describe(Ending ending) {
  switch (ending) {
    case Ending::landed: return "lands";
    case Ending::out_of_range: return "out of range";
    case Ending::timed_out: return "still flying";
  }
  return "";
}

/// Flies one shot; writes "shot,t,x,y,z" rows to csv when given; prints how it ends.
template <class Body>
void fly(const scenes::BallisticShot<double>& shot, double dt, std::FILE* csv) {
  Body body;
  scenes::launch(body, shot);
  const double duration = scenes::ballistic_duration<double>;
  const int max_steps = static_cast<int>(duration / dt + 0.5);
  double time = 0;
  Ending ending = Ending::timed_out;
  for (int step = 1; step <= max_steps; ++step) {
    body.integrate(dt);
    time = step * dt;
    const auto p = body.position();
    if (csv != nullptr) {
      std::fprintf(csv, "%.*s,%.6f,%.6f,%.6f,%.6f\n", static_cast<int>(shot.name.size()),
                   shot.name.data(), time, p.x, p.y, p.z);
    }
    if (p.y < 0) {
      ending = Ending::landed;
      break;
    }
    if (p.z > 200) {
      ending = Ending::out_of_range;
      break;
    }
  }
  const auto p = body.position();
  std::printf("%-10.*s %-13s at t = %.3f s: x %.3f y %.3f z %.3f m\n",
              static_cast<int>(shot.name.size()), shot.name.data(), describe(ending), time, p.x,
              p.y, p.z);
}

}  // namespace

int main(int argc, char** argv) {
  double dt = 1.0 / 60;
  bool defaults = false;
  const char* csv_path = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--dt") == 0 && i + 1 < argc) {
      dt = std::strtod(argv[++i], nullptr);
    } else if (std::strcmp(argv[i], "--defaults") == 0) {
      defaults = true;
    } else if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--dt SECONDS] [--defaults] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  if (!(dt > 0 && dt <= 5)) {
    std::fprintf(stderr, "--dt must be in (0, 5] seconds, got %g\n", dt);
    return 2;
  }
  std::FILE* csv = nullptr;
  if (csv_path != nullptr) {
    csv = std::fopen(csv_path, "w");
    if (csv == nullptr) {
      std::fprintf(stderr, "cannot write %s\n", csv_path);
      return 1;
    }
    std::fprintf(csv, "shot,t,x,y,z\n");
  }

  std::printf("%s, step %.6f s\n",
              defaults ? "the defaults (eq. 3.6, p + v t)" : "exact pair (closed form with drag)",
              dt);
  for (const auto& shot : scenes::ballistic_shots<double>) {
    if (defaults) {
      fly<Particle<double>>(shot, dt, csv);
    } else {
      fly<Particle<double, damping::Exact, position::Exact>>(shot, dt, csv);
    }
  }
  if (csv != nullptr) std::fclose(csv);
  return 0;
}
