// A damping policy without a velocity update does not satisfy DampingPolicy.
// expected-error: (DampingPolicy<D>)
// expected-error: does not satisfy 'DampingPolicy'
#include <pointmass/particle.hpp>

struct NoVelocityUpdate {
  template <class R>
  struct State {
    R value() const { return R(1); }
  };
  template <class R, class T>
  static int factors(const State<R>&, const T&) {
    return 0;
  }
};

int main() {
  pointmass::Particle<float, NoVelocityUpdate> particle;
  particle.integrate(0.033f);
}
