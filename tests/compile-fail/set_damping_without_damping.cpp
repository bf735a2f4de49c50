// damping::None stores no damping value, so its particle has no set_damping.
// expected-error: stores_damping
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<float, pointmass::damping::None> particle;
  particle.set_damping(0.99f);
}
