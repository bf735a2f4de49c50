// SPDX-License-Identifier: BSL-1.0
// A ParticleSystem does not convert to the state or the facets below it: they are private.
// expected-error: is an inaccessible base of
// expected-error: to its private base class
#include <pointmass/particle_system.hpp>

using System = pointmass::ParticleSystem<float>;
using Base = pointmass::detail::SystemColumns<pointmass::detail::SystemStateBase<
    float, pointmass::damping::PerSecond, pointmass::position::Euler>>;

int main() {
  System system;
  const Base& base = system;
  return static_cast<int>(sizeof(base));
}
