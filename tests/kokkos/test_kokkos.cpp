// SPDX-License-Identifier: BSL-1.0
// KokkosSystem's own behaviour: copies both ways carry every stored array and the uniform
// values, expiry leaves the order swap-remove leaves, settings steer the step, views see the
// arrays, a bad duration is reported and changes nothing, the step keeps the uniform damping
// factors for its length; systems with wide positions step as the host steps them.
#include "../support/counting_damping.hpp"
#include "kokkos_support.hpp"

#include <stdexcept>
#include <type_traits>
#include <vector>

using namespace pointmass;
using test::DeviceSystem;
using test::Space;

namespace {

using Featured = ParticleSystem<double, damping::PerSecond, position::ConstantAcceleration,
                                features::PerParticleDamping, features::PerParticleAcceleration,
                                features::ForceAccumulator, features::Lifetime>;
using Sparks = ParticleSystem<float, damping::PerSecond, position::Euler, features::Lifetime>;

// A copy would share the arrays while keeping a count of its own: moves only.
static_assert(!std::is_copy_constructible_v<DeviceSystem<Sparks>>);
static_assert(std::is_nothrow_move_constructible_v<DeviceSystem<Sparks>>);

}  // namespace

TEST_CASE("the backend under test runs on the threads it was given") {
  // Serial has one; a threaded backend (OpenMP) was initialised with 2 in main.cpp.
  CHECK(Space().concurrency() == (std::is_same_v<Space, Kokkos::Serial> ? 1 : 2));
}

TEST_CASE("copy_from and copy_to carry every stored array and the uniform values") {
  const Featured host = test::make_scene<Featured>(100, 5);
  DeviceSystem<Featured> device(host);
  CHECK(device.size() == 100);
  CHECK(device.capacity() >= 100);
  for (const std::size_t start : {std::size_t{0}, std::size_t{40}, std::size_t{300}}) {
    CAPTURE(start);
    Featured back = test::make_scene<Featured>(start, 9);  // other particles, another size
    device.copy_to(back);
    CHECK(test::same_arrays(back, host));
  }
  // The uniform values too (a configuration with them).
  Sparks sparks = test::make_scene<Sparks>(20, 1);
  sparks.set_damping(0.25f);
  sparks.set_acceleration({1.0f, 2.0f, 3.0f});
  DeviceSystem<Sparks> device_sparks(sparks);
  Sparks back;
  device_sparks.copy_to(back);
  CHECK(test::same_arrays(back, sparks));
  CHECK(back.damping() == 0.25f);
  CHECK(back.acceleration() == Vector3<float>{1.0f, 2.0f, 3.0f});
}

// Positions stored wider than the arithmetic (precision.hpp): double, and a compensated float
// pair whose error terms are arrays of their own, carried and stepped as the others are.
TEST_CASE_TEMPLATE("wide positions: Kokkos equals ParticleSystem::step, bit for bit", S,
                   Precision<float, double>, Precision<float, Compensated<float>>) {
  using System = ParticleSystem<S, damping::PerSecond, position::Euler, features::Lifetime>;
  static_assert(!std::is_same_v<typename System::position_value, float>);
  for (const std::size_t count : {std::size_t{17}, std::size_t{257}}) {
    test::check_equivalence<System>(count, 1000, 11);
  }
}

TEST_CASE("reserve keeps the particles, and copy_from into a smaller capacity grows") {
  const Featured host = test::make_scene<Featured>(50, 2);
  DeviceSystem<Featured> device(host);
  device.reserve(5000);
  CHECK(device.capacity() >= 5000);
  Featured back;
  device.copy_to(back);
  CHECK(test::same_arrays(back, host));
  const Featured larger = test::make_scene<Featured>(6000, 4);
  device.copy_from(larger);
  device.copy_to(back);
  CHECK(test::same_arrays(back, larger));
}

TEST_CASE("expiry leaves the survivors in swap-remove's order") {
  // Particles 0..7 (position x = their number); 1, 2 and 6 expire at the first step.
  // Swap-remove from index 0: 7 fills 1; 6 fills 2 and, expired, is replaced by 5:
  // 0 7 5 3 4.
  Sparks host(8);
  for (int i = 0; i < 8; ++i) host.spawn({float(i), 0.0f, 0.0f}, {});
  host.set_acceleration({});
  for (const std::size_t i : {std::size_t{1}, std::size_t{2}, std::size_t{6}}) {
    host.set_lifetime(i, 0.01f);
  }
  DeviceSystem<Sparks> device(host);
  device.step(Space(), 0.5f);
  Sparks back;
  device.copy_to(back);
  const std::vector<float> expected = {0, 7, 5, 3, 4};
  const std::vector<float> order(back.template column<pointmass::Column::position_x>().begin(),
                                 back.template column<pointmass::Column::position_x>().end());
  CHECK(order == expected);
}

