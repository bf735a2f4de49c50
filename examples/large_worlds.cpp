// SPDX-License-Identifier: BSL-1.0
// Large worlds: how far each position precision drifts (precision.hpp). For every launch, the
// particle flies 10^6 steps of 1/60 s (4.6 hours) as all-float, with double positions and with
// compensated positions, and its final position is compared with
//   * the exact sum of the same float steps: the displacement an all-float particle computes
//     each step, summed in long double — what the position storage loses, nothing else;
//   * an all-double particle (double velocities and step), for information: there the float
//     step length alone (1/60 rounded to float) moves a 10 m/s flight by about 9 mm.
// Built without FMA contraction (large_worlds.cmake), so that the all-float and the wide
// particles compute the same float velocities, bit for bit.
// Prints Markdown tables (scripts/large-worlds.sh writes them into
// docs/results/large-worlds.md).
//   large_worlds           the tables
//   large_worlds --quick   10^4 steps (the smoke test)
#include <pointmass/pointmass.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

namespace pm = pointmass;
using pm::Vector3;
using Wide = long double;

struct Launch {
  const char* name;
  Vector3<double> start;
  Vector3<float> velocity;
  Vector3<float> acceleration;
  float damping;
  long steps;
};

Vector3<Wide> widen(const Vector3<double>& v) { return {Wide(v.x), Wide(v.y), Wide(v.z)}; }
Vector3<Wide> widen(const Vector3<float>& v) { return {Wide(v.x), Wide(v.y), Wide(v.z)}; }
double distance(const Vector3<Wide>& a, const Vector3<Wide>& b) {
  const Wide dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return static_cast<double>(std::sqrt(dx * dx + dy * dy + dz * dz));
}

template <class Particle>
void configure(Particle& particle, const Launch& launch) {
  using R = typename Particle::real;
  particle.set_velocity({R(launch.velocity.x), R(launch.velocity.y), R(launch.velocity.z)});
  particle.set_acceleration(
      {R(launch.acceleration.x), R(launch.acceleration.y), R(launch.acceleration.z)});
  if constexpr (Particle::stores_damping) particle.set_damping(R(launch.damping));
}

struct Drift {
  double exact[3];  ///< float, double positions, compensated: against the exact sum
  double twin[3];   ///< the same against all-double
};

template <class D, class P>
Drift fly(const Launch& launch) {
  pm::Particle<float, D, P> single;
  pm::Particle<pm::Precision<float, double>, D, P> wide;
  pm::Particle<pm::Precision<float, pm::Compensated<float>>, D, P> pair;
  pm::Particle<float, D, P> mover;  // at the origin before each step: its step is the displacement
  pm::Particle<double, D, P> twin;
  single.set_position({static_cast<float>(launch.start.x), static_cast<float>(launch.start.y),
                       static_cast<float>(launch.start.z)});
  wide.set_position(launch.start);
  pair.set_position(launch.start);
  twin.set_position(launch.start);
  configure(single, launch);
  configure(wide, launch);
  configure(pair, launch);
  configure(mover, launch);
  configure(twin, launch);
  const float h = 1.0f / 60.0f;
  Vector3<Wide> exact = widen(launch.start);
  for (long n = 0; n < launch.steps; ++n) {
    mover.set_position({});
    mover.integrate(h);
    exact += widen(mover.position());
    single.integrate(h);
    wide.integrate(h);
    pair.integrate(h);
    twin.integrate(1.0 / 60.0);
  }
  const Vector3<Wide> finals[3] = {widen(single.position()), widen(wide.position()),
                                   widen(pair.position())};
  Drift drift{};
  for (int k = 0; k < 3; ++k) {
    drift.exact[k] = distance(finals[k], exact);
    drift.twin[k] = distance(finals[k], widen(twin.position()));
  }
  return drift;
}

