#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates the renderer hand-off table of docs/results/hand-off.md: builds
# benchmarks/system_step.cpp with -O3 -march=native (Release), runs the step and the copy-out
# rows with interleaved repetitions, and writes their medians (M particles/s) and the time of
# each against the lean step's, measured in the same run, between the handoff markers. Builds
# it with clang as well and runs the lean step, the strided copy and the camera-relative copy
# rows there: the loops whose speed depends on the compiler's choices (a loop left scalar, or
# vectorised with scatter stores), each compiler's rows timed against its own lean step.
# Usage: scripts/benchmark-handoff.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ clang libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-system}"
build_release "$build" system_step -DCMAKE_CXX_COMPILER="$(command -v g++)" "${POINTMASS_BENCHMARKS_ONLY[@]}"
build_release "$build-clang" system_step -DCMAKE_CXX_COMPILER="$(command -v clang++)" \
  "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp) clang_json=$(mktemp)
trap 'rm -f "$json" "$clang_json"' EXIT
run_repetitions "$json" "$build/benchmarks/system_step" "$repetitions" 0.05 \
  --benchmark_filter='BM_System<(Sparks|Interpolated|GameSparks)<float>>/(100000|1000000)$|BM_Copy|BM_Relative'
run_repetitions "$clang_json" "$build-clang/benchmarks/system_step" "$repetitions" 0.05 \
  --benchmark_filter='BM_System<Sparks<float>>/(100000|1000000)$|BM_CopyStrided|BM_Relative'
# One report: clang's runs named "clang:" + name (so the noisy-run note covers both).
python3 - "$json" "$clang_json" <<'PY'
import json, sys
report, other = (json.load(open(name)) for name in sys.argv[1:])
for b in other['benchmarks']:
    b['run_name'] = 'clang:' + b['run_name']
    b['name'] = 'clang:' + b['name']
report['benchmarks'] += other['benchmarks']
json.dump(report, open(sys.argv[1], 'w'))
PY
table="$build/handoff.md"
POINTMASS_COMPILERS="g++ $(g++ -dumpfullversion), clang $(clang++ -dumpversion)" \
  median_table "$json" "$repetitions" >"$table" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-handoff.sh {sys.argv[2]}`), "
      "float, M particles/s; time / step: the row's time over the lean step's, same size and "
      f"compiler ({os.environ['POINTMASS_COMPILERS']}, -O3 -march=native; g++ where the row "
      "names no compiler).\n")
print("| what | 100,000 | time / step | 1,000,000 | time / step |\n|---|---|---|---|---|")
rows = [("`step`, `ParticleSystem<float>` (lean)", "BM_System<Sparks<float>>"),
        ("`step` with `Interpolation`", "BM_System<Interpolated<float>>"),
        ("`step` with `Lifetime`, `Interpolation`, `Handles`, a colour column", "BM_System<GameSparks<float>>"),
        ("`copy_positions` into `float[3 n]`", "BM_CopyPacked<float>"),
        ("`copy_positions` into `{x, y, z}` structs", "BM_CopyVec3<float>"),
        ("`copy_positions`, stride 6 (interleaved vertices)", "BM_CopyStrided<float>"),
        ("`copy_interpolated_positions`, alpha 0.5, `float[3 n]`", "BM_CopyInterpolated<float>"),
        ("`copy_positions(out, camera)`, `Precision<float, double>`, into `Vector3<float>`",
         "BM_Relative<Precision<float, double>>"),
        ("`copy_positions(out, camera)`, `Precision<float, Compensated<float>>`",
         "BM_Relative<Precision<float, Compensated<float>>>"),
        ("`step`, lean, clang", "clang:BM_System<Sparks<float>>"),
        ("`copy_positions`, stride 6, clang", "clang:BM_CopyStrided<float>"),
        ("`copy_positions(out, camera)`, `Precision<float, double>`, clang",
         "clang:BM_Relative<Precision<float, double>>"),
        ("`copy_positions(out, camera)`, `Precision<float, Compensated<float>>`, clang",
         "clang:BM_Relative<Precision<float, Compensated<float>>>")]
for label, name in rows:
    cells = []
    for n in ("100000", "1000000"):
        v = rate.get(f"{name}/{n}")
        compiler = name[:name.index(':') + 1] if ':' in name else ''  # its own lean step
        step = rate.get(f"{compiler}BM_System<Sparks<float>>/{n}")
        cells += [f"{v:,.0f}", f"{step / v:.2f}"] if v and step else ["", ""]
    print(f"| {label} | " + " | ".join(cells) + " |")
PY
publish_table "$POINTMASS_ROOT/docs/results/hand-off.md" handoff "$table"
