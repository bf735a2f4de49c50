#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/small-systems.md (small systems at a fixed step): builds
# benchmarks/small_systems.cpp with -O3 -march=native (Release), runs it with interleaved
# repetitions, and writes the medians (ns a step) of `step`, which keeps the damping factors
# of the last step length, and of the same step computing them every time, measured in the
# same run, into docs/results/small-systems.md between the small-systems markers.
# Usage: scripts/benchmark-small-systems.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-system}"
build_release "$build" small_systems "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/small_systems" "$repetitions" 0.05
table="$build/small-systems.md"
median_table "$json" "$repetitions" >"$table" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-small-systems.sh {sys.argv[2]}`), "
      "ns a step of 1/60 s: `step`, and in brackets the same step computing its damping factors "
      "every time, and its time over `step`'s.\n")
sizes = ("16", "64", "256", "512")
print("| system | " + " | ".join(f"{int(n):,} particles" for n in sizes) + " |")
print("|---|" + "---|" * len(sizes))
ns = {name: 1e3 * int(name.rsplit("/", 1)[1]) / r for name, r in rate.items()}
for label, system in (("`ParticleSystem<float>` (PerSecond + Euler, sparks)", "FloatSparks"),
                      ("`ParticleSystem<double>`", "DoubleSparks"),
                      ("`ParticleSystem<Precision<float, double>>`", "FarSparks"),
                      ("`ParticleSystem<float, damping::Exact, position::Exact>`", "FloatShots")):
    cells = []
    for n in sizes:
        kept, afresh = ns[f"BM_Step<{system}>/{n}"], ns[f"BM_Afresh<{system}>/{n}"]
        cells.append(f"{kept:.1f} ({afresh:.1f}, {afresh / kept:.2f})")
    print(f"| {label} | " + " | ".join(cells) + " |")
PY
publish_table "$POINTMASS_ROOT/docs/results/small-systems.md" small-systems "$table"
