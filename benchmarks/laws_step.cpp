// SPDX-License-Identifier: BSL-1.0
// Force laws fused into the step (system.step(t, forces::laws(...)), and its Substeps), on a
// float scene: gravity as the system's acceleration, quadratic drag (k1 0.1, k2 0.01) and a
// spring to the origin (k 4, rest 2), PerSecond damping 0.99, Euler positions, 1/60 s.
//   * BM_ApplyStep: forces::apply for each law, then step(t), the fused step's baseline;
//   * BM_Fused: step(t, laws(drag, spring));
//   * BM_FusedSeparate8: 8 x step(t / 8, laws), the sub-steps' baseline;
//   * BM_Substeps8: step(t, laws, Substeps{8}), one pass;
//   * BM_MemoryRoof: a plain loop over the system's own columns moving the bytes of one fused
//     pass (loads p, v, force and inverse mass; stores p, v and force), bound by memory;
//   * BM_ComputeRoof: the laws' arithmetic (the fused forms of Drag and AnchoredSpring) and
//     the Euler step over 64 particles in local arrays (registers and L1), bound by
//     arithmetic.
// scripts/benchmark-laws.sh runs it and writes the table of docs/performance.md.
// Counters: items_per_second = particle-steps/s (particle-substeps/s with sub-steps);
// array_bytes = the system's arrays (storage_bytes_per_particle x particles).
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "support/bench_refresh.hpp"
#include "support/bench_support.hpp"
#include "support/law_roofs.hpp"

namespace {

using namespace pointmass;
using pointmass_benchmarks::duration;

using R = float;
using System = ParticleSystem<R, damping::PerSecond, position::Euler, features::ForceAccumulator>;

constexpr R kept_per_second = 0.99f;
constexpr Vector3<R> gravity{0.0f, -9.81f, 0.0f};
constexpr std::size_t substeps = 8;

const forces::Drag<R> drag{0.1f, 0.01f};
const forces::AnchoredSpring<R> spring{{0.0f, 0.0f, 0.0f}, 4.0f, 2.0f};

// Particle k's start: spread over a few metres around the anchor at the origin, moving.
Vector3<R> start_position(std::size_t k) {
  const R f = static_cast<R>(k % 1000) / 1000.0f;
  return {3.0f * f - 1.5f, 2.0f - f, f};
}
Vector3<R> start_velocity(std::size_t k) {
  const R f = static_cast<R>(k % 997) / 997.0f;
  return {1.0f - f, 2.0f * f, f - 0.5f};
}
R mass_of(std::size_t k) { return 1.0f + static_cast<R>(k % 5) / 4.0f; }

System scene(std::size_t n) {
  System system(n);
  system.set_acceleration(gravity);
  system.set_damping(kept_per_second);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = system.spawn(start_position(k), start_velocity(k));
    system.set_mass(i, mass_of(k));
  }
  return system;
}

void set_counters(benchmark::State& state, std::size_t per_iteration) {
  const auto n = static_cast<std::size_t>(state.range(0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n * per_iteration));
  state.counters["array_bytes"] = static_cast<double>(n * System::storage_bytes_per_particle);
}

// Runs `frame` once an iteration on the scene, its velocities put back now and then outside
// the timing (drag and damping would bring the particles to rest, support/bench_refresh.hpp).
template <class Frame>
void time_frames(benchmark::State& state, std::size_t per_iteration, Frame&& frame) {
  System system = scene(static_cast<std::size_t>(state.range(0)));
  const pointmass_benchmarks::SavedVelocities<System> start(system);
  std::int64_t steps = 0;
  for (auto _ : state) {
    frame(system);
    benchmark::ClobberMemory();
    pointmass_benchmarks::refresh_now_and_then(state, steps, [&] { start.restore(system); });
  }
  set_counters(state, per_iteration);
}

void BM_ApplyStep(benchmark::State& state) {
  time_frames(state, 1, [](System& system) {
    const R t = duration<R>();
    forces::apply(drag, system, t);
    forces::apply(spring, system, t);
    system.step(t);
  });
}

