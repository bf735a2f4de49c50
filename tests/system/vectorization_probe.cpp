// Compiled (not run) by the vectorisation tests: steps the common configurations so that
// the compiler's vectorisation report can be checked for the step loop of
// particle_system.hpp (see CMakeLists.txt).
#include <pointmass/particle_system.hpp>

namespace pm = pointmass;

void step_sparks(pm::ParticleSystem<float>& system, float t) { system.step(t); }
void step_sparks(pm::ParticleSystem<double>& system, double t) { system.step(t); }
void step_undamped(pm::ParticleSystem<float, pm::damping::None>& system, float t) {
  system.step(t);
}
void step_featured(pm::ParticleSystem<float, pm::damping::PerFrame, pm::position::Kinematic,
                                      pm::features::PerParticleAcceleration,
                                      pm::features::Forces, pm::features::Lifetime>& system,
                   float t) {
  system.step(t);
}
