#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/large-worlds.md's measured tables: builds examples/large_worlds.cpp
# (the drift of each position precision after 10^6 steps) and benchmarks/large_worlds_step.cpp
# (the batch step's cost, all variants side by side in one run) in Release with
# -march=native, runs them, and writes the tables between the document's markers.
# Usage: scripts/large-worlds.sh [repetitions]      (build tree: $LARGE_WORLDS_BUILD or
#                                                      build/large-worlds)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-9}
build=${LARGE_WORLDS_BUILD:-"$POINTMASS_ROOT/build/large-worlds"}
build_release "$build" "large_worlds large_worlds_step" -DPOINTMASS_BUILD_TESTS=OFF \
  -DPOINTMASS_BUILD_EXAMPLES=ON -DPOINTMASS_BUILD_BENCHMARKS=ON
doc="$POINTMASS_ROOT/docs/results/large-worlds.md"

drift="$build/drift.md"
"$build/examples/large_worlds" >"$drift"
cat "$drift"
replace_between_markers "$doc" drift "$drift"

json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/large_worlds_step" "$repetitions" 0.05
cost="$build/cost.md"
median_table "$json" "$repetitions" >"$cost" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/large-worlds.sh {sys.argv[2]}`); "
      "`ParticleSystem::step`, M particle-steps/s, and the cost against all-float in the same "
      "run (time per step / all-float's). The rows \"by hand\" are the sparks' arithmetic "
      "written as a plain loop over arrays of each storage, in the same run: what the "
      "storage itself costs on this machine, the bound for the rows above them; walking "
      "forwards, or forwards and backwards in turn where the system of that storage does "
      "(\"the system's walk\"). The rows "
      "\"bytes only\" load every byte of each storage, add a constant and store it back: "
      "what the bytes alone cost, with no arithmetic to speak of.\n")
sizes = ("1000", "100000", "10000000")
for kind, title in (("Sparks", "sparks: per-second damping, p + v t, gravity"),
                    ("Shots", "artillery: damping::Exact, position::Exact, gravity")):
    print(f"### {title}\n")
    print("| positions | bytes per particle | 1,000 | 100,000 | 10,000,000 | cost at 1,000 | 100,000 | 10,000,000 |")
    print("|---|---|---|---|---|---|---|---|")
    for variant, label, size in (("Float", "float", 24), ("Double", "`Precision<float, double>`", 36),
                                 ("Compensated", "`Precision<float, Compensated<float>>`", 36)):
        name = f"BM_Step<{variant}{kind}>"
        cells = [f"{rate[f'{name}/{n}']:,.0f}" for n in sizes]
        costs = [f"{rate[f'BM_Step<Float{kind}>/{n}'] / rate[f'{name}/{n}']:.2f}" for n in sizes]
        print(f"| {label} | {size} | " + " | ".join(cells) + " | " + " | ".join(costs) + " |")
    if kind == "Sparks":
        # The bound: the same arithmetic written by hand over plain arrays of each storage;
        # and what the bytes alone cost: every byte loaded, one addition, stored back.
        for benchmark, prefix, pair in (("BM_HandSparks", "by hand", "float pair (Fast2Sum)"),
                                        ("BM_HandSparksLikeSystem", "by hand, the system's walk",
                                         "float pair (Fast2Sum)"),
                                        ("BM_Traffic", "bytes only", "float pair")):
            for variant, label, size in (("float", "float positions", 24), ("double", "double positions", 36),
                                         ("compensated", pair, 36)):
                name = f"{benchmark}<Storage::{variant}_positions>"
                base = f"{benchmark}<Storage::float_positions>"
                cells = [f"{rate[f'{name}/{n}']:,.0f}" for n in sizes]
                costs = [f"{rate[f'{base}/{n}'] / rate[f'{name}/{n}']:.2f}" for n in sizes]
                print(f"| {prefix}: {label} | {size} | " + " | ".join(cells) + " | " + " | ".join(costs) + " |")
        # In the L1 data cache (500 particles): the step, the stores alone and the bytes alone
        # (the floors the bytes set: no step of a storage takes less time than storing its
        # bytes, nor than loading, changing and storing each element it changes).
        l1 = [c["size"] for c in ctx.get("caches", []) if c.get("level") == 1 and c.get("type") == "Data"]
        l1_text = f"{l1[0] // 1024} KiB" if l1 else "the"
        print(f"\nIn the L1 data cache ({l1_text} a core here): 500 particles, 12 KB of float "
              "storage and 18 KB of either wide one. \"Stores alone\" writes every byte the step "
              "changes once, with nothing loaded and nothing computed; \"bytes alone\" loads "
              "each of those elements, adds a constant and stores it back, the least a step "
              "that changes them does. The rows \"a step of ...\" are the cost against the "
              "all-float step of a wide step that took only that time: a floor, since no wide "
              "step takes less.\n")
        print("| at 500 particles | float | `Precision<float, double>` | `Precision<float, Compensated<float>>` |")
        print("|---|---|---|---|")
        storage = {"Float": "float", "Double": "double", "Compensated": "compensated"}
        order = tuple(storage)
        step = {v: rate[f"BM_Step<{v}Sparks>/500"] for v in order}
        stores = {v: rate[f"BM_Stores<Storage::{storage[v]}_positions>/500"] for v in order}
        traffic = {v: rate[f"BM_Traffic<Storage::{storage[v]}_positions>/500"] for v in order}
        print("| step, M particle-steps/s (cost against all-float) | "
              + " | ".join(f"{step[v]:,.0f} ({step['Float'] / step[v]:.2f})" for v in order) + " |")
        print("| stores alone, M particles/s (against all-float's stores) | "
              + " | ".join(f"{stores[v]:,.0f} ({stores['Float'] / stores[v]:.2f})" for v in order) + " |")
        print("| a step of its stores' time alone, cost against the all-float step | "
              + " | ".join(f"{step['Float'] / stores[v]:.2f}" for v in order) + " |")
        print("| bytes alone, M particles/s (against all-float's bytes alone) | "
              + " | ".join(f"{traffic[v]:,.0f} ({traffic['Float'] / traffic[v]:.2f})" for v in order) + " |")
        print("| a step of its bytes' time alone, cost against the all-float step | "
              + " | ".join(f"{step['Float'] / traffic[v]:.2f}" for v in order) + " |")
    print()
PY
publish_table "$doc" cost "$cost"

# The same sparks' steps built for 512-bit vectors, on a processor that has them (AVX-512):
# what the instruction count of the wide steps costs at the width the compiler picks by
# default (256 bits here) against the width that converts 8 floats to doubles at once.
wide="$build/wide-vectors.md"
if grep -qw avx512f /proc/cpuinfo; then
  build512=${LARGE_WORLDS_BUILD_512:-"$POINTMASS_ROOT/build/large-worlds-512"}
  RELEASE_CXX_FLAGS="-march=native -mprefer-vector-width=512" build_release "$build512" \
    large_worlds_step -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF \
    -DPOINTMASS_BUILD_BENCHMARKS=ON
  json512=$(mktemp)
  trap 'rm -f "$json" "$json512"' EXIT
  run_repetitions "$json512" "$build512/benchmarks/large_worlds_step" "$repetitions" 0.05 \
    --benchmark_filter='^BM_Step<.*Sparks>/(500|1000|100000)$'
  median_table "$json512" "$repetitions" "$json" >"$wide" <<'PY'
default = {}
for b in json.load(open(sys.argv[3]))["benchmarks"]:
    if b.get("aggregate_name") == "median":
        default[b["run_name"]] = b["items_per_second"] / 1e6
print(f"The sparks' `ParticleSystem::step` built with `-march=native -mprefer-vector-width=512`, "
      f"medians of {sys.argv[2]} interleaved repetitions (`scripts/large-worlds.sh "
      f"{sys.argv[2]}`), M particle-steps/s and the cost against all-float of the same build; "
      "in brackets, the speed against the default build of the table above (`-march=native`).\n")
print("| positions | 500 | 1,000 | 100,000 | cost at 500 | 1,000 | 100,000 |")
print("|---|---|---|---|---|---|---|")
sizes = ("500", "1000", "100000")
for variant, label in (("Float", "float"), ("Double", "`Precision<float, double>`"),
                       ("Compensated", "`Precision<float, Compensated<float>>`")):
    name = f"BM_Step<{variant}Sparks>"
    cells = [f"{rate[f'{name}/{n}']:,.0f} ({rate[f'{name}/{n}'] / default[f'{name}/{n}']:.2f}x)"
             for n in sizes]
    costs = [f"{rate[f'BM_Step<FloatSparks>/{n}'] / rate[f'{name}/{n}']:.2f}" for n in sizes]
    print(f"| {label} | " + " | ".join(cells) + " | " + " | ".join(costs) + " |")
PY
else
  echo "Not measured: this machine's processor has no 512-bit vectors (AVX-512)." >"$wide"
fi
publish_table "$doc" wide-vectors "$wide"
