// SPDX-License-Identifier: BSL-1.0
// damping::PerSecond with every position policy it pairs with: after 1,000 steps the Kokkos-stepped
// arrays equal ParticleSystem::step's bit for bit, for every feature set, float and double,
// at 15, 16, 17, 255, 256 and 257 particles (kokkos_support.hpp).
#include "kokkos_support.hpp"

using namespace pointmass;

TEST_CASE("PerSecond damping, Euler position: Kokkos equals ParticleSystem::step, bit for bit") {
  test::check_pair<damping::PerSecond, position::Euler>();
}

TEST_CASE(
    "PerSecond damping, ConstantAcceleration position: Kokkos equals ParticleSystem::step, bit for "
    "bit") {
  test::check_pair<damping::PerSecond, position::ConstantAcceleration>();
}

TEST_CASE(
    "PerSecond damping, SemiImplicit position: Kokkos equals ParticleSystem::step, bit for bit") {
  test::check_pair<damping::PerSecond, position::SemiImplicit>();
}

// The credited kicks and their half steps are columns like any other: carried by copy_from
// and copy_to, moved by expiry, stepped by the same kernel.
TEST_CASE(
    "PerSecond damping, VelocityVerlet position: Kokkos equals ParticleSystem::step, bit for "
    "bit") {
  test::check_pair<damping::PerSecond, position::VelocityVerlet>();
}
