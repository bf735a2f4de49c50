// SPDX-License-Identifier: BSL-1.0
// damping::Exact with every position policy it pairs with: after 1,000 steps the Kokkos-stepped
// arrays equal ParticleSystem::step's bit for bit, for every feature set, float and double,
// at 15, 16, 17, 255, 256 and 257 particles (kokkos_support.hpp).
#include "kokkos_support.hpp"

using namespace pointmass;

TEST_CASE("Exact damping, Euler position: Kokkos equals ParticleSystem::step, bit for bit") {
  test::check_pair<damping::Exact, position::Euler>();
}

TEST_CASE(
    "Exact damping, ConstantAcceleration position: Kokkos equals ParticleSystem::step, bit for "
    "bit") {
  test::check_pair<damping::Exact, position::ConstantAcceleration>();
}

TEST_CASE("Exact damping, SemiImplicit position: Kokkos equals ParticleSystem::step, bit for bit") {
  test::check_pair<damping::Exact, position::SemiImplicit>();
}

TEST_CASE("Exact damping, Exact position: Kokkos equals ParticleSystem::step, bit for bit") {
  test::check_pair<damping::Exact, position::Exact>();
}
