// Compiled (not run) by the vectorisation tests: steps the common configurations so that
// the compiler's vectorisation report can be checked for the step loop of
// particle_system.hpp (see CMakeLists.txt). With POINTMASS_PROBE_BACKWARD it instantiates
// only the backward walk (step_range_backward), and no configuration with another loop
// (Lifetime's expiry pass), so a vectorised loop in the report can only be that walk's.
#include <pointmass/particle_system.hpp>

namespace pm = pointmass;

namespace {

template <class System>
void probe(System& system, typename System::real t) {
#if defined(POINTMASS_PROBE_BACKWARD)
  System::step_range_backward(system.arrays(), 0, system.size(), system.step_parameters(t));
#else
  system.step(t);
#endif
}

}  // namespace

void step_sparks(pm::ParticleSystem<float>& system, float t) { probe(system, t); }
void step_sparks(pm::ParticleSystem<double>& system, double t) { probe(system, t); }
void step_undamped(pm::ParticleSystem<float, pm::damping::None>& system, float t) {
  probe(system, t);
}
#if defined(POINTMASS_PROBE_BACKWARD)
void step_featured(pm::ParticleSystem<float, pm::damping::PerFrame, pm::position::Kinematic,
                                      pm::features::PerParticleAcceleration,
                                      pm::features::ForceAccumulator>& system,
                   float t) {
  probe(system, t);
}
#else
void step_featured(pm::ParticleSystem<float, pm::damping::PerFrame, pm::position::Kinematic,
                                      pm::features::PerParticleAcceleration,
                                      pm::features::ForceAccumulator, pm::features::Lifetime>& system,
                   float t) {
  probe(system, t);
}
#endif
