// SPDX-License-Identifier: BSL-1.0
// A ParticleSystem feature tag the library does not know (a user's own type in the list).
// expected-error: is_feature_v<Features> && ...) [with Features = {Colour}]
// expected-error: is_feature_v<Colour>' evaluated to false
#include <pointmass/particle_system.hpp>

struct Colour {};

int main() {
  pointmass::ParticleSystem<float, pointmass::damping::PerSecond, pointmass::position::Euler,
                            Colour>
      sparks;
  return static_cast<int>(sparks.size());
}
