// SPDX-License-Identifier: BSL-1.0
// Snapshots (snapshot.hpp): save, step, restore, step again gives the same bits, in memory and
// through bytes; the state hash follows the state and nothing else; bad bytes are refused,
// named, and change nothing.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <pointmass/detail/hash64.hpp>
#include <pointmass/snapshot.hpp>

#include "snapshot_scenes.hpp"

#if POINTMASS_TEST_XXHASH
#include <xxhash.h>
#endif

using namespace pointmass;
using namespace pointmass::test::snapshots;

namespace {

// What a refused load reported: "argument 'what'" of the last violation.
std::string reported;  // NOLINT: the handler below is a plain function
void record(const ContractViolation& violation) { reported = describe(violation); }

struct RecordedContracts {
  ContractHandler previous = set_contract_handler(&record);
  RecordedContracts() { reported.clear(); }
  RecordedContracts(const RecordedContracts&) = delete;
  RecordedContracts& operator=(const RecordedContracts&) = delete;
  ~RecordedContracts() { set_contract_handler(previous); }
};

template <class System>
System scene(std::uint64_t seed, int steps, Random& random) {
  random = Random{seed};
  System system;
  run_scene(system, random, steps);
  return system;
}

}  // namespace

TEST_CASE_TEMPLATE(
    "snapshot: stepping on from a restore gives the bits of stepping on from "
    "the save",
    System, Fireworks, Rope, Far, Wide, Sparks) {
  Random random{0};
  System system = scene<System>(7, 40, random);
  REQUIRE(system.size() > 20);
  const Snapshot<System> saved(system);
  const Random at_save = random;
  const std::uint64_t hash_at_save = state_hash(system);
  CHECK(saved.hash() == hash_at_save);
  const std::vector<std::byte> bytes = save_bytes(system);

  run_scene(system, random, 30);  // births, deaths (kill and expiry), slots reused
  const auto columns_after = columns_of(system);
  const std::uint64_t hash_after = state_hash(system);
  REQUIRE(hash_after != hash_at_save);

  SUBCASE("in memory") {
    saved.restore(system);
    CHECK(state_hash(system) == hash_at_save);
    random = at_save;
    run_scene(system, random, 30);
    CHECK(columns_of(system) == columns_after);
    CHECK(state_hash(system) == hash_after);
  }
  SUBCASE("through bytes, into another system") {
    System other = scene<System>(99, 10, random);  // with particles of its own
    REQUIRE(load_bytes(other, bytes));
    CHECK(state_hash(other) == hash_at_save);
    random = at_save;
    run_scene(other, random, 30);
    CHECK(columns_of(other) == columns_after);
    CHECK(state_hash(other) == hash_after);
    if constexpr (System::template has<features::Handles>) {
      for (std::size_t i = 0; i < system.size(); ++i) CHECK(other.handle(i) == system.handle(i));
    }
  }
}

TEST_CASE("snapshot: a restore reuses the memory it has") {
  Random random{0};
  Fireworks system = scene<Fireworks>(3, 30, random);
  Snapshot<Fireworks> saved(system);
  system.reserve(4 * system.size());
  const auto* const positions = system.column<Column::position_x>().data();
  for (int round = 0; round < 3; ++round) {
    run_scene(system, random, 5);
    saved.restore(system);
    CHECK(system.column<Column::position_x>().data() == positions);
    saved.save(system);
  }
  CHECK(system.capacity() >= 4 * saved.size());
}

TEST_CASE("snapshot: the hash covers every column and the generations, not the capacity") {
  Random random{0};
  Fireworks system = scene<Fireworks>(5, 30, random);
  const std::uint64_t hash = state_hash(system);
  Fireworks copy = system;
  copy.reserve(10 * system.size());
  CHECK(state_hash(copy) == hash);
  SUBCASE("one bit of any column") {
    using Access = detail::SystemAccess;
    std::size_t column = 0;
    Access::Layout<Fireworks>::for_each_array(Access::arrays(copy), [&](auto* array) {
      auto* byte = reinterpret_cast<unsigned char*>(array + copy.size() / 2);
      *byte = static_cast<unsigned char>(*byte ^ 1u);
      CAPTURE(column);
      CHECK(state_hash(copy) != hash);
      *byte = static_cast<unsigned char>(*byte ^ 1u);
      CHECK(state_hash(copy) == hash);
      ++column;
    });
    CHECK(column == Access::Layout<Fireworks>::array_count);
  }
  SUBCASE("a slot's generation: a particle born and killed") {
    copy.kill(copy.size() - 1);
    Fireworks back = copy;
    back.spawn(system.position(system.size() - 1), system.velocity(system.size() - 1));
    REQUIRE(back.size() == system.size());
    CHECK(state_hash(back) != hash);
  }
}

