// SPDX-License-Identifier: BSL-1.0
// A consumer that includes the headers with a plain -I and builds with warnings beyond the
// project's own, as errors: -Wfloat-equal and -Wmissing-noreturn (and, with clang,
// -Weverything but for the warnings listed in run.cmake). Every policy pair, in float, double
// and long double, is instantiated, so that a warning inside a template shows.
// ParticleSystem is stepped in every feature set too.
#include <pointmass/pointmass.hpp>

#include <cstdio>

namespace pm = pointmass;

namespace {

template <class R, class D, class P>
R run() {
  pm::Particle<R, D, P> particle;
  particle.set_position({R(0), R(1), R(0)});
  particle.set_velocity({R(1), R(2), R(3)});
  particle.set_acceleration(pm::gravity<R>());
  particle.set_mass(R(2));
  if constexpr (pm::Particle<R, D, P>::stores_damping) particle.set_damping(R(0.9));
  const pm::forces::Gravity<R> gravity(pm::gravity<R>());
  pm::forces::update_force(gravity, particle, R(0.01));
  const pm::forces::AnchoredSpring<R> spring({R(0), R(2), R(0)}, R(10), R(0.5));
  pm::forces::update_force(spring, particle, R(0.01));
  particle.integrate(R(0.01));
  particle.integrate(R(0));
  pm::ParticleSystem<R, D, P, pm::features::ForceAccumulator, pm::features::Lifetime,
                     pm::features::PerParticleAcceleration>
      system;
  system.spawn(particle);
  system.set_lifetime(0, R(1));
  system.step(R(0.01));
  system.step(R(0));
  return pm::magnitude(pm::normalized(system.position(0))) + pm::real_sqrt(R(4));
}

template <class R>
R every_pair() {
  namespace damping = pm::damping;
  namespace position = pm::position;
  return run<R, damping::None, position::Euler>() + run<R, damping::None, position::Exact>() +
         run<R, damping::PerFrame, position::ConstantAcceleration>() +
         run<R, damping::PerSecond, position::SemiImplicit>() +
         run<R, damping::AccelerateThenDamp, position::Euler>() +
         run<R, damping::Exact, position::Exact>();
}

}  // namespace

int main() {
  // Each run returns |unit vector| + sqrt(4) = 3, six pairs: 18 in each precision.
  const double total = static_cast<double>(every_pair<float>()) + every_pair<double>() +
                       static_cast<double>(every_pair<long double>());
  if (total < 53.999 || total > 54.001) {
    std::printf("strict: wrong total %g\n", total);
    return 1;
  }
  std::printf("strict: ok\n");
  return 0;
}
