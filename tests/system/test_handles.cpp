// SPDX-License-Identifier: BSL-1.0
// Handles (system/handles.hpp): found after any removals, dead after clear(), a new table
// after a move, nothing from a free slot or another system's slot, generations that wrap.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::SpawnTag;

TEST_CASE("handles: live handles find their particle, dead ones nothing, after any removals") {
  using Named = ParticleSystem<float, damping::None, position::Euler, features::Lifetime,
                               features::Handles, features::Column<SpawnTag, std::uint32_t>>;
  std::mt19937 random(3);
  Named system;
  std::vector<std::pair<Named::Handle, std::uint32_t>> live, dead;
  std::uint32_t next_id = 0;
  const auto refresh = [&] {  // which handles died (by kill, kill_if or expiry)
    std::vector<std::pair<Named::Handle, std::uint32_t>> still;
    std::set<std::uint32_t> present(system.column<SpawnTag>().begin(),
                                    system.column<SpawnTag>().end());
    for (const auto& entry : live) (present.count(entry.second) ? still : dead).push_back(entry);
    live = still;
  };
  for (int round = 0; round < 150; ++round) {
    for (int n = 0; n < 40; ++n) {
      const std::size_t i = system.spawn({}, {0, 1, 0}, next_id);
      system.set_lifetime(i, float(1 + random() % 20) / 60);
      live.emplace_back(system.handle(i), next_id++);
    }
    for (int n = 0; n < 10 && system.size() > 0; ++n) system.kill(random() % system.size());
    if (round % 5 == 0) {
      system.kill_if([&](std::size_t i) { return system.column<SpawnTag>(i) % 11 == 0; });
    }
    system.step(1.0f / 60);
    refresh();
    for (const auto& [handle, id] : live) {
      const auto index = system.find(handle);
      REQUIRE(index.has_value());
      CHECK(system.column<SpawnTag>(*index) == id);
      CHECK(system.handle(*index) == handle);  // both ways
    }
    for (const auto& entry : dead) REQUIRE_FALSE(system.find(entry.first).has_value());
  }
  CHECK(dead.size() > 3000);
  // Slots were reused (the table is far smaller than the number of particles ever spawned).
  CHECK(pointmass::detail::SystemAccess::handle_table_bytes(system) < std::size_t{next_id} * 8 / 4);
  CHECK_FALSE(system.find(Named::Handle{}).has_value());  // a default handle names nothing
}

TEST_CASE("handles: clear() kills every handle and frees every slot for the next spawns") {
  using Named = ParticleSystem<float, damping::None, position::Euler, features::Handles>;
  Named system;
  std::vector<Named::Handle> cleared;
  std::set<std::uint32_t> cleared_slots;
  for (int i = 0; i < 6; ++i) {
    cleared.push_back(system.spawn_handle(Vector3<float>{float(i), 0, 0}, Vector3<float>{}));
    cleared_slots.insert(cleared.back().slot);
  }
  system.clear();
  for (const auto& handle : cleared) CHECK_FALSE(system.contains(handle));
  std::set<std::uint32_t> slots;
  for (int i = 0; i < 6; ++i) {
    const Named::Handle handle =
        system.spawn_handle(Vector3<float>{float(10 + i), 0, 0}, Vector3<float>{});
    slots.insert(handle.slot);
    CHECK(system.find(handle) == std::optional<std::size_t>{std::size_t(i)});
  }
  CHECK(slots == cleared_slots);  // the freed slots again: the table does not grow
  for (const auto& handle : cleared) CHECK_FALSE(system.contains(handle));  // a new generation
}

TEST_CASE("handles: a moved-from system starts a new table (no free slot it does not have)") {
  // The table's free list once survived a move while its slots did not: the moved-from
  // system's next spawn then took a freed slot number past the end of its empty table.
  using Named = ParticleSystem<double, damping::None, position::Euler, features::Handles>;
  Named source;
  for (int i = 0; i < 8; ++i) source.spawn({double(i), 0, 0}, {});
  source.kill(2);
  source.kill(5);  // slots 2 and 5 on the free list
  const Named::Handle kept = source.handle(0);
  Named target = std::move(source);
  CHECK(target.find(kept) == std::optional<std::size_t>{0});  // the table moved along
  Named assigned;
  assigned = std::move(target);  // move-assigned: the same through the swap
  CHECK(assigned.find(kept) == std::optional<std::size_t>{0});
  for (Named* moved_from : {&source, &target}) {
    REQUIRE(moved_from->size() == 0);
    CHECK(pointmass::detail::SystemAccess::handle_table_bytes(*moved_from) == 0);
    const Named::Handle first =
        moved_from->spawn_handle(Vector3<double>{1, 2, 3}, Vector3<double>{});
    const Named::Handle second =
        moved_from->spawn_handle(Vector3<double>{4, 5, 6}, Vector3<double>{});
    CHECK(first.slot == 0);  // new slots from the start, not the old free list's 5 and 2
    CHECK(second.slot == 1);
    CHECK(moved_from->find(first) == std::optional<std::size_t>{0});
    CHECK(moved_from->find(second) == std::optional<std::size_t>{1});
    CHECK(moved_from->position(1).x == 4.0);
  }
}

