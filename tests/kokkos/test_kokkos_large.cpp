// SPDX-License-Identifier: BSL-1.0
// 1,000,000 particles: a few steps of two configurations (the many-step runs are at the
// sizes around the vector block), so that the Kokkos loop and the expiry's scans run over
// many chunks of a threaded backend, with particles expiring at every step.
#include "kokkos_support.hpp"

using namespace pointmass;

TEST_CASE_TEMPLATE(
    "1,000,000 particles: Kokkos equals ParticleSystem::step, bit for bit", System,
    ParticleSystem<float, damping::PerSecond, position::ConstantAcceleration, features::Lifetime>,
    ParticleSystem<double, damping::Exact, position::Exact, features::PerParticleDamping,
                   features::PerParticleAcceleration, features::ForceAccumulator,
                   features::Lifetime>) {
  using R = typename System::real;
  constexpr std::size_t count = 1'000'000;
  System host = test::make_scene<System>(count, 3);
  // Lifetimes over the first few steps, so that every step expires many particles.
  for (std::size_t i = 0; i < count; i += 3) host.set_lifetime(i, R(0.02) * R(i % 10 + 1));
  test::DeviceSystem<System> device(host);
  std::size_t previous = count;
  for (int step = 0; step < 4; ++step) {
    host.step(R(1) / R(30));
    device.step(test::Space(), R(1) / R(30));
    CHECK(host.size() < previous);  // this step expired particles
    previous = host.size();
  }
  System back;
  device.copy_to(back);
  REQUIRE(back.size() == host.size());
  CHECK(test::same_arrays(back, host));
}
