// SPDX-License-Identifier: BSL-1.0
// The step kernel's tuning constants are not part of ParticleSystem's interface.
// expected-error: is not a member of
// expected-error: no member named 'movable_chunk' in
#include <pointmass/particle_system.hpp>

static_assert(pointmass::ParticleSystem<float>::movable_chunk == 1024);

int main() { return 0; }
