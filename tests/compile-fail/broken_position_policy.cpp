// SPDX-License-Identifier: BSL-1.0
// A position policy that returns a number instead of a position does not satisfy
// PositionPolicyFor: one sentence says what a position policy needs.
// expected-error: this position policy does not fit this damping policy: it needs a static position(p0, v0, v1, a, t, factors)
#include <pointmass/particle.hpp>

struct ReturnsANumber {
  template <class P, class V, class A, class T, class F>
  static constexpr float position(const P&, const V&, const V&, const A&, const T&,
                                  const F&) noexcept {
    return 0.0f;
  }
};

int main() {
  pointmass::Particle<float, pointmass::damping::PerSecond, ReturnsANumber> particle;
  particle.integrate(0.033f);
}
