// SPDX-License-Identifier: BSL-1.0
// A user's program on pointmass::units: one second of free fall in SI quantities, with the
// gravity units.hpp provides, read back as a length and as a number of metres.
#include <pointmass/units.hpp>

#include <cstdio>

int main() {
  namespace si = boost::units::si;
  pointmass::units::Particle<double, pointmass::damping::None,
                             pointmass::position::ConstantAcceleration>
      ball;
  ball.set_position(pointmass::Vector3<double>{0, 10, 0} * si::meters);
  ball.set_acceleration(pointmass::units::gravity<double>());
  for (int i = 0; i < 60; ++i) ball.integrate((1.0 / 60) * si::seconds);
  const pointmass::units::length<double> height = ball.position().y;
  const double metres = height.value();
  const double expected = 10 - 9.807 / 2;
  if (metres - expected > 1e-12 || metres - expected < -1e-12) {
    std::printf("consumer_units: wrong height %.17g m, expected %.17g m\n", metres, expected);
    return 1;
  }
  std::printf("consumer_units: ok (height %.6f m after 1 s)\n", metres);
  return 0;
}
