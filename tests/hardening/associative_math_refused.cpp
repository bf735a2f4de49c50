// SPDX-License-Identifier: BSL-1.0
// Built by g++ with -fassociative-math (alone or in -ffast-math): refused, naming the flag.
// expected-error: -fassociative-math (part of -ffast-math) reorders the library's exact sums
#include <pointmass/pointmass.hpp>

int main() { return pointmass::Particle<float>{}.velocity().x > 0.0f ? 1 : 0; }
