// SPDX-License-Identifier: BSL-1.0
// Two translation units of one program, one with POINTMASS_CHECKS on and one off, each call
// the same library functions (Particle<float>::integrate, ParticleSystem<float>::step): each
// must behave as its own setting says. Built without optimisation, so that the calls are not
// inlined and the linker has to choose between the two units' definitions if they had the
// same name (the one-definition rule; the library keeps them apart by an inline namespace).
#include <cstdio>

#include "odr.hpp"

int main() {
  const bool on = rejects_with_checks_on();
  const bool off = rejects_with_checks_off();
  std::printf("checks on: %s; checks off: %s\n", on ? "rejected" : "accepted",
              off ? "rejected" : "accepted");
  if (on && !off) {
    std::printf("odr: ok\n");
    return 0;
  }
  return 1;
}
