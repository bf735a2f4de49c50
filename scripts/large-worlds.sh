#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/large-worlds.md's measured tables: builds examples/large_worlds.cpp (the
# drift of each position precision after 10^6 steps) and benchmarks/large_worlds_step.cpp (the
# batch step's cost, all variants side by side in one run) in Release with -march=native,
# runs them, and writes the tables between the document's markers.
# Usage: scripts/large-worlds.sh [repetitions]      (build tree: $LARGE_WORLDS_BUILD or
#                                                      build/large-worlds)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-9}
build=${LARGE_WORLDS_BUILD:-"$POINTMASS_ROOT/build/large-worlds"}
build_release "$build" "large_worlds large_worlds_step" -DPOINTMASS_BUILD_TESTS=OFF \
  -DPOINTMASS_BUILD_EXAMPLES=ON -DPOINTMASS_BUILD_BENCHMARKS=ON
doc="$POINTMASS_ROOT/docs/large-worlds.md"

drift="$build/drift.md"
"$build/examples/large_worlds" >"$drift"
cat "$drift"
replace_between_markers "$doc" drift "$drift"

json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/large_worlds_step" "$repetitions" 0.05
cost="$build/cost.md"
median_table "$json" "$repetitions" >"$cost" <<'PY'
print(f"Machine: {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/large-worlds.sh {sys.argv[2]}`); "
      "`ParticleSystem::step`, M particle-steps/s, and the cost against all-float in the same "
      "run (time per step / all-float's). The rows \"by hand\" are the sparks' arithmetic "
      "written as a plain loop over arrays of each storage, in the same run: what the "
      "storage itself costs on this machine, the bound for the rows above them. The rows "
      "\"bytes only\" load every byte of each storage, add a constant and store it back: "
      "what the bytes alone cost, with no arithmetic to speak of.\n")
sizes = ("1000", "100000", "10000000")
targets = {"Double": ("<= 1.15", "<= 1.50", "<= 1.50"),
           "Compensated": ("<= 1.30", "<= 1.50", "<= 1.50")}
for kind, title in (("Sparks", "sparks: per-second damping, p + v t, gravity"),
                    ("Shots", "artillery: damping::Exact, position::Exact, gravity")):
    print(f"### {title}\n")
    print("| positions | bytes per particle | 1,000 | 100,000 | 10,000,000 | cost at 1,000 | 100,000 | 10,000,000 | target |")
    print("|---|---|---|---|---|---|---|---|---|")
    for variant, label, size in (("Float", "float (today)", 24), ("Double", "`Precision<float, double>`", 36),
                                 ("Compensated", "`Precision<float, Compensated<float>>`", 36)):
        name = f"BM_Step<{variant}{kind}>"
        cells = [f"{rate[f'{name}/{n}']:,.0f}" for n in sizes]
        costs = [f"{rate[f'BM_Step<Float{kind}>/{n}'] / rate[f'{name}/{n}']:.2f}" for n in sizes]
        target = " / ".join(targets[variant]) if variant in targets and kind == "Sparks" else ""
        print(f"| {label} | {size} | " + " | ".join(cells) + " | " + " | ".join(costs) + f" | {target} |")
    if kind == "Sparks":
        # The bound: the same arithmetic written by hand over plain arrays of each storage;
        # and what the bytes alone cost: every byte loaded, one addition, stored back.
        for benchmark, prefix, pair, note in (("BM_HandSparks", "by hand", "float pair (Fast2Sum)", "the bound"),
                                              ("BM_Traffic", "bytes only", "float pair", "the bytes alone")):
            for variant, label, size in (("float", "float positions", 24), ("double", "double positions", 36),
                                         ("compensated", pair, 36)):
                name = f"{benchmark}<Storage::{variant}_positions>"
                base = f"{benchmark}<Storage::float_positions>"
                cells = [f"{rate[f'{name}/{n}']:,.0f}" for n in sizes]
                costs = [f"{rate[f'{base}/{n}'] / rate[f'{name}/{n}']:.2f}" for n in sizes]
                print(f"| {prefix}: {label} | {size} | " + " | ".join(cells) + " | " + " | ".join(costs) + f" | {note} |")
        # The floor in cache: a step stores every byte it changes, 24 a particle in all-float
        # and 36 in either wide storage: 6 and 9 stores of 32 bytes for 8 particles.
        mhz = float(ctx.get('mhz_per_cpu'))
        cycles = {v: 8 * mhz / rate[f"BM_Step<{v}Sparks>/1000"] for v in ("Float", "Double", "Compensated")}
        print(f"\nIn cycles at {mhz:,.0f} MHz, from the rates above: the all-float step of 1,000 "
              f"sparks takes {cycles['Float']:.1f} cycles per 8 particles, which store 6 vectors "
              f"of 32 bytes; double positions take {cycles['Double']:.1f} and compensated "
              f"{cycles['Compensated']:.1f}, for 9 stores each.")
    print()
PY
publish_table "$doc" cost "$cost"
