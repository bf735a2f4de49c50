// SPDX-License-Identifier: BSL-1.0
// A system whose growth fails to allocate is left as it was: the block and the handle table
// grow together or not at all (this executable replaces the aligned operator new, which the
// particle block uses, with one that can be told to fail).
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdlib>
#include <new>

#include <pointmass/particle_system.hpp>

namespace {
bool fail_aligned_allocations = false;
}  // namespace

void* operator new(std::size_t size, std::align_val_t alignment) {
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
  const std::size_t table_bytes = system.handle_table_bytes();
  fail_aligned_allocations = true;
  CHECK_THROWS_AS(system.spawn({99.0f, 0.0f, 0.0f}, {}), std::bad_alloc);
  CHECK_THROWS_AS(system.reserve(1000), std::bad_alloc);
  fail_aligned_allocations = false;
  CHECK(system.size() == 16);
  CHECK(system.capacity() == 16);
  CHECK(system.handle_table_bytes() == table_bytes);
  REQUIRE(system.find(last).has_value());
  CHECK(system.position(*system.find(last)).x == 15.0f);
  // And it grows when memory is there again.
  system.spawn({99.0f, 0.0f, 0.0f}, {});
  CHECK(system.size() == 17);
}
