// SPDX-License-Identifier: BSL-1.0
// A system with features::Handles keeps its handle table beside the host's arrays, which a
// device cannot keep: KokkosSystem refuses the configuration with one sentence (compiled, and
// expected to fail, by tests/kokkos/CMakeLists.txt where Kokkos is found).
// expected-error: KokkosSystem: features::Handles is not supported on a device
#include <pointmass/kokkos.hpp>
#include <pointmass/particle_system.hpp>

using Named = pointmass::ParticleSystem<float, pointmass::damping::None, pointmass::position::Euler,
                                        pointmass::features::Handles>;

int main() {
  const pointmass::KokkosSystem<Named> device;
  return static_cast<int>(device.size());
}
