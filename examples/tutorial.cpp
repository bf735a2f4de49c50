// SPDX-License-Identifier: BSL-1.0
// tutorial — the code of docs/tutorial.md, which quotes it, each part checking its result.
//
// 1. One particle: a ball thrown with the defaults, then a shell with the exact pair; each
//    checked against the closed form of its motion.
// 2. Many particles: a ParticleSystem of sparks with lifetimes; the survivors counted and
//    their height checked.
// 3. Forces: a bob on a spring with drag; its rest position checked against the one worked
//    by hand.
// 4. Fireworks: a rocket whose fuse ends bursts into sparks (the expiry callback), stepped
//    at a fixed 60 Hz and drawn between the steps; the sparks counted.
//
// Each check prints "ok: ..." or "FAILED: ..."; the program returns 1 at the first failure.
#include <pointmass/pointmass.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

namespace {

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) std::exit(1);
}

bool near(double value, double expected, double tolerance) {
  return std::abs(value - expected) <= tolerance;
}

void one_particle() {
  pointmass::Particle<double> ball;                  // damping::PerSecond, position::Euler
  ball.set_position({0.0, 2.0, 0.0});                // m
  ball.set_velocity({3.0, 10.0, 0.0});               // m/s
  ball.set_acceleration(pointmass::gravity(9.807));  // (0, -9.807, 0) m/s^2
  ball.set_damping(1.0);                             // velocity kept per second: all, no drag
  const double dt = 1.0 / 60;                        // s
  for (int step = 0; step < 60; ++step) ball.integrate(dt);
  const pointmass::Vector3<double> p = ball.position();
  std::printf("ball after 1 s: x %.4f y %.4f m\n", p.x, p.y);  // x 3.0000 y 7.1782 m

  // Euler's p + v t over n steps of dt is p0 + v0 T - g T (T - dt) / 2 (T = n dt): the
  // parabola's p0 + v0 T - g T^2 / 2 plus g T dt / 2, 8 cm here.
  const double T = 1.0;
  check(near(p.x, 3.0 * T, 1e-12), "the ball moves 3 m along x");
  check(near(p.y, 2.0 + 10.0 * T - 9.807 * T * (T - dt) / 2, 1e-12),
        "the ball is where Euler's steps put it");
  check(near(p.y - (2.0 + 10.0 * T - 9.807 * T * T / 2), 9.807 * T * dt / 2, 1e-12),
        "Euler's ball is g T dt / 2 above the parabola");

  using Shell = pointmass::Particle<double, pointmass::damping::Exact, pointmass::position::Exact>;
  Shell shell;
  shell.set_position({0.0, 2.0, 0.0});
  shell.set_velocity({3.0, 10.0, 0.0});
  shell.set_acceleration(pointmass::gravity(9.807));
  shell.set_damping(0.5);  // keeps half its velocity per second
  for (int step = 0; step < 60; ++step) shell.integrate(dt);
  const pointmass::Vector3<double> q = shell.position();
  std::printf("shell after 1 s: x %.4f y %.4f m\n", q.x, q.y);  // x 2.1640 y 5.2710 m

  // The motion with drag: v' = a + k v, k = ln d; p(T) = p0 + v0 (e^kT - 1) / k
  // + a (e^kT - 1 - k T) / k^2.
  const double k = std::log(0.5);
  const double phi1 = std::expm1(k * T) / k;
  const double phi2 = (std::expm1(k * T) - k * T) / (k * k);
  check(near(q.x, 3.0 * phi1, 1e-12), "the shell is on its exact path (x)");
  check(near(q.y, 2.0 + 10.0 * phi1 - 9.807 * phi2, 1e-12), "the shell is on its exact path (y)");
}

void many_particles() {
  using Sparks =
      pointmass::ParticleSystem<float, pointmass::damping::None, pointmass::position::Euler,
                                pointmass::features::Lifetime>;
  Sparks sparks(1000);                                  // room for 1,000
  sparks.set_acceleration(pointmass::gravity(9.807f));  // one acceleration for all
  for (int n = 0; n < 100; ++n) {
    const std::size_t i = sparks.spawn({0.0f, 1.0f, 0.0f}, {float(n % 10) - 4.5f, 8.0f, 0.0f});
    sparks.set_lifetime(i, n % 2 == 0 ? 0.5f : 2.0f);  // s
  }
  for (int step = 0; step < 60; ++step) sparks.step(1.0f / 60);

  float highest = 0.0f;
  for (std::size_t i = 0; i < sparks.size(); ++i) highest = std::max(highest, sparks.position(i).y);
  std::printf("sparks after 1 s: %zu left, the highest at y %.3f m\n", sparks.size(),
              double(highest));  // 50 left, the highest at y 4.178 m

  check(sparks.size() == 50, "the 50 sparks with a lifetime of 0.5 s are gone");
  check(near(double(highest), 1.0 + 8.0 - 9.807 * (1.0 - 1.0 / 60) / 2, 1e-4),
        "the sparks are where Euler's steps put them");
}

