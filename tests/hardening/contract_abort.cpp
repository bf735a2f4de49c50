// SPDX-License-Identifier: BSL-1.0
// Built with -fno-exceptions -fno-rtti: the default contract handler cannot throw, so it must
// print the violation (function, argument, value, requirement) to stderr and abort. The
// program breaks the contract named by its argument; contract_abort.cmake runs it and checks
// that it died by abort with the documented message, and did not get past the bad call.
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>

#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#if POINTMASS_HAS_EXCEPTIONS
#error "contract_abort.cpp must be built with -fno-exceptions"
#endif

int main(int argc, char** argv) {
  using namespace pointmass;
  const char* which = argc > 1 ? argv[1] : "";
  if (std::strcmp(which, "set_mass") == 0) {
    Particle<double> particle;
    particle.set_mass(-1.5);
  } else if (std::strcmp(which, "integrate") == 0) {
    Particle<float, damping::Exact, position::Exact> particle;
    particle.integrate(-0.25f);
  } else if (std::strcmp(which, "add_force") == 0) {
    Particle<float> particle;
    particle.add_force({1.0f, std::numeric_limits<float>::infinity(), 0.5f});
  } else if (std::strcmp(which, "kill") == 0) {
    ParticleSystem<double> system(4);
    system.kill(7);
  } else if (std::strcmp(which, "reserve") == 0) {  // where std::length_error would be thrown
    ParticleSystem<float> system(4);
    system.reserve(std::numeric_limits<std::size_t>::max());
  } else {
    std::fprintf(stderr, "usage: %s set_mass|integrate|add_force|kill|reserve\n", argv[0]);
    return 2;
  }
  std::puts("survived the violation");  // reached only if the handler returned
  return 0;
}
