// SPDX-License-Identifier: BSL-1.0
// Snapshots of a firework batch (lifetimes, per-particle damping, handles, a user column):
// in memory (Snapshot::save, restore), the state hash, the byte format's write and read, 8
// steps, and a rollback (save, restore, 8 steps replayed) against the 8 steps alone.
// scripts/benchmark-snapshot.sh runs it and writes docs/results/snapshot.md.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <pointmass/particle_system.hpp>
#include <pointmass/snapshot.hpp>

#include "support/bench_support.hpp"

namespace {

using namespace pointmass;
using pointmass_benchmarks::duration;

struct Colour {};
using Fireworks =
    ParticleSystem<float, damping::PerSecond, position::SemiImplicit, features::PerParticleDamping,
                   features::Lifetime, features::Handles, features::Column<Colour, std::uint32_t>>;

// n particles that outlive any benchmark (a step removes none), each damped on its own.
Fireworks fireworks(std::size_t n) {
  Fireworks system(n);
  for (std::size_t k = 0; k < n; ++k) {
    const float f = static_cast<float>(k % 1000) / 1000.0f;
    const std::size_t i =
        system.spawn({f, 2 * f, 3 * f}, {1 - f, 10 * f, f - 0.5f}, static_cast<std::uint32_t>(k));
    system.set_damping(i, 0.5f + 0.4f * f);
    system.set_lifetime(i, 1e6f);
  }
  system.step(duration<float>());  // the damping column's retention kept for this length
  return system;
}

void set_counters(benchmark::State& state, std::size_t n) {
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void BM_Save(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Fireworks system = fireworks(n);
  Snapshot<Fireworks> saved(system);
  for (auto _ : state) {
    saved.save(system);
    benchmark::ClobberMemory();
  }
  set_counters(state, n);
}

void BM_Restore(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Fireworks system = fireworks(n);
  const Snapshot<Fireworks> saved(system);
  for (auto _ : state) {
    saved.restore(system);
    benchmark::ClobberMemory();
  }
  set_counters(state, n);
}

void BM_Hash(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Fireworks system = fireworks(n);
  for (auto _ : state) benchmark::DoNotOptimize(state_hash(system));
  set_counters(state, n);
}

void BM_WriteBytes(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Fireworks system = fireworks(n);
  std::vector<std::byte> bytes = save_bytes(system);
  for (auto _ : state) {
    save_bytes(system, bytes);
    benchmark::DoNotOptimize(bytes.data());
  }
  set_counters(state, n);
  state.counters["bytes_per_particle"] = static_cast<double>(bytes.size()) / double(n);
  state.counters["storage_bytes_per_particle"] = Fireworks::storage_bytes_per_particle;
}

void BM_ReadBytes(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Fireworks system = fireworks(n);
  const std::vector<std::byte> bytes = save_bytes(system);
  for (auto _ : state) {
    if (!load_bytes(system, bytes)) state.SkipWithError("load_bytes refused its own bytes");
    benchmark::ClobberMemory();
  }
  set_counters(state, n);
}

void BM_Step8(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Fireworks system = fireworks(n);
  for (auto _ : state) {
    for (int k = 0; k < 8; ++k) system.step(duration<float>());
    benchmark::ClobberMemory();
  }
  set_counters(state, n);
}

// A rollback: save the frame, restore it, replay 8 steps.
void BM_Rollback8(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Fireworks system = fireworks(n);
  Snapshot<Fireworks> saved(system);
  for (auto _ : state) {
    saved.save(system);
    saved.restore(system);
    for (int k = 0; k < 8; ++k) system.step(duration<float>());
    benchmark::ClobberMemory();
  }
  set_counters(state, n);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(100000);
  if (std::getenv("POINTMASS_BENCHMARK_SMOKE") == nullptr) b->Arg(1000)->Arg(1000000);
}

BENCHMARK(BM_Save)->Apply(sizes);
BENCHMARK(BM_Restore)->Apply(sizes);
BENCHMARK(BM_Hash)->Apply(sizes);
BENCHMARK(BM_WriteBytes)->Apply(sizes);
BENCHMARK(BM_ReadBytes)->Apply(sizes);
BENCHMARK(BM_Step8)->Apply(sizes);
BENCHMARK(BM_Rollback8)->Apply(sizes);

// Before timing: what the rows time keeps the bits (a restore and a load give the saved
// state, and the 8 replayed steps those of 8 steps from it).
bool same_state() {
  Fireworks system = fireworks(1000);
  const Snapshot<Fireworks> saved(system);
  const std::vector<std::byte> bytes = save_bytes(system);
  Fireworks stepped = system;
  for (int k = 0; k < 8; ++k) stepped.step(duration<float>());
  saved.restore(stepped);
  Fireworks loaded;
  return state_hash(stepped) == state_hash(system) && load_bytes(loaded, bytes) &&
         state_hash(loaded) == state_hash(system) && saved.hash() == state_hash(system);
}

}  // namespace

int main(int argc, char** argv) {
  pointmass_benchmarks::set_duration(argc);
  if (!same_state()) {
    std::fputs("snapshot: a restore or a load does not give the saved state\n", stderr);
    return EXIT_FAILURE;
  }
  return pointmass_benchmarks::run_benchmarks(argc, argv);
}