void BM_Fused(benchmark::State& state) {
  const auto laws = forces::laws(drag, spring);
  time_frames(state, 1, [&](System& system) { system.step(duration<R>(), laws); });
}

void BM_FusedSeparate8(benchmark::State& state) {
  const auto laws = forces::laws(drag, spring);
  time_frames(state, substeps, [&](System& system) {
    const R t = duration<R>() / static_cast<R>(substeps);
    for (std::size_t s = 0; s < substeps; ++s) system.step(t, laws);
  });
}

void BM_Substeps8(benchmark::State& state) {
  const auto laws = forces::laws(drag, spring);
  time_frames(state, substeps,
              [&](System& system) { system.step(duration<R>(), laws, Substeps{substeps}); });
}

#if defined(__clang__)
#define POINTMASS_BENCH_INDEPENDENT _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__)
#define POINTMASS_BENCH_INDEPENDENT _Pragma("GCC ivdep")
#else
#define POINTMASS_BENCH_INDEPENDENT
#endif

// The bytes of one fused pass, with adds: loads p, v, force, inverse mass; stores p, v, force.
void memory_pass(R* __restrict px, R* __restrict py, R* __restrict pz, R* __restrict vx,
                 R* __restrict vy, R* __restrict vz, R* __restrict fx, R* __restrict fy,
                 R* __restrict fz, const R* __restrict w, std::size_t n, R c) {
  POINTMASS_BENCH_INDEPENDENT
  for (std::size_t i = 0; i < n; ++i) {
    const R k = (fx[i] + fy[i]) + (fz[i] + w[i]);
    px[i] += c;
    py[i] += c;
    pz[i] += c;
    vx[i] += k;
    vy[i] += k;
    vz[i] += k;
    fx[i] = c;
    fy[i] = c;
    fz[i] = c;
  }
}

void BM_MemoryRoof(benchmark::State& state) {
  System system = scene(static_cast<std::size_t>(state.range(0)));
  const std::size_t n = system.size();
  R* px = system.column<Column::position_x>().data();
  R* py = system.column<Column::position_y>().data();
  R* pz = system.column<Column::position_z>().data();
  R* vx = system.column<Column::velocity_x>().data();
  R* vy = system.column<Column::velocity_y>().data();
  R* vz = system.column<Column::velocity_z>().data();
  R* fx = system.column<Column::force_x>().data();
  R* fy = system.column<Column::force_y>().data();
  R* fz = system.column<Column::force_z>().data();
  const R* w = std::as_const(system).column<Column::inverse_mass>().data();
  const R c = duration<R>() * 1e-6f;  // small, so the values stay far from overflow
  for (auto _ : state) {
    memory_pass(px, py, pz, vx, vy, vz, fx, fy, fz, w, n, c);
    benchmark::ClobberMemory();
  }
  set_counters(state, 1);
}

void BM_ComputeRoof(benchmark::State& state) {
  pointmass_benchmarks::fused_compute_roof(
      state, drag, spring, gravity, kept_per_second, duration<R>(), [](std::size_t k) {
        return pointmass_benchmarks::RoofStart<R>{start_position(k), start_velocity(k), mass_of(k)};
      });
  state.counters["array_bytes"] = static_cast<double>(static_cast<std::size_t>(state.range(0)) *
                                                      System::storage_bytes_per_particle);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(1000);
  if (std::getenv("POINTMASS_BENCHMARK_SMOKE") == nullptr) b->Arg(100000)->Arg(10000000);
}

BENCHMARK(BM_ApplyStep)->Apply(sizes);
BENCHMARK(BM_Fused)->Apply(sizes);
BENCHMARK(BM_FusedSeparate8)->Apply(sizes);
BENCHMARK(BM_Substeps8)->Apply(sizes);
BENCHMARK(BM_MemoryRoof)->Apply(sizes);
BENCHMARK(BM_ComputeRoof)->Apply(sizes);

}  // namespace

int main(int argc, char** argv) {
  pointmass_benchmarks::set_duration(argc);
  return pointmass_benchmarks::run_benchmarks(argc, argv);
}
