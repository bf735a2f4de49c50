#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates the renderer hand-off table of docs/particle-system.md: builds
# benchmarks/system_step.cpp with -O3 -march=native (Release), runs the step and the copy-out
# rows with interleaved repetitions, and writes their medians (M particles/s) and the time of
# each against the lean step's, measured in the same run, between the handoff markers.
# Usage: scripts/benchmark-handoff.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-system}"
cmake -S "$POINTMASS_ROOT" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_BENCHMARKS=ON \
  -DCMAKE_CXX_FLAGS="-march=native" >/dev/null
cmake --build "$build" --target system_step >/dev/null
json=$(mktemp)
trap 'rm -f "$json"' EXIT
"$build/benchmarks/system_step" --benchmark_repetitions="$repetitions" \
  --benchmark_filter='BM_System<(Sparks|Interpolated|GameSparks)<float>>/(100000|1000000)$|BM_Copy' \
  --benchmark_enable_random_interleaving=true --benchmark_min_time=0.05 \
  --benchmark_report_aggregates_only=true --benchmark_format=json >"$json"
table="$build/handoff.md"
python3 - "$json" "$repetitions" >"$table" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
rate = {b["run_name"]: b["items_per_second"] / 1e6
        for b in data["benchmarks"] if b.get("aggregate_name") == "median"}
ctx = data["context"]
print(f"Machine: {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-handoff.sh {sys.argv[2]}`), "
      "float, M particles/s; time / step: the row's time over the lean step's, same size.\n")
print("| what | 100,000 | time / step | 1,000,000 | time / step |\n|---|---|---|---|---|")
rows = [("`step`, `ParticleSystem<float>` (lean)", "BM_System<Sparks<float>>"),
        ("`step` with `Interpolation`", "BM_System<Interpolated<float>>"),
        ("`step` with `Lifetime`, `Interpolation`, `Handles`, a colour column", "BM_System<GameSparks<float>>"),
        ("`copy_positions` into `float[3 n]`", "BM_CopyPacked<float>"),
        ("`copy_positions` into `{x, y, z}` structs", "BM_CopyVec3<float>"),
        ("`copy_positions`, stride 6 (interleaved vertices)", "BM_CopyStrided<float>"),
        ("`copy_interpolated_positions`, alpha 0.5, `float[3 n]`", "BM_CopyInterpolated<float>")]
for label, name in rows:
    cells = []
    for n in ("100000", "1000000"):
        v = rate.get(f"{name}/{n}")
        step = rate.get(f"BM_System<Sparks<float>>/{n}")
        cells += [f"{v:,.0f}", f"{step / v:.2f}"] if v and step else ["", ""]
    print(f"| {label} | " + " | ".join(cells) + " |")
PY
cat "$table"
replace_between_markers "$POINTMASS_ROOT/docs/particle-system.md" handoff "$table"
echo "updated docs/particle-system.md"
