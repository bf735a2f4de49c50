#!/usr/bin/env bash
# Regenerates the "reference engine's job" table of docs/performance.md: builds
# benchmarks/engine_step.cpp with -O3 -march=native (Release), runs it with interleaved
# repetitions, prints the medians (M particle-steps/s) and their ratios against the reference
# engine's loop as Markdown, and writes them into docs/performance.md between the engine
# markers.
# Usage: scripts/benchmark-engine.sh [repetitions]   (build directory: $POINTMASS_BENCHMARK_BUILD,
#        default build/benchmark-engine)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build=${POINTMASS_BENCHMARK_BUILD:-"$POINTMASS_ROOT/build/benchmark-engine"}
cmake -S "$POINTMASS_ROOT" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="-march=native" >/dev/null
cmake --build "$build" --target engine_step >/dev/null
json=$(mktemp)
trap 'rm -f "$json"' EXIT
"$build/benchmarks/engine_step" --benchmark_repetitions="$repetitions" \
  --benchmark_enable_random_interleaving=true --benchmark_min_time=0.05 \
  --benchmark_report_aggregates_only=true --benchmark_format=json >"$json"
tables="$build/engine-tables.md"
python3 - "$json" "$repetitions" >"$tables" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
rate = {b["run_name"]: b["items_per_second"] / 1e6
        for b in data["benchmarks"] if b.get("aggregate_name") == "median"}
ctx = data["context"]
print(f"Command: `scripts/benchmark-engine.sh {sys.argv[2]}`. Machine: {ctx.get('num_cpus')} CPUs "
      f"at {ctx.get('mhz_per_cpu')} MHz, one thread; -O3 -march=native; medians of "
      f"{sys.argv[2]} interleaved repetitions. Each cell: M particle-steps/s, and in brackets "
      f"the ratio to the reference engine's loop at the same size and step kind.\n")
sizes = ("1024", "100000", "1000000")
for real in ("float", "double"):
    engine = f"BM_Engine<{real}, false>"
    engine_varying = f"BM_Engine<{real}, true>"
    print(f"### {real}\n")
    print("| loop | 1,024 | 100,000 | 1,000,000 |\n|---|---|---|---|")
    rows = [("reference engine's particles, fixed step (baseline)", engine, engine),
            ("reference engine's particles, step length changing every step", engine_varying, engine_varying),
            ("`Particle<R>` (defaults), fixed step",
             f"BM_Particles<{real}, damping::PerSecond, position::Euler, false>", engine),
            ("`Particle<R>` (defaults), step length changing every step",
             f"BM_Particles<{real}, damping::PerSecond, position::Euler, true>", engine_varying),
            ("`Particle<R, AccelerateThenDamp, Euler>` (bit for bit the engine's), fixed step",
             f"BM_Particles<{real}, damping::AccelerateThenDamp, position::Euler, false>", engine),
            ("`Particle<R, AccelerateThenDamp, Euler>`, step length changing every step",
             f"BM_Particles<{real}, damping::AccelerateThenDamp, position::Euler, true>", engine_varying),
            ("hand-written struct loop, the defaults' arithmetic, fixed step", f"BM_HandStruct<{real}>", engine),
            ("`ParticleSystem`, per-particle damping, acceleration, mass and forces",
             f"BM_System<FullFeatured<{real}>>", engine),
            ("`ParticleSystem<R>` (lean: uniform damping and gravity)", f"BM_System<Lean<{real}>>", engine)]
    for label, name, base in rows:
        cells = []
        for n in sizes:
            key, base_key = f"{name}/{n}", f"{base}/{n}"
            if key in rate and base_key in rate:
                cells.append(f"{rate[key]:,.0f} ({rate[key] / rate[base_key]:.2f}x)")
            else:
                cells.append("")
        print(f"| {label} | " + " | ".join(cells) + " |")
    def ratio(a, b, n):
        return rate[f"{a}/{n}"] / rate[f"{b}/{n}"]
    particles = f"BM_Particles<{real}, damping::PerSecond, position::Euler, false>"
    print("\n| ratio | 1,024 | 100,000 | 1,000,000 | target |\n|---|---|---|---|---|")
    def line(label, a, b, target):
        print(f"| {label} | " + " | ".join(f"{ratio(a, b, n):.2f}" for n in sizes) + f" | {target} |")
    line("`Particle<R>` fixed step / engine", particles, engine,
         ">= 2.5 (float, 1,024 and 100,000); >= 2 (double)")
    line("`Particle<R>` changing step / engine changing step",
         f"BM_Particles<{real}, damping::PerSecond, position::Euler, true>", engine_varying, ">= 1.0")
    line("`Particle<R>` fixed step / hand-written struct loop", particles, f"BM_HandStruct<{real}>",
         ">= 0.97 (time <= 1.03x)")
    line("`Particle<R, AccelerateThenDamp, Euler>` / engine",
         f"BM_Particles<{real}, damping::AccelerateThenDamp, position::Euler, false>", engine, ">= 1.0")
    line("full-featured system / engine", f"BM_System<FullFeatured<{real}>>", engine,
         ">= 10, 4, 2 (float); >= 5, 2 (double)")
    print()
PY
cat "$tables"
replace_between_markers "$POINTMASS_ROOT/docs/performance.md" engine "$tables"
echo "updated docs/performance.md"
