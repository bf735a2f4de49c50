// SPDX-License-Identifier: BSL-1.0
// A damping policy with everything but its velocity update (damping::None without
// velocity) does not satisfy DampingPolicy, and the requirement named is the velocity.
// expected-error: D::velocity(vf, vf, tf, D::factors(
// expected-error: no member named 'velocity' in 'NoVelocityUpdate'
#include <pointmass/particle.hpp>

struct NoVelocityUpdate {
  static constexpr int order = 1;
  static constexpr bool exact_for_constant_acceleration = true;
  template <pointmass::Real R>
  struct State {
    static constexpr R value() noexcept { return R(1); }
  };
  struct Factors {};
  template <pointmass::Real R, class T>
  static constexpr Factors factors(const State<R>&, const T&) noexcept {
    return {};
  }
};

int main() {
  pointmass::Particle<float, NoVelocityUpdate> particle;
  particle.integrate(0.033f);
}
