// SPDX-License-Identifier: BSL-1.0
// Allocation. A system whose growth fails to allocate is left as it was: the block and the
// handle table grow together or not at all. A step allocates nothing, whatever it does
// (expiry, callbacks, handles, interpolation). This executable replaces operator new, plain
// and aligned (the particle block's), with ones that count and can be told to fail.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <pointmass/particle_system.hpp>

namespace {
bool fail_aligned_allocations = false;
std::size_t allocations = 0;          // every operator new, plain and aligned
std::size_t aligned_allocations = 0;  // the aligned ones: the particle block's
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

void* operator new(std::size_t size, std::align_val_t alignment) {
  ++allocations;
  ++aligned_allocations;
  if (fail_aligned_allocations) throw std::bad_alloc();
  const auto a = static_cast<std::size_t>(alignment);
  if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

TEST_CASE("a growth that fails to allocate changes nothing, handles included") {
  using Named = pointmass::ParticleSystem<float, pointmass::damping::None,
                                          pointmass::position::Euler, pointmass::features::Handles>;
  Named system;
  for (int i = 0; i < 16; ++i) system.spawn({float(i), 0.0f, 0.0f}, {});
  REQUIRE(system.capacity() == 16);  // full: the next spawn grows
  const Named::Handle last = system.handle(15);
  const std::size_t table_bytes = pointmass::detail::SystemAccess::handle_table_bytes(system);
  fail_aligned_allocations = true;
  CHECK_THROWS_AS(system.spawn({99.0f, 0.0f, 0.0f}, {}), std::bad_alloc);
  CHECK_THROWS_AS(system.reserve(1000), std::bad_alloc);
  fail_aligned_allocations = false;
  CHECK(system.size() == 16);
  CHECK(system.capacity() == 16);
  CHECK(pointmass::detail::SystemAccess::handle_table_bytes(system) == table_bytes);
  REQUIRE(system.find(last).has_value());
  CHECK(system.position(*system.find(last)).x == 15.0f);
  // And it grows when memory is there again.
  system.spawn({99.0f, 0.0f, 0.0f}, {});
  CHECK(system.size() == 17);
}

TEST_CASE("spawn_burst: the largest count it allows goes to the allocator, one more is refused") {
  // max_size() - size() more particles is within the limit: the burst asks for a larger
  // block (here refused: std::bad_alloc); one more is past it (std::length_error, before the
  // block is asked for). Neither calls the generator or changes the system.
  using Sparks = pointmass::ParticleSystem<float>;
  Sparks system;
  for (int i = 0; i < 3; ++i) system.spawn({float(i), 0.0f, 0.0f}, {});
  const std::size_t room = Sparks::max_size() - system.size();
  std::size_t generated = 0;
  const auto generator = [&](std::size_t) {
    ++generated;
    return std::tuple{pointmass::Vector3<float>{}, pointmass::Vector3<float>{}};
  };
  // What a burst of `count` throws, and how many blocks it asked for.
  const auto burst = [&](std::size_t count) {
    const std::size_t before = aligned_allocations;
    std::string thrown = "nothing";
    try {
      (void)system.spawn_burst(count, generator);
    } catch (const std::bad_alloc&) {
      thrown = "bad_alloc";
    } catch (const std::length_error&) {
      thrown = "length_error";
    }
    return std::pair{thrown, aligned_allocations - before};
  };
  fail_aligned_allocations = true;
  const auto [within, within_allocations] = burst(room);
  const auto [beyond, beyond_allocations] = burst(room + 1);
  fail_aligned_allocations = false;
  CHECK(within == "bad_alloc");
  CHECK(within_allocations == 1);
  CHECK(beyond == "length_error");
  CHECK(beyond_allocations == 0);
  CHECK(generated == 0);
  CHECK(system.size() == 3);
  CHECK(system.position(2).x == 2.0f);
}

namespace {

// Spawns `count` particles into a system reserved for them, each with what its features
// store (a lifetime from 0.02 s to 0.5 s, so the steps expire some), then counts the
// allocations of `steps` steps of 1/60 s, with an expiry callback when asked.
template <class System>
std::size_t allocations_of_steps(std::size_t count, int steps, bool with_callback) {
  using R = typename System::real;
  using Position = typename System::position_value;
  System system(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t index =
        system.spawn({Position(i), Position(10), Position(0)}, {R(1), R(2), R(0)});
    if constexpr (System::template has<pointmass::features::Lifetime>) {
      system.set_lifetime(index, R(0.02) + R(0.48) * R(i % 17) / R(16));
    }
    if constexpr (System::template has<pointmass::features::ForceAccumulator>)
      system.set_mass(index, R(1) + R(i % 3));
  }
  std::size_t expired = 0;
  const std::size_t before = allocations;
  for (int step = 0; step < steps; ++step) {
    if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
      for (std::size_t i = 0; i < system.size(); ++i) system.add_force(i, {R(0), R(1), R(0)});
    }
    if constexpr (System::template has<pointmass::features::Lifetime>) {
      if (with_callback) {
        system.step(R(1) / R(60), [&](auto&&...) { ++expired; });
        continue;
      }
    }
    system.step(R(1) / R(60));
  }
  const std::size_t made = allocations - before;
  if constexpr (System::template has<pointmass::features::Lifetime>) {
    CHECK(system.size() < count);  // the steps expired particles: expiry is covered
    if (with_callback) CHECK(expired > 0);
  }
  return made;
}

}  // namespace

TEST_CASE("a step allocates nothing: expiry, callbacks, handles and interpolation included") {
  namespace pm = pointmass;
  namespace f = pm::features;
  using Sparks = pm::ParticleSystem<float>;
  using Featured =
      pm::ParticleSystem<float, pm::damping::Exact, pm::position::Exact, f::PerParticleDamping,
                         f::PerParticleAcceleration, f::ForceAccumulator, f::Lifetime>;
  using Game = pm::ParticleSystem<double, pm::damping::PerSecond, pm::position::Euler, f::Lifetime,
                                  f::Interpolation, f::Handles, f::Column<int, float>>;
  using Wide = pm::ParticleSystem<pm::Precision<float, double>, pm::damping::PerSecond,
                                  pm::position::ConstantAcceleration, f::Lifetime>;
  // Sizes on both sides of the alternating walk's lower bound (32 KiB of arrays).
  for (const std::size_t count : {std::size_t{100}, std::size_t{3000}}) {
    CAPTURE(count);
    CHECK(allocations_of_steps<Sparks>(count, 30, false) == 0);
    CHECK(allocations_of_steps<Featured>(count, 30, false) == 0);
    CHECK(allocations_of_steps<Featured>(count, 30, true) == 0);
    CHECK(allocations_of_steps<Game>(count, 30, true) == 0);
    CHECK(allocations_of_steps<Wide>(count, 30, true) == 0);
  }
}

TEST_CASE("the allocation count sees what it is meant to see") {
  // The count is not vacuous: a growth beyond the reserved capacity is counted.
  pointmass::ParticleSystem<float> system(4);
  for (int i = 0; i < 4; ++i) system.spawn({}, {});
  const std::size_t before = allocations;
  system.spawn({}, {});
  CHECK(allocations > before);
}
