#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates the table of docs/performance.md ("Force laws in the step"): builds
# benchmarks/laws_step.cpp with -O3 -march=native (Release; RELEASE_CXX_FLAGS for other
# flags), runs it with interleaved repetitions, and writes, from the medians, for each size:
# the fused step's speed against forces::apply then step, 8 sub-steps in one pass against 8
# separate fused steps, the memory roof (ns a particle for one pass over the arrays), the
# compute roof (ns a particle-step of the laws' arithmetic in registers) and the bound they
# put on what 8 sub-steps can gain, between the laws markers.
# Usage: scripts/benchmark-laws.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-9}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-laws}"
build_release "$build" laws_step "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/laws_step" "$repetitions" 0.05
table="$build/laws.md"
median_table "$json" "$repetitions" >"$table.raw" <<'PY'
median = {b['run_name']: b for b in data['benchmarks'] if b.get('aggregate_name') == 'median'}
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, one "
      "thread; -O3 -march=native; float, gravity, drag and a spring to an anchor, 1/60 s; "
      f"medians of {sys.argv[2]} interleaved repetitions "
      f"(`scripts/benchmark-laws.sh {sys.argv[2]}`).")
print("| particles (arrays) | apply + step | fused | gain (roof) | 8 fused steps | `Substeps{8}` "
      "| gain (roof) | M | C |\n|---|---|---|---|---|---|---|---|---|")
for n in ("1000", "100000", "10000000"):
    ns = {k: 1e3 / rate[f"{k}/{n}"] for k in ("BM_ApplyStep", "BM_Fused", "BM_FusedSeparate8",
                                           "BM_Substeps8", "BM_MemoryRoof", "BM_ComputeRoof")}
    memory, compute = ns["BM_MemoryRoof"], ns["BM_ComputeRoof"]
    fused_roof = ns["BM_ApplyStep"] / max(memory, compute)
    sub_roof = 8 * max(memory, compute) / max(memory, 8 * compute)
    size = median[f"BM_Fused/{n}"]['array_bytes']
    size = f"{size / 1e6:,.0f} MB" if size >= 1e6 else f"{size / 1e3:,.0f} kB"
    print(f"| {int(n):,} ({size}) | {ns['BM_ApplyStep']:.2f} | {ns['BM_Fused']:.2f} "
          f"| {ns['BM_ApplyStep'] / ns['BM_Fused']:.2f} ({fused_roof:.2f}) "
          f"| {ns['BM_FusedSeparate8']:.2f} | {ns['BM_Substeps8']:.2f} "
          f"| {ns['BM_FusedSeparate8'] / ns['BM_Substeps8']:.2f} ({sub_roof:.2f}) "
          f"| {memory:.2f} | {compute:.2f} |")
PY
# A note on a noisy run joins the Machine line: the section's lines stay as many.
python3 - "$table.raw" >"$table" <<'PY'
import sys
text = open(sys.argv[1]).read().rstrip('\n')
table, _, note = text.partition('\n\n')
lines = table.split('\n')
if note:
    lines[0] += ' ' + note.strip()
print('\n'.join(lines))
PY
rm -f "$table.raw"
publish_table "$POINTMASS_ROOT/docs/performance.md" laws "$table"
