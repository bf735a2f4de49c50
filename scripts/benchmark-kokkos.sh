#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/kokkos.md (KokkosSystem against ParticleSystem and the memory
# bound): builds benchmarks/kokkos/kokkos_step.cpp
# with -O3 -march=native (Release), runs it with interleaved repetitions, prints the medians
# at 10,000,000 particles (M particle-steps/s) and their ratios as Markdown, and writes them
# into docs/results/kokkos.md between the kokkos markers.
# Usage: scripts/benchmark-kokkos.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3 \
  libtrilinos-kokkos-dev
repetitions=${1:-10}
build="$POINTMASS_ROOT/build/benchmark-kokkos"
build_release "$build" kokkos_step "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/kokkos_step" "$repetitions" 0.5 \
  --benchmark_filter=/10000000/
tables="$build/tables.md"
median_table "$json" "$repetitions" >"$tables" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-kokkos.sh {sys.argv[2]}`), "
      "M particle-steps/s at 10,000,000 particles, `ParticleSystem<R>` (uniform per-second "
      "damping and gravity).\n")
def key(name, real):
    return f"{name.replace('%s', real)}/10000000/real_time"
rows = [("`ParticleSystem<R>::step`, 1 thread", "BM_SystemStep<%s>"),
        ("Kokkos Serial, `KokkosSystem::step`, 1 thread", "BM_Kokkos<%s, Kokkos::Serial>"),
        ("read-modify-write bandwidth (6 arrays), 1 thread", "BM_Bandwidth<%s>"),
        ("`pointmass::step(par_unseq, ...)` (TBB), 2 threads", "BM_SystemParallel<%s>"),
        ("Kokkos OpenMP, `KokkosSystem::step`, 2 threads", "BM_Kokkos<%s, Kokkos::OpenMP>"),
        ("read-modify-write bandwidth (6 arrays), 2 threads", "BM_BandwidthParallel<%s>")]
print("| loop | float | double |\n|---|---|---|")
for label, name in rows:
    cells = [f"{rate[key(name, r)]:,.0f}" if key(name, r) in rate else
             "not measured: this Kokkos has no OpenMP backend" for r in ("float", "double")]
    print(f"| {label} | " + " | ".join(cells) + " |")
def ratio(a, b, real):
    ka, kb = key(a, real), key(b, real)
    return f"{rate[ka] / rate[kb]:.2f}" if ka in rate and kb in rate else "not measured"
print("\n| ratio | float | double |\n|---|---|---|")
for label, a, b in [
        ("Kokkos Serial / `step`", "BM_Kokkos<%s, Kokkos::Serial>", "BM_SystemStep<%s>"),
        ("Kokkos Serial / one-thread bound", "BM_Kokkos<%s, Kokkos::Serial>", "BM_Bandwidth<%s>"),
        ("`par_unseq` / two-thread bound", "BM_SystemParallel<%s>", "BM_BandwidthParallel<%s>"),
        ("Kokkos OpenMP / two-thread bound", "BM_Kokkos<%s, Kokkos::OpenMP>", "BM_BandwidthParallel<%s>"),
        ("Kokkos OpenMP / `par_unseq`", "BM_Kokkos<%s, Kokkos::OpenMP>", "BM_SystemParallel<%s>")]:
    print(f"| {label} | {ratio(a, b, 'float')} | {ratio(a, b, 'double')} |")
PY
publish_table "$POINTMASS_ROOT/docs/results/kokkos.md" kokkos "$tables"
