// SPDX-License-Identifier: BSL-1.0
// A Spring (or Bungee) keeps the address of the other body: a temporary one would be gone
// before the spring's first use. The other body is a named object that outlives the spring.
// expected-error: the other body is a temporary
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

using Body = pointmass::Particle<double>;

Body anchor_body() {
  Body body;
  body.set_position({0.0, 5.0, 0.0});
  return body;
}

int main() {
  Body ball;
  const pointmass::forces::Spring<Body> rope(anchor_body(), 20.0, 1.0);
  pointmass::forces::update_force(rope, ball, 0.01);
}