std::string metres(double x) {
  char text[32];
  if (x == 0.0) return "0";
  if (x >= 1000.0) std::snprintf(text, sizeof text, "%.0f km", x / 1000.0);
  else if (x >= 1.0) std::snprintf(text, sizeof text, "%.2f m", x);
  else if (x >= 1e-3) std::snprintf(text, sizeof text, "%.2f mm", x * 1e3);
  else if (x >= 1e-6) std::snprintf(text, sizeof text, "%.2f um", x * 1e6);
  else std::snprintf(text, sizeof text, "%.1e m", x);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const long steps = quick ? 10'000 : 1'000'000;
  namespace d = pm::damping;
  namespace p = pm::position;
  // Free flight (no drag, no gravity) as in docs/accuracy.md; the artillery shot (gravity and
  // per-second drag, the exact pair) launched far from the origin; sparks (per-frame drag).
  const Launch free_1e6{
      "free flight from 1e6 m (None, Euler)", {1e6, 0, 0}, {10, 0, 5}, {0, 0, 0}, 1.0f, steps};
  const Launch free_1e8{
      "free flight from 1e8 m (None, Euler)", {1e8, 0, 0}, {10, 0, 5}, {0, 0, 0}, 1.0f, steps};
  const Launch shot_1e6{"artillery from 1e6 m, gravity and drag (Exact, Exact)",
                        {1e6, 0, 2.5e5},
                        {300, 400, 0},
                        {0, -9.81f, 0},
                        0.9f,
                        steps};
  const Launch shot_1e8{"artillery from 1e8 m, gravity and drag (Exact, Exact)",
                        {1e8, 0, 2.5e7},
                        {300, 400, 0},
                        {0, -9.81f, 0},
                        0.9f,
                        steps};
  const Launch sparks_1e6{"sparks from 1e6 m, per-frame drag (PerFrame, ConstantAcceleration)",
                          {0, 1e6, 0},
                          {3, 8, -2},
                          {0, -9.81f, 0},
                          0.995f,
                          steps};
  const Launch shot_near{"near the origin: a 10 s shot from (0, 0, 0) (Exact, Exact), 600 steps",
                         {0, 0, 0},
                         {30, 40, 0},
                         {0, -9.81f, 0},
                         0.9f,
                         600};
  const Launch free_near{"near the origin: 10^4 steps of 0.1 m/s from (1, 2, 3) (None, Euler)",
                         {1, 2, 3},
                         {0.1f, 0, 0.05f},
                         {0, 0, 0},
                         1.0f,
                         10'000};

  struct Row {
    const Launch* launch;
    Drift drift;
  };
  const Row rows[] = {{&free_1e6, fly<d::None, p::Euler>(free_1e6)},
                      {&free_1e8, fly<d::None, p::Euler>(free_1e8)},
                      {&shot_1e6, fly<d::Exact, p::Exact>(shot_1e6)},
                      {&shot_1e8, fly<d::Exact, p::Exact>(shot_1e8)},
                      {&sparks_1e6, fly<d::PerFrame, p::ConstantAcceleration>(sparks_1e6)},
                      {&shot_near, fly<d::Exact, p::Exact>(shot_near)},
                      {&free_near, fly<d::None, p::Euler>(free_near)}};

  std::printf(
      "Drift after %ld steps of 1/60 s (unless the row says otherwise) against the exact "
      "sum of the same float steps (what the position storage loses):\n\n",
      steps);
  std::printf(
      "| launch | float | `Precision<float, double>` | `Precision<float, Compensated<float>>` |\n"
      "|---|---|---|---|\n");
  for (const Row& row : rows) {
    std::printf("| %s | %s | %s | %s |\n", row.launch->name, metres(row.drift.exact[0]).c_str(),
                metres(row.drift.exact[1]).c_str(), metres(row.drift.exact[2]).c_str());
  }
  std::printf(
      "\nThe same against an all-double particle (double velocities and step; for "
      "information: it includes what the float inputs themselves differ by):\n\n");
  std::printf(
      "| launch | float | `Precision<float, double>` | `Precision<float, Compensated<float>>` |\n"
      "|---|---|---|---|\n");
  for (const Row& row : rows) {
    std::printf("| %s | %s | %s | %s |\n", row.launch->name, metres(row.drift.twin[0]).c_str(),
                metres(row.drift.twin[1]).c_str(), metres(row.drift.twin[2]).c_str());
  }
  return 0;
}
