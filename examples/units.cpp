// SPDX-License-Identifier: BSL-1.0
// Cyclone's ballistic shots, with Boost.Units: every value the particle takes or
// gives is an SI quantity, and a dimension slip (a velocity as a position, a force as an
// acceleration, a duration in metres) does not compile. See docs/units.md.
//
// Prints, for each shot, where it is when it comes down to the ground or when the round ends.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <boost/units/io.hpp>

#include <pointmass/extras/scenes.hpp>
#include <pointmass/units.hpp>

namespace pm = pointmass;
namespace si = boost::units::si;
using Real = double;
using Shell = pm::units::Particle<Real, pm::damping::PerSecond, pm::position::ConstantAcceleration>;

/// Puts the particle at the start of a shot: the scene's plain numbers times their SI units.
void launch(Shell& shell, const pm::scenes::BallisticShot<Real>& shot) {
  shell.set_position(pm::scenes::ballistic_origin<Real> * si::meters);
  shell.set_velocity(shot.velocity * si::meters_per_second);
  shell.set_acceleration(shot.acceleration * si::meters_per_second_squared);
  shell.set_mass(shot.mass * si::kilograms);
  shell.set_damping(shot.damping);  // a fraction kept per second: dimensionless
}

int main() {
  const pm::units::time<Real> frame = (1.0 / 30.0) * si::seconds;
  const pm::units::time<Real> round = pm::scenes::ballistic_duration<Real> * si::seconds;
  const int frames_per_round = static_cast<int>(std::lround((round / frame).value()));
  const pm::units::length<Real> ground = 0.0 * si::meters;

  for (const auto& shot : pm::scenes::ballistic_shots<Real>) {
    Shell shell;
    launch(shell, shot);
    int frames = 0;
    while (frames < frames_per_round && shell.position().y >= ground) {
      shell.integrate(frame);
      ++frames;
    }
    const pm::units::time<Real> elapsed = static_cast<Real>(frames) * frame;
    const auto p = shell.position();
    const auto v = shell.velocity();
    std::printf("%-9s after %5.3f s: range %8.3f m, height %7.3f m, speed forward %7.3f m/s\n",
                shot.name.data(), pm::in_seconds(elapsed), p.z.value(), p.y.value(), v.z.value());
  }

  // Quantities print with their units, too:
  Shell shell;
  launch(shell, pm::scenes::ballistic_shots<Real>[1]);
  shell.integrate(frame);
  std::printf("artillery after one frame: ");
  std::fflush(stdout);
  std::cout << "y = " << shell.position().y << ", vy = " << shell.velocity().y << '\n';
}
