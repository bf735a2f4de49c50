// A Real that is not float, double or long double.
// expected-error: (Real<R>)
// expected-error: does not satisfy 'Real'
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<int> particle;
  particle.integrate(1);
}
