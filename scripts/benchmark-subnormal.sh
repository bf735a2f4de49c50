#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/subnormal.md (particles at rest: subnormal velocities): builds
# benchmarks/system_step.cpp with -O3 -march=native (Release), runs the sparks' step with
# normal velocities, with x and z velocities in the subnormal range, and the same under
# FlushDenormals, with interleaved repetitions, and writes the medians (M particle-steps/s)
# and each row's time against the normal velocities', measured in the same run, into
# docs/results/subnormal.md between the subnormal markers.
# Usage: scripts/benchmark-subnormal.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-9}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-system}"
build_release "$build" system_step "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/system_step" "$repetitions" 0.05 \
  --benchmark_filter='BM_System<Sparks<(float|double)>>/(1000|100000)$|BM_Subnormal'
table="$build/subnormal.md"
median_table "$json" "$repetitions" >"$table" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at "
      f"{ctx.get('mhz_per_cpu')} MHz; medians of {sys.argv[2]} interleaved repetitions "
      f"(`scripts/benchmark-subnormal.sh {sys.argv[2]}`); `ParticleSystem<R>::step` (the "
      "sparks: per-second damping 0.9, gravity), M particle-steps/s; time / normal: the row's "
      "time over the step with normal velocities, same size and precision.\n")
sizes = ("1000", "100000")
print("| velocities | float, 1,000 | time / normal | float, 100,000 | time / normal "
      "| double, 1,000 | time / normal | double, 100,000 | time / normal |")
print("|---|---|---|---|---|---|---|---|---|")
rows = [("normal (x and z refreshed before they decay)", "BM_System<Sparks<{r}>>"),
        ("x and z subnormal", "BM_Subnormal<{r}, false>"),
        ("x and z subnormal, steps under `FlushDenormals`", "BM_Subnormal<{r}, true>")]
for label, name in rows:
    cells = []
    for r in ("float", "double"):
        for n in sizes:
            v = rate.get(f"{name.format(r=r)}/{n}")
            normal = rate.get(f"BM_System<Sparks<{r}>>/{n}")
            cells += [f"{v:,.0f}", f"{normal / v:.2f}"] if v and normal else ["", ""]
    print(f"| {label} | " + " | ".join(cells) + " |")
PY
publish_table "$POINTMASS_ROOT/docs/results/subnormal.md" subnormal "$table"
