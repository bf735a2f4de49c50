// SPDX-License-Identifier: BSL-1.0
// What the benchmark programs share: the step length as a run-time value, six staggered
// arrays with the read-modify-write loop over them (the memory bound of a step of six arrays),
// main's run of Google Benchmark with the smoke test's filter, and a console reporter that keeps
// each benchmark's median time for the ratios a program prints after the table.
// bench_parallel.hpp adds the read-modify-write loop on the standard parallel algorithms.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <new>
#include <random>
#include <string>
#include <vector>

namespace pointmass_benchmarks {

// The step, a run-time value from outside every timed loop (set_duration, in main), so the
// compiler cannot fold it; each main checks that a step really moves the particles.
inline float float_duration = 0.0f;
inline double double_duration = 0.0;
template <class R>
R duration() {
  if constexpr (sizeof(R) == sizeof(float)) return float_duration;
  else return double_duration;
}
/// 1/60 s, computed at run time from the program's arguments' count (always >= 1).
inline void set_duration(int argc) {
  float_duration = 1.0f / (60.0f * static_cast<float>(argc > 0 ? 1 : 2));
  double_duration = 1.0 / (60.0 * (argc > 0 ? 1 : 2));
}

// Six arrays in one block, each offset by k x 448 bytes within its page (as a system's).
template <class R>
struct StaggeredArrays {
  /// Values drawn uniformly from [-10, 10].
  explicit StaggeredArrays(std::size_t count) : StaggeredArrays(count, R(0)) {
    std::mt19937 engine(1);
    std::uniform_real_distribution<R> value(R(-10), R(10));
    for (std::size_t k = 0; k < 6; ++k) {
      for (std::size_t i = 0; i < count; ++i) array[k][i] = value(engine);
    }
  }
  /// Every value `value`.
  StaggeredArrays(std::size_t count, R value) {
    const std::size_t span = (count * sizeof(R) + 4095) / 4096 * 4096 + 448;
    block = static_cast<std::byte*>(::operator new (6 * span, std::align_val_t{64}));
    for (std::size_t k = 0; k < 6; ++k) {
      array[k] = reinterpret_cast<R*>(block + k * span);
      std::fill(array[k], array[k] + count, value);
    }
  }
  ~StaggeredArrays() { ::operator delete (block, std::align_val_t{64}); }
  StaggeredArrays(const StaggeredArrays&) = delete;
  StaggeredArrays& operator=(const StaggeredArrays&) = delete;
  std::byte* block = nullptr;
  R* array[6] = {};
};

// Read-modify-write of six arrays: the memory bound of a step of six arrays.
template <class R>
void rmw(R* __restrict a0, R* __restrict a1, R* __restrict a2, R* __restrict a3, R* __restrict a4,
         R* __restrict a5, std::size_t n, R c) {
  for (std::size_t i = 0; i < n; ++i) {
    a0[i] += c, a1[i] += c, a2[i] += c, a3[i] += c, a4[i] += c, a5[i] += c;
  }
}

/// The body of a bandwidth benchmark: rmw over `arrays` (state.range(0) elements each), on one
/// thread. Counts items (particles), not bytes.
template <class R>
void bandwidth(benchmark::State& state, StaggeredArrays<R>& arrays) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const R c = duration<R>();
  R** a = arrays.array;
  for (auto _ : state) {
    rmw(a[0], a[1], a[2], a[3], a[4], a[5], n, c);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// The console table as usual, and each benchmark's median CPU time (or its single run's,
/// without repetitions), by name, for the ratios a program prints after the table. CPU time,
/// not wall time: on a machine shared with other work the wall time also counts the time the
/// process waited.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (median || (run.run_type == Run::RT_Iteration && run.repetitions <= 1)) {
        times_[run.run_name.function_name] = run.GetAdjustedCPUTime();
      }
    }
  }
  /// The median CPU times so far, by benchmark name.
  const std::map<std::string, double>& times() const noexcept { return times_; }

 private:
  std::map<std::string, double> times_;
};

/// main's run: Google Benchmark with the program's arguments, and `smoke_filter` (a
/// --benchmark_filter) as well when POINTMASS_BENCHMARK_SMOKE is set (the smoke tests,
/// benchmarks/CMakeLists.txt). Returns main's exit status.
inline int run_benchmarks(int argc, char** argv, const char* smoke_filter = nullptr) {
  std::vector<char*> arguments(argv, argv + argc);
  std::string filter = smoke_filter != nullptr ? smoke_filter : "";
  if (smoke_filter != nullptr && std::getenv("POINTMASS_BENCHMARK_SMOKE") != nullptr) {
    arguments.push_back(filter.data());
  }
  int count = static_cast<int>(arguments.size());
  benchmark::Initialize(&count, arguments.data());
  if (benchmark::ReportUnrecognizedArguments(count, arguments.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace pointmass_benchmarks
