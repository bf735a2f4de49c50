// SPDX-License-Identifier: BSL-1.0
// A chain of particles on springs, hanging from a fixed anchor under gravity.
//
// Five 1 kg particles, joined by springs of stiffness 200 N/m and rest length 0.5 m, the top
// one hung from an anchor at the origin. Gravity, the springs and a little damping are
// registered in a ForceRegistry; each frame the registry adds the forces and each particle
// integrates (symplectic Euler, which keeps a spring's energy bounded). After 60 s the chain
// has come to rest, and the program checks it against the static equilibrium worked by hand:
// the spring above particle n carries the weight of the particles from n down, so it is
// stretched by (N - n + 1) m g / k, and particle n hangs at
//   y_n = -sum_{j=1..n} (L + (N - j + 1) m g / k).
// It prints each particle's height and the hand-worked one, then "equilibrium: PASS" (and
// returns 0) when every particle is within 1 mm, or "equilibrium: FAIL" (and returns 1).
#include <array>
#include <cmath>
#include <cstdio>

#include <pointmass/forces.hpp>
#include <pointmass/pointmass.hpp>

namespace pm = pointmass;
namespace forces = pointmass::forces;

int main() {
  using Body = pm::Particle<double, pm::damping::PerSecond, pm::position::SemiImplicit>;
  constexpr int count = 5;
  constexpr double mass = 1.0;
  constexpr double stiffness = 200.0;
  constexpr double rest_length = 0.5;
  constexpr double g = 9.807;
  constexpr double frame = 1.0 / 60;

  std::array<Body, count> chain;
  for (int i = 0; i < count; ++i) {
    Body& body = chain[std::size_t(i)];
    body.set_mass(mass);
    body.set_position({0.3 * (i + 1), -rest_length * (i + 1), 0.0});  // released askew
    body.set_damping(0.5);  // keeps half its velocity per second: the chain settles
  }

  // Springs between neighbours act on both ends: one generator per end, as in the reference
  // engine's registry. The top particle hangs from the anchor.
  forces::Gravity<double> gravity({0.0, -g, 0.0});
  forces::AnchoredSpring<double> hook({0.0, 0.0, 0.0}, stiffness, rest_length);
  std::array<forces::Spring<Body>, count - 1> to_above;
  std::array<forces::Spring<Body>, count - 1> to_below;
  forces::ForceRegistry<Body, forces::Gravity<double>, forces::AnchoredSpring<double>,
                        forces::Spring<Body>>
      registry;
  registry.add(chain[0], hook);
  for (std::size_t i = 0; i < count; ++i) registry.add(chain[i], gravity);
  for (std::size_t i = 0; i + 1 < count; ++i) {
    to_above[i] = forces::Spring<Body>(chain[i], stiffness, rest_length);
    to_below[i] = forces::Spring<Body>(chain[i + 1], stiffness, rest_length);
    registry.add(chain[i + 1], to_above[i]);
    registry.add(chain[i], to_below[i]);
  }

  for (int frame_number = 0; frame_number < 60 * 60; ++frame_number) {
    registry.update_forces(frame);
    for (Body& body : chain) body.integrate(frame);
  }

  bool pass = true;
  double expected_y = 0.0;
  std::printf("particle   x (m)      y (m)      y by hand (m)\n");
  for (int n = 1; n <= count; ++n) {
    expected_y -= rest_length + (count - n + 1) * mass * g / stiffness;
    const pm::Vector3<double> p = chain[std::size_t(n - 1)].position();
    std::printf("%8d %9.5f %10.5f %12.5f\n", n, p.x, p.y, expected_y);
    if (std::abs(p.y - expected_y) > 1e-3 || std::abs(p.x) > 1e-3) pass = false;
  }
  std::printf("equilibrium: %s\n", pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}
