#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/snapshot.md (snapshots of a firework batch): builds
# benchmarks/snapshot.cpp with -O3 -march=native (Release), runs it with interleaved
# repetitions, and writes the medians (microseconds of wall time) of save, restore, the
# state hash, the byte format's write and read, 8 steps and a rollback (save, restore, 8
# steps), with the bytes a particle takes in the format, between the snapshot markers.
# Usage: scripts/benchmark-snapshot.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-system}"
build_release "$build" snapshot "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/snapshot" "$repetitions" 0.05
table="$build/snapshot.md"
median_table "$json" "$repetitions" >"$table" <<'PY'
us = {b['run_name']: b['real_time'] / 1e3 for b in data['benchmarks']
      if b.get('aggregate_name') == 'median'}
extra = {b['run_name']: b for b in data['benchmarks'] if b.get('aggregate_name') == 'median'}
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-snapshot.sh {sys.argv[2]}`), "
      "microseconds of wall time on one core, float; a firework batch: `PerSecond`, "
      "`SemiImplicit`, `PerParticleDamping`, `Lifetime`, `Handles`, a 4-byte colour column.\n")
sizes = ("1000", "100000", "1000000")
print("| what | 1,000 | 100,000 | 1,000,000 |\n|---|---|---|---|")
rows = [("`Snapshot::save`", "BM_Save"), ("`Snapshot::restore`", "BM_Restore"),
        ("`state_hash`", "BM_Hash"), ("`save_bytes` (into a vector it reuses)", "BM_WriteBytes"),
        ("`load_bytes`", "BM_ReadBytes"), ("8 steps of 1/60 s", "BM_Step8"),
        ("rollback: save, restore, 8 steps", "BM_Rollback8")]
for label, name in rows:
    print(f"| {label} | " + " | ".join(f"{us[f'{name}/{n}']:,.1f}" for n in sizes) + " |")
write = extra["BM_WriteBytes/100000"]
print(f"\nThe byte format takes {write['bytes_per_particle']:.1f} bytes a particle at 100,000 "
      f"particles (the arrays: `storage_bytes_per_particle` = "
      f"{write['storage_bytes_per_particle']:.0f}; the rest is the handle table).")
PY
publish_table "$POINTMASS_ROOT/docs/results/snapshot.md" snapshot "$table"
