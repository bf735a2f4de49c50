// SPDX-License-Identifier: BSL-1.0
// Compiles: every argument has the type it should. Proves the harness can tell good from bad.
#include <pointmass/particle.hpp>
#include <pointmass/units.hpp>

namespace pm = pointmass;
namespace si = boost::units::si;

/// A user's position policy, correct in its dimensions: p0 + v1 t.
struct UserSemiImplicit {
  template <class P, class V, class A, class T, class F>
  static constexpr P position(const P& p0, const V&, const V& v1, const A&, const T& t,
                              const F&) noexcept {
    return p0 + v1 * t;
  }
};

int main() {
  pm::units::Particle<float, pm::damping::PerSecond, UserSemiImplicit> shell;
  shell.set_position(pm::Vector3<float>{0.0f, 1.5f, 0.0f} * si::meters);
  shell.set_velocity(pm::Vector3<float>{0.0f, 30.0f, 40.0f} * si::meters_per_second);
  shell.set_acceleration(pm::Vector3<float>{0.0f, -20.0f, 0.0f} * si::meters_per_second_squared);
  shell.set_mass(200.0f * si::kilograms);
  shell.set_inverse_mass(0.005f / si::kilograms);
  shell.set_damping(0.99f);
  shell.add_force(pm::Vector3<float>{1.0f, 0.0f, 0.0f} * si::newtons);
  shell.integrate(0.033f * si::seconds);

  pm::units::Particle<double, pm::damping::Exact, pm::position::Exact> exact;
  exact.integrate(0.033 * si::seconds);

  pm::Particle<float> plain;
  plain.set_damping(0.995f);
  plain.integrate(0.033f);
  return shell.position().y.value() > 0.0f ? 0 : 1;
}
