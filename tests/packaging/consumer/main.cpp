// SPDX-License-Identifier: BSL-1.0
// A user's program: one second of free fall with the full position update is exact.
#include <pointmass/pointmass.hpp>

#include <cstdio>

int main() {
  pointmass::Particle<double, pointmass::damping::None, pointmass::position::ConstantAcceleration>
      ball;
  ball.set_position({0, 10, 0});
  ball.set_acceleration(pointmass::gravity<double>());
  for (int i = 0; i < 60; ++i) ball.integrate(1.0 / 60);
  const double expected = 10 - 9.807 / 2;
  const double error = ball.position().y - expected;
  if (error > 1e-12 || error < -1e-12) {
    std::printf("consumer: wrong height %.17g, expected %.17g\n", ball.position().y, expected);
    return 1;
  }
  std::printf("consumer: ok (height %.6f m after 1 s)\n", ball.position().y);
  return 0;
}
