#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# What setting a PerSecond or Exact damping value costs (the library's own logarithm) against
# the C library's log and logl, medians of interleaved repetitions in one run
# (benchmarks/damping_set.cpp, clang at -O2), written into docs/results/numerics.md between
# the damping-set markers.
# Usage: scripts/benchmark-damping-set.sh [repetitions]   (default 9)
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages cmake ninja-build clang libboost-dev libbenchmark-dev libtbb-dev
repetitions=${1:-9}
dir="$POINTMASS_ROOT/build/damping-set"
cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" \
  -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$dir" --target damping_set >/dev/null
output=$("$dir/benchmarks/damping_set" --benchmark_repetitions="$repetitions" \
  --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
  --benchmark_color=false | sed 's/\x1b\[[0-9;]*m//g')  # the console reporter's colours
echo "$output"
cpu=$(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1)
{
  echo "Command: \`scripts/benchmark-damping-set.sh $repetitions\` ($cpu, $(nproc) CPUs; clang"
  echo "$(clang++ -dumpversion) at -O2; medians of $repetitions interleaved repetitions, 1,024"
  echo "damping values over [1e-3, 1)):"
  echo
  grep '^|' <<<"$output"
} > "$dir/table.md"
replace_between_markers "$POINTMASS_ROOT/docs/results/numerics.md" damping-set "$dir/table.md"
echo "updated docs/results/numerics.md"