TEST_CASE("expire alone removes what finish_step removes and says how many") {
  Featured host = test::make_scene<Featured>(300, 8);
  for (std::size_t i = 0; i < 300; i += 4) host.set_lifetime(i, 0.5);
  DeviceSystem<Featured> device(host);
  // Age everything past 0.5 s with a loop of one's own over step_particle ...
  const auto arrays = device.arrays();
  const auto parameters = device.step_parameters(0.75);
  Kokkos::parallel_for(Kokkos::RangePolicy<Space>(0, 300), [=](std::int64_t i) {
    Featured::StepView::step_particle(arrays, static_cast<std::size_t>(i), parameters);
  });
  CHECK(device.expire(Space()) == 75);
  // ... as the host does with the same step.
  host.step(0.75);
  Featured back;
  device.copy_to(back);
  CHECK(back.size() == 225);
  CHECK(test::same_arrays(back, host));
}

TEST_CASE("settings steer the step: the uniform acceleration") {
  Sparks host = test::make_scene<Sparks>(16, 3);
  DeviceSystem<Sparks> device(host);
  device.settings().set_acceleration({0.0f, 100.0f, 0.0f});
  host.set_acceleration({0.0f, 100.0f, 0.0f});
  device.step(Space(), 0.125f);
  host.step(0.125f);
  Sparks back;
  device.copy_to(back);
  CHECK(test::same_arrays(back, host));
  CHECK(back.acceleration().y == 100.0f);
}

TEST_CASE("the step keeps the uniform damping factors for its length, as ParticleSystem::step") {
  // A fixed step computes the factors once; settings().set_damping forgets them; what is
  // stepped with the kept factors is what ParticleSystem::step gives with its own.
  using Counted = ParticleSystem<float, test::CountingPerSecond>;
  Counted host;
  for (int i = 0; i < 40; ++i) {
    host.spawn({float(i), 0.0f, 0.0f}, {1.0f, 2.0f, float(i)});
  }
  host.set_damping(0.5f);
  DeviceSystem<Counted> device(host);
  auto& calls = test::CountingPerSecond::factor_calls;
  calls = 0;
  for (int step = 0; step < 3; ++step) device.step(Space(), 0.125f);
  CHECK(calls == 1);  // a fixed step: computed once, then kept
  device.step(Space(), 0.25f);
  CHECK(calls == 2);  // a new length
  device.settings().set_damping(0.25f);
  device.step(Space(), 0.25f);
  CHECK(calls == 3);  // a new damping, the same length
  for (int step = 0; step < 3; ++step) host.step(0.125f);
  host.step(0.25f);
  host.set_damping(0.25f);
  host.step(0.25f);
  Counted back;
  device.copy_to(back);
  CHECK(test::same_arrays(back, host));
  // copy_from takes another damping (through set_damping): the kept factors are forgotten.
  Counted other = host;
  other.set_damping(0.75f);
  device.copy_from(other);
  calls = 0;
  device.step(Space(), 0.25f);
  CHECK(calls == 1);
  other.step(0.25f);
  device.copy_to(back);
  CHECK(test::same_arrays(back, other));
}

TEST_CASE("view<C> is the array C of the live particles") {
  const Featured host = test::make_scene<Featured>(33, 6);
  DeviceSystem<Featured> device(host);
  const auto lifetime = device.view<Column::lifetime>();
  CHECK(lifetime.extent(0) == 33);
  CHECK(lifetime.data() == device.arrays().lifetime);
  const auto damping = device.view<Column::damping>();
  CHECK(damping.data() == device.arrays().damping);
}

TEST_CASE("a zero duration changes nothing, and a bad one is reported and changes nothing") {
  const Featured host = test::make_scene<Featured>(20, 7);
  DeviceSystem<Featured> device(host);
  device.step(Space(), 0.0);
  Featured back;
  device.copy_to(back);
  CHECK(test::same_arrays(back, host));
#if POINTMASS_CHECKS
  CHECK_THROWS_WITH_AS(device.step(Space(), -0.25),
                       "pointmass: KokkosSystem::step: argument 'duration' = -0.25 must be "
                       "finite and >= 0",
                       std::invalid_argument);
  device.copy_to(back);
  CHECK(test::same_arrays(back, host));
#endif
}

TEST_CASE("a moved-from KokkosSystem is empty: stepping it moves nothing of the new owner's") {
  const Sparks host = test::make_scene<Sparks>(64, 3);
  DeviceSystem<Sparks> source(host);
  DeviceSystem<Sparks> owner(std::move(source));
  CHECK(source.size() == 0);
  CHECK(source.capacity() == 0);
  source.step(Space(), 0.5f);  // nothing to step
  Sparks back;
  owner.copy_to(back);
  CHECK(test::same_arrays(back, host));  // the owner's particles did not move
  // Move assignment too, into a system that had particles of its own.
  DeviceSystem<Sparks> assigned(test::make_scene<Sparks>(10, 4));
  assigned = std::move(owner);
  CHECK(owner.size() == 0);
  owner.step(Space(), 0.5f);
  assigned.copy_to(back);
  CHECK(test::same_arrays(back, host));
  CHECK(assigned.size() == 64);
}
