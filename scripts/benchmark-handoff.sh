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
build_release "$build" system_step "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/system_step" "$repetitions" 0.05 \
  --benchmark_filter='BM_System<(Sparks|Interpolated|GameSparks)<float>>/(100000|1000000)$|BM_Copy|BM_Relative'
table="$build/handoff.md"
median_table "$json" "$repetitions" >"$table" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-handoff.sh {sys.argv[2]}`), "
      "float, M particles/s; time / step: the row's time over the lean step's, same size.\n")
print("| what | 100,000 | time / step | 1,000,000 | time / step |\n|---|---|---|---|---|")
rows = [("`step`, `ParticleSystem<float>` (lean)", "BM_System<Sparks<float>>"),
        ("`step` with `Interpolation`", "BM_System<Interpolated<float>>"),
        ("`step` with `Lifetime`, `Interpolation`, `Handles`, a colour column", "BM_System<GameSparks<float>>"),
        ("`copy_positions` into `float[3 n]`", "BM_CopyPacked<float>"),
        ("`copy_positions` into `{x, y, z}` structs", "BM_CopyVec3<float>"),
        ("`copy_positions`, stride 6 (interleaved vertices)", "BM_CopyStrided<float>"),
        ("`copy_interpolated_positions`, alpha 0.5, `float[3 n]`", "BM_CopyInterpolated<float>"),
        ("`positions_relative_to` a camera, `Precision<float, double>`, into `Vector3<float>`",
         "BM_Relative<Precision<float, double>>"),
        ("`positions_relative_to` a camera, `Precision<float, Compensated<float>>`",
         "BM_Relative<Precision<float, Compensated<float>>>")]
for label, name in rows:
    cells = []
    for n in ("100000", "1000000"):
        v = rate.get(f"{name}/{n}")
        step = rate.get(f"BM_System<Sparks<float>>/{n}")
        cells += [f"{v:,.0f}", f"{step / v:.2f}"] if v and step else ["", ""]
    print(f"| {label} | " + " | ".join(cells) + " |")
PY
publish_table "$POINTMASS_ROOT/docs/particle-system.md" handoff "$table"
