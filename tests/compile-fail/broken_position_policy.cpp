// A position policy that returns a number instead of a position does not satisfy
// PositionPolicyFor.
// expected-error: (PositionPolicyFor<P, D>)
// expected-error: 'PositionPolicyFor<ReturnsANumber
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