TEST_CASE("snapshot: a long double's padding never enters the hash") {
  if constexpr (detail::value_bytes<long double> < sizeof(long double)) {
    Random random{0};
    Wide system = scene<Wide>(1, 10, random);
    const std::uint64_t hash = state_hash(system);
    auto* padding = reinterpret_cast<unsigned char*>(system.column<Column::velocity_x>().data()) +
                    detail::value_bytes<long double>;
    *padding = static_cast<unsigned char>(*padding ^ 0xFFu);
    CHECK(state_hash(system) == hash);
    CHECK(save_bytes(system) == save_bytes(Wide(system)));
  }
}

TEST_CASE("snapshot: the hash is XXH64 of the documented bytes") {
  Random random{0};
  const Fireworks system = scene<Fireworks>(11, 30, random);
  const std::vector<std::byte> bytes = save_bytes(system);
  // The hashed part of the body: all but the retention's duration, the free list's head and
  // each slot's link (docs/replay.md).
  std::uint64_t body = 0;
  std::memcpy(&body, bytes.data() + 24, 8);
  std::uint64_t slot_count = 0;
  const std::size_t hashed_without_generations =
      8 + 3 * 4 + system.size() * Fireworks::storage_bytes_per_particle;  // count, acceleration
  std::memcpy(&slot_count, bytes.data() + 32 + hashed_without_generations, 8);
  const auto hashed = static_cast<std::size_t>(hashed_without_generations + 8 + 4 * slot_count);
  CHECK(body == hashed + 4 + 4 + 4 * slot_count);
  detail::Hash64 hash;
  hash.update(bytes.data() + 32, hashed);
  CHECK(hash.digest() == state_hash(system));
#if POINTMASS_TEST_XXHASH
  CHECK(XXH64(bytes.data() + 32, hashed, 0) == state_hash(system));
  // Fed in pieces of every length, the same as XXH64 of the whole.
  for (std::size_t piece = 1; piece < 70; ++piece) {
    detail::Hash64 pieces;
    for (std::size_t at = 0; at < bytes.size(); at += piece) {
      pieces.update(bytes.data() + at, std::min(piece, bytes.size() - at));
    }
    CHECK(pieces.digest() == XXH64(bytes.data(), bytes.size(), 0));
  }
#endif
}

namespace {

// The check value recomputed, so that a change further in passes it.
void reseal(std::vector<std::byte>& bytes) {
  detail::Hash64 hash;
  hash.update(bytes.data(), bytes.size() - 8);
  const std::uint64_t check = hash.digest();
  std::memcpy(bytes.data() + bytes.size() - 8, &check, 8);
}

// load_bytes refuses `bytes`, naming `what`, and `system` keeps its state.
template <class System>
void refused(System& system, const std::vector<std::byte>& bytes, const char* what) {
  const std::uint64_t hash = state_hash(system);
  const auto columns = columns_of(system);
  const RecordedContracts recording;
  CHECK_FALSE(load_bytes(system, bytes));
  CHECK(reported.find(std::string("load_bytes: argument '") + what + "'") != std::string::npos);
  CHECK(state_hash(system) == hash);
  CHECK(columns_of(system) == columns);
}

}  // namespace

TEST_CASE("snapshot: bad bytes are refused, named, and change nothing") {
  Random random{0};
  const Fireworks saved = scene<Fireworks>(13, 30, random);
  const std::vector<std::byte> good = save_bytes(saved);
  Fireworks system = scene<Fireworks>(17, 20, random);
  REQUIRE(state_hash(system) != state_hash(saved));

  SUBCASE("truncated") {
    for (const std::size_t length :
         {std::size_t{0}, std::size_t{39}, good.size() / 2, good.size() - 1}) {
      CAPTURE(length);
      refused(system, std::vector<std::byte>(good.begin(), good.begin() + long(length)),
              "bytes.size()");
    }
  }
  SUBCASE("not a snapshot") {
    std::vector<std::byte> bytes = good;
    bytes[0] = std::byte{'X'};
    refused(system, bytes, "magic");
  }
  SUBCASE("another version") {
    std::vector<std::byte> bytes = good;
    bytes[8] = std::byte{2};
    reseal(bytes);
    refused(system, bytes, "version");
  }
  SUBCASE("another configuration") {
    Random other_random{0};
    refused(system, save_bytes(scene<Sparks>(13, 30, other_random)), "configuration");
    refused(system, save_bytes(scene<Far>(13, 30, other_random)), "configuration");
  }
  SUBCASE("a flipped bit anywhere") {
    for (std::size_t bit = 0; bit < good.size() * 8; bit += 61) {
      std::vector<std::byte> bytes = good;
      bytes[bit / 8] ^= std::byte{static_cast<unsigned char>(1u << (bit % 8))};
      CAPTURE(bit);
      const std::uint64_t hash = state_hash(system);
      const RecordedContracts recording;
      CHECK_FALSE(load_bytes(system, bytes));
      CHECK_FALSE(reported.empty());
      CHECK(state_hash(system) == hash);
    }
  }
  SUBCASE("a count above max_size(), sealed") {
    std::vector<std::byte> bytes = good;
    const std::uint64_t count = std::uint64_t{Fireworks::max_size()} + 1;
    std::memcpy(bytes.data() + 32, &count, 8);
    reseal(bytes);
    refused(system, bytes, "size");
  }
  SUBCASE("a count the bytes do not hold, sealed") {
    std::vector<std::byte> bytes = good;
    const std::uint64_t count = saved.size() + 1;
    std::memcpy(bytes.data() + 32, &count, 8);
    reseal(bytes);
    refused(system, bytes, "size");
  }
  SUBCASE("a handle table that disagrees with the particles, sealed") {
    // The last 4 bytes before the check value are the last slot's link.
    for (const std::uint32_t link : {0u, 1u, 0xFFFFFFFEu}) {
      std::vector<std::byte> bytes = good;
      std::uint32_t old = 0;
      std::memcpy(&old, bytes.data() + bytes.size() - 12, 4);
      if (old == link) continue;
      std::memcpy(bytes.data() + bytes.size() - 12, &link, 4);
      reseal(bytes);
      CAPTURE(link);
      refused(system, bytes, "slots");
    }
  }
  CHECK(load_bytes(system, good));
  CHECK(state_hash(system) == state_hash(saved));
}

