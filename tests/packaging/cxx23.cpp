// SPDX-License-Identifier: BSL-1.0
// Compiled with -std=c++2b followed by pkg-config's flags: the package must not lower the
// consumer's standard.
#include <pointmass/pointmass.hpp>

static_assert(__cplusplus > 202002L,
              "the consumer asked for C++23, but compiles as C++20 or older");

int main() {
  pointmass::Particle<double> particle;
  particle.integrate(0.01);
  return particle.position().y > 0.0 ? 1 : 0;
}