TEST_CASE("handles: a free slot answers for nothing, whichever copy issued the handle") {
  // A free slot already holds the generation its next particle will get, and its index is a
  // free-list link: a handle issued by a copy (or before this state was assigned back) with
  // that slot and generation once matched it, and find gave the link as a particle's index.
  using Named = ParticleSystem<float, damping::None, position::Euler, features::Handles>;
  Named live;
  for (int i = 0; i < 4; ++i) live.spawn({float(i), 0, 0}, {});
  live.kill(1);
  live.kill(0);  // slots 1 and 0 free, generation 1 each; two particles left
  const Named snapshot = live;
  const Named::Handle later = live.spawn_handle(Vector3<float>{99, 0, 0}, Vector3<float>{});
  REQUIRE(live.find(later) == std::optional<std::size_t>{2});
  live = snapshot;  // back to before the spawn: `later`'s slot is free again
  REQUIRE(live.size() == 2);
  CHECK_FALSE(live.find(later).has_value());
  CHECK_FALSE(live.contains(later));
  // The same between a system and its copy: the copy's slot is free, its link `none`.
  Named copy = snapshot;
  const Named::Handle other = copy.spawn_handle(Vector3<float>{7, 0, 0}, Vector3<float>{});
  Named original = snapshot;
  original.kill(1);  // its slots: more free ones, none of them `other`'s particle
  CHECK_FALSE(original.find(other).has_value());
  CHECK_FALSE(snapshot.find(other).has_value());
  CHECK(copy.find(other) == std::optional<std::size_t>{2});  // where it was issued, it answers
  // Every particle of the snapshot still answers for itself through its own handle.
  for (std::size_t i = 0; i < snapshot.size(); ++i)
    CHECK(snapshot.find(snapshot.handle(i)) == std::optional<std::size_t>{i});
}

TEST_CASE("handles: a handle from a system with more slots answers for nothing") {
  // `small`'s table is full (16 slots in a capacity of 16): slot 16, the first past its end,
  // must be refused before it is read (AddressSanitizer reports the read otherwise).
  using Named = ParticleSystem<float, damping::None, position::Euler, features::Handles>;
  Named large, small(16);
  for (int i = 0; i < 17; ++i) large.spawn({float(i), 0, 0}, {});
  for (int i = 0; i < 16; ++i) small.spawn({float(i), 0, 0}, {});
  REQUIRE(small.capacity() == 16);
  const Named::Handle foreign = large.handle(16);
  CHECK_FALSE(small.find(foreign).has_value());
  CHECK_FALSE(small.contains(foreign));
}

TEST_CASE("handles: a slot's generation wraps by retiring the slot, old handles stay dead") {
  // 8-bit generations: a slot serves generations 0 .. 254, 255 lives, then is retired.
  using Small =
      ParticleSystem<float, damping::None, position::Euler, features::BasicHandles<std::uint8_t>>;
  Small system;
  system.spawn({9, 9, 9}, {});  // a bystander that lives throughout
  const Small::Handle bystander = system.handle(0);
  std::vector<Small::Handle> old;
  for (int life = 0; life < 1000; ++life) {
    const std::size_t i = system.spawn({float(life), 0, 0}, {});
    const Small::Handle handle = system.handle(i);
    CHECK(system.find(handle) == i);
    for (const Small::Handle& h : old) REQUIRE_FALSE(system.find(h).has_value());
    old.push_back(handle);
    system.kill(i);
  }
  // Every (slot, generation) pair was issued once.
  std::set<std::pair<std::uint32_t, unsigned>> issued;
  for (const Small::Handle& h : old) issued.insert({h.slot, h.generation});
  CHECK(issued.size() == old.size());
  unsigned largest = 0;
  for (const Small::Handle& h : old) largest = std::max(largest, unsigned{h.generation});
  CHECK(largest == 254);
  // The slot the first life took served 255 lives (the number the docs give), then retired.
  const auto lives = std::count_if(old.begin(), old.end(),
                                   [&](const Small::Handle& h) { return h.slot == old[0].slot; });
  CHECK(lives == 255);
  CHECK(system.find(bystander) == std::size_t{0});
}
