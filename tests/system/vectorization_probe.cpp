// Compiled (not run) by the vectorisation tests: steps one configuration, the system type
// POINTMASS_PROBE_SYSTEM given on the command line, so that the compiler's vectorisation
// report can only be about that configuration's loops (the list of configurations is in
// CMakeLists.txt). With POINTMASS_PROBE_BACKWARD it instantiates only the backward walk
// (step_range_backward), and no other loop (Lifetime's expiry pass), so a vectorised loop
// in the report can only be that walk's.
#include <pointmass/particle_system.hpp>

namespace pm = pointmass;

#if !defined(POINTMASS_PROBE_SYSTEM)
#error "POINTMASS_PROBE_SYSTEM (a ParticleSystem type) must be defined"
#endif

using ProbedSystem = POINTMASS_PROBE_SYSTEM;

void step_probe(ProbedSystem& system, ProbedSystem::real t) {
#if defined(POINTMASS_PROBE_BACKWARD)
  ProbedSystem::step_range_backward(system.arrays(), 0, system.size(), system.step_parameters(t));
#else
  system.step(t);
#endif
}
