#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/forces.md (Cyclone's force-driven job against pointmass's ways of
# adding forces): builds benchmarks/forces_step.cpp with -O3 -march=native (Release), runs it
# with interleaved repetitions, and writes the medians (M particle-steps/s) and their ratios
# to Cyclone's registry loop at the same size between the forces markers.
# Usage: scripts/benchmark-forces.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build="${POINTMASS_BENCHMARK_BUILD:-$POINTMASS_ROOT/build/benchmark-engine}"
build_release "$build" forces_step "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/forces_step" "$repetitions" 0.05
table="$build/forces.md"
median_table "$json" "$repetitions" >"$table" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, one "
      f"thread; -O3 -march=native; medians of {sys.argv[2]} interleaved repetitions "
      f"(`scripts/benchmark-forces.sh {sys.argv[2]}`). Each cell: M particle-steps/s, and in "
      "brackets the ratio to Cyclone's registry loop at the same size.\n")
sizes = ("1024", "100000", "1000000")
rows = [("Cyclone's particles and force registry (baseline)", "BM_Cyclone"),
        ("`Particle<R>` under `ForceRegistry` (2 registrations each)", "BM_Registry"),
        ("`Particle<R>`, `forces::update_force` for each force, then `integrate`", "BM_UpdateForce"),
        ("`ParticleSystem`: `forces::apply` for each force, then `step`", "BM_SystemApply"),
        ("`ParticleSystem`: `step(t, forces::laws(drag, spring))`", "BM_SystemLaws"),
        ("a hand-written loop: both forces and the step in one pass", "BM_HandFused"),
        ("roof, the registry's memory: its walk with generators that add nothing",
         "BM_RegistryRoof"),
        ("roof, per-particle arithmetic: each `force()` and `integrate`, data in L1",
         "BM_ScalarRoof"),
        ("roof, fused arithmetic: the laws' fused forms and the step, data in L1",
         "BM_FusedRoof")]
for real in ("float", "double"):
    print(f"\n## {real}\n\n| loop | 1,024 | 100,000 | 1,000,000 |\n|---|---|---|---|")
    for label, name in rows:
        cells = []
        for n in sizes:
            v, base = rate.get(f"{name}<{real}>/{n}"), rate.get(f"BM_Cyclone<{real}>/{n}")
            cells.append(f"{v:,.0f} ({v / base:.2f})" if v and base else "")
        print(f"| {label} | " + " | ".join(cells) + " |")
PY
publish_table "$POINTMASS_ROOT/docs/results/forces.md" forces "$table"
