// SPDX-License-Identifier: BSL-1.0
// aim_preview — an artillery aim preview from the exact pair's trajectory queries.
//
// A game showing where a shell will go before it is fired: Cyclone's artillery
// shell (200 kg, 50 m/s, gravity 20 m/s^2, 99% of the velocity kept per second) aimed at
// 30, 45 and 60 degrees over a wall 20 m high at z = 60 m. For each aim the preview asks, without
// stepping anything:
//   - when the shell reaches the wall (time_to_reach on z) and how high it is there
//     (position_at): it clears the wall or hits it;
//   - whether it ever climbs to 40 m (time_to_reach on y: "never" when the apex is lower);
//   - when and where it lands (time_to_reach on y = 0, then position_at).
// Then it checks the preview against the real thing: the same shell stepped at 60 Hz passes,
// at every step, where position_at says (to 1e-9 of the distance flown), and prints PASS.
//
//   aim_preview
#include <pointmass/pointmass.hpp>

#include <cmath>
#include <cstdio>
#include <optional>

namespace {

using namespace pointmass;
using Shell = Particle<double, damping::Exact, position::Exact>;

Shell aimed(double degrees) {
  const double angle = degrees * 3.14159265358979323846 / 180.0;
  Shell shell;
  shell.set_position({0.0, 1.5, 0.0});
  shell.set_velocity({0.0, 50.0 * std::sin(angle), 50.0 * std::cos(angle)});
  shell.set_acceleration(gravity(20.0));
  shell.set_mass(200.0);
  shell.set_damping(0.99);
  return shell;
}

/// True when stepping a copy at 60 Hz until it lands passes where position_at says.
bool stepping_agrees(const Shell& shell, double landing) {
  Shell stepped = shell;
  const double dt = 1.0 / 60;
  for (int n = 1; n * dt <= landing; ++n) {
    stepped.integrate(dt);
    const Vector3<double> preview = position_at(shell, n * dt);
    if (magnitude(stepped.position() - preview) > 1e-9 * (1.0 + magnitude(preview))) return false;
  }
  return true;
}

}  // namespace

int main() {
  const double wall_z = 60.0, wall_height = 20.0, high = 40.0;
  bool all_agree = true;
  for (const double degrees : {30.0, 45.0, 60.0}) {
    const Shell shell = aimed(degrees);
    std::printf("aim %2.0f deg:", degrees);
    if (const std::optional<double> at_wall = time_to_reach(shell, Axis::z, wall_z)) {
      const double y = position_at(shell, *at_wall).y;
      std::printf(" wall at t = %.3f s, y = %.3f m (%s);", *at_wall, y,
                  y > wall_height ? "clears" : "hits");
    } else {
      std::printf(" never reaches the wall;");
    }
    if (const std::optional<double> up = time_to_reach(shell, Axis::y, high)) {
      std::printf(" %.0f m at t = %.3f s;", high, *up);
    } else {
      std::printf(" %.0f m never;", high);
    }
    const std::optional<double> landing = time_to_reach(shell, Axis::y, 0.0);
    if (!landing) {
      std::printf(" never lands\n");
      all_agree = false;
      continue;
    }
    const Vector3<double> impact = position_at(shell, *landing);
    std::printf(" lands at t = %.3f s, z = %.3f m\n", *landing, impact.z);
    all_agree = all_agree && stepping_agrees(shell, *landing);
  }
  std::printf("stepped at 60 Hz, the shells pass where the preview says: %s\n",
              all_agree ? "PASS" : "FAIL");
  return all_agree ? 0 : 1;
}