TEST_CASE("snapshot: a loaded state steps with its own damping, not the factors kept before") {
  Sparks saved;
  saved.set_damping(0.9f);
  Sparks system;
  system.set_damping(0.3f);  // its kept factors are 0.3's after a step
  for (Sparks* each : {&saved, &system}) {
    each->spawn({0, 0, 0}, {1, 2, 3});
    each->step(1.0f / 60);
  }
  REQUIRE(load_bytes(system, save_bytes(saved)));
  saved.step(1.0f / 60);
  system.step(1.0f / 60);
  CHECK(columns_of(system) == columns_of(saved));
}

// --- golden snapshots: the format and the bits, the same in every configuration -------------
// tests/system/snapshots/NAME.snapshot holds save_bytes after 40 steps of the scene (seed 21),
// and hashes.txt the state hash after 8 more steps from the file's state. Written by
// scripts/golden-snapshots.sh (this test with POINTMASS_WRITE_GOLDEN set to the folder).

namespace {

std::vector<std::byte> read_file(const std::string& path) {
  std::vector<std::byte> bytes;
  if (std::FILE* file = std::fopen(path.c_str(), "rb")) {
    std::byte buffer[4096];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file)) != 0;) {
      bytes.insert(bytes.end(), buffer, buffer + got);
    }
    std::fclose(file);
  }
  return bytes;
}

// The hash after 8 more steps, as 16 hexadecimal digits.
template <class System>
std::string hash_after_more_steps(System system, Random random) {
  run_scene(system, random, 8);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_hash(system)));
  return text;
}

template <class System>
void golden(const char* name, std::string& hashes) {
  Random random{0};
  const System system = scene<System>(21, 40, random);
  const std::vector<std::byte> bytes = save_bytes(system);
  const std::string path = std::string(POINTMASS_SNAPSHOT_DIR) + "/" + name + ".snapshot";
  const std::string line = std::string(name) + " " + hash_after_more_steps(system, random) + "\n";
  if (const char* folder = std::getenv("POINTMASS_WRITE_GOLDEN")) {
    const std::string out = std::string(folder) + "/" + name + ".snapshot";
    std::FILE* file = std::fopen(out.c_str(), "wb");
    REQUIRE(file != nullptr);
    CHECK(std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size());
    std::fclose(file);
    hashes += line;
    return;
  }
  const std::string named = name;
  CAPTURE(named);
  const std::vector<std::byte> committed = read_file(path);
  REQUIRE(!committed.empty());
  CHECK(committed == bytes);  // the same format and the same bits here
  System loaded;
  REQUIRE(load_bytes(loaded, committed));
  hashes += std::string(name) + " " + hash_after_more_steps(loaded, random) + "\n";
}

}  // namespace

TEST_CASE("snapshot: the committed snapshots load, and step on to the committed hashes") {
  std::string hashes;
  golden<Fireworks>("fireworks", hashes);
  golden<Rope>("rope", hashes);
  golden<Far>("far", hashes);
  golden<Sparks>("sparks", hashes);
  const std::string committed_path = std::string(POINTMASS_SNAPSHOT_DIR) + "/hashes.txt";
  if (const char* folder = std::getenv("POINTMASS_WRITE_GOLDEN")) {
    std::FILE* file = std::fopen((std::string(folder) + "/hashes.txt").c_str(), "wb");
    REQUIRE(file != nullptr);
    std::fputs(hashes.c_str(), file);
    std::fclose(file);
    return;
  }
  const std::vector<std::byte> committed = read_file(committed_path);
  CHECK(std::string(reinterpret_cast<const char*>(committed.data()), committed.size()) == hashes);
}