void spring_and_drag() {
  namespace forces = pointmass::forces;
  using Body =
      pointmass::Particle<double, pointmass::damping::None, pointmass::position::SemiImplicit>;
  Body bob;
  bob.set_mass(2.0);                                // kg
  bob.set_position({0.5, -1.0, 0.0});               // m: released to one side
  bob.set_acceleration(pointmass::gravity(9.807));  // gravity: cheapest as the acceleration
  // anchor, stiffness k (N/m), rest length (m); drag -v (k1 + k2 |v|): k1 (N s/m), k2 (N s^2/m^2)
  forces::AnchoredSpring<double> spring({0.0, 0.0, 0.0}, 50.0, 1.0);
  forces::Drag<double> drag(2.0, 0.0);
  const double dt = 1.0 / 60;
  for (int step = 0; step < 20 * 60; ++step) {  // 20 s
    forces::update_force(spring, bob, dt);      // adds to the force accumulator
    forces::update_force(drag, bob, dt);        // the drag's too
    bob.integrate(dt);                          // uses the forces, then clears them
  }
  const pointmass::Vector3<double> p = bob.position();
  std::printf("bob after 20 s: x %.4f y %.4f m\n", p.x, p.y);  // x 0.0000 y -1.3923 m

  // At rest the spring holds the weight: stretched by m g / k below the anchor.
  check(near(p.x, 0.0, 1e-3) && near(p.y, -(1.0 + 2.0 * 9.807 / 50.0), 1e-3),
        "the bob comes to rest where the spring holds its weight");
}

void fireworks() {
  struct KindTag {};                                 // names the column
  enum class Kind : std::uint8_t { rocket, spark };  // what each particle is
  using Fireworks =
      pointmass::ParticleSystem<float, pointmass::damping::PerSecond, pointmass::position::Euler,
                                pointmass::features::Lifetime, pointmass::features::Interpolation,
                                pointmass::features::Column<KindTag, Kind>>;
  Fireworks show(1024);
  show.set_acceleration(pointmass::gravity(9.807f));
  show.set_damping(0.5f);  // every particle keeps half its velocity per second
  const int payload = 12;  // sparks per rocket

  const std::size_t rocket = show.spawn({0, 0, 0}, {0, 25, 0}, Kind::rocket);
  show.set_lifetime(rocket, 1.0f);  // the fuse, s

  std::size_t bursts = 0;
  const auto burst = [&](std::size_t i) {  // particle i's lifetime is over: once, before removal
    if (show.column<KindTag>(i) != Kind::rocket) return;  // a spark just goes out
    ++bursts;
    for (int k = 0; k < payload; ++k) {
      const float angle = 6.2831853f * float(k) / float(payload);
      const pointmass::Vector3<float> kick{8 * std::cos(angle), 2, 8 * std::sin(angle)};
      const std::size_t spark = show.spawn(show.position(i), show.velocity(i) + kick, Kind::spark);
      show.set_lifetime(spark, 0.8f);
    }
  };

  pointmass::FixedStep<double> clock(1.0 / 60, 4);  // 60 Hz, at most 4 steps a frame
  std::vector<pointmass::Vector3<float>> drawn;     // what the renderer draws
  std::size_t after_first_burst = 0;
  for (int frame = 0; frame < 125; ++frame) {
    const double frame_time = frame % 3 == 0 ? 0.030 : 0.015;  // the frames come unevenly
    const auto due = clock.advance(frame_time);
    for (int s = 0; s < due.steps; ++s) {
      show.step(1.0f / 60, burst);
      if (bursts == 1 && after_first_burst == 0) after_first_burst = show.size();
    }
    drawn.resize(show.size());
    show.copy_interpolated_positions(float(due.alpha), std::span(drawn));
    // draw(drawn) here: every particle between its last two steps, at due.alpha
  }
  std::printf("fireworks: %zu sparks after the burst, %zu left after 2.5 s\n", after_first_burst,
              show.size());

  check(bursts == 1 && after_first_burst == std::size_t(payload),
        "the rocket bursts once, into its payload");
  check(show.empty(), "every spark has gone out");
}

}  // namespace

int main() {
  one_particle();
  many_particles();
  spring_and_drag();
  fireworks();
  std::printf("tutorial: all checks passed\n");
}
