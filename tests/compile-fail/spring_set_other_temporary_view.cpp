// SPDX-License-Identifier: BSL-1.0
// Spring::set_other keeps the address of the other body, as the constructor does: a temporary
// view (forces::relative_to(b, origin)) would be gone before the spring's first use. Name the
// view, and keep it as long as the spring.
// expected-error: the other body is a temporary
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

using Far = pointmass::Particle<pointmass::Precision<float, double>>;

int main() {
  Far a, b;
  const pointmass::Vector3<double> origin{1e6, 0.0, 0.0};
  pointmass::forces::Bungee<pointmass::forces::RelativeBody<Far>> cord;
  cord.set_other(pointmass::forces::relative_to(b, origin));
  auto view_a = pointmass::forces::relative_to(a, origin);
  pointmass::forces::update_force(cord, view_a, 1.0f / 60);
}
