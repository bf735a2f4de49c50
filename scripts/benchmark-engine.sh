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
build_release "$build" engine_step
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/engine_step" "$repetitions" 0.05
tables="$build/engine-tables.md"
median_table "$json" "$repetitions" >"$tables" <<'PY'
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
            ("hand-written struct loop, the Particle's data and step, fixed step",
             f"BM_HandSameData<{real}>", engine),
            ("hand-written lean struct loop (d^t kept, nothing else), fixed step", f"BM_HandStruct<{real}>", engine),
            ("`ParticleSystem`, per-particle damping, acceleration, mass and forces",
             f"BM_System<FullFeatured<{real}>>", engine),
            ("`ParticleSystem`, the same with uniform damping",
             f"BM_System<UniformDampingFeatured<{real}>>", engine),
            ("`ParticleSystem<R>` (lean: uniform damping and gravity)", f"BM_System<Lean<{real}>>", engine),
            ("memory bound: read-modify-write of the full-featured system's arrays",
             f"BM_BandwidthFullFeatured<{real}>", engine),
            ("memory bound: read-modify-write of a vector of `Particle<R>`'s bytes",
             f"BM_BandwidthBytes<{real}, sizeof(Particle<{real}>)>", engine),
            ("memory bound: read-modify-write of the lean struct's bytes",
             f"BM_BandwidthBytes<{real}, sizeof(HandParticle<{real}>)>", engine)]
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
        key, base_key = f"{a}/{n}", f"{b}/{n}"
        return rate[key] / rate[base_key] if key in rate and base_key in rate else None
    particles = f"BM_Particles<{real}, damping::PerSecond, position::Euler, false>"
    print("\n| ratio | 1,024 | 100,000 | 1,000,000 | target |\n|---|---|---|---|---|")
    def line(label, a, b, target, at=sizes):
        cells = []
        for n in sizes:
            r = ratio(a, b, n) if n in at else None
            cells.append("" if r is None else f"{r:.2f}")
        print(f"| {label} | " + " | ".join(cells) + f" | {target} |")
    line("`Particle<R>` fixed step / engine", particles, engine,
         ">= 2.5 (float, 1,024 and 100,000); >= 2 (double)")
    line("`Particle<R>` changing step / engine changing step",
         f"BM_Particles<{real}, damping::PerSecond, position::Euler, true>", engine_varying, ">= 1.0")
    line("`Particle<R>` fixed step / hand-written loop, the Particle's data and step", particles,
         f"BM_HandSameData<{real}>", ">= 0.97 (time <= 1.03x)")
    line("`Particle<R>` fixed step / hand-written lean struct loop", particles, f"BM_HandStruct<{real}>",
         "(the price of the bytes)")
    line("`Particle<R, AccelerateThenDamp, Euler>` fixed step / engine",
         f"BM_Particles<{real}, damping::AccelerateThenDamp, position::Euler, false>", engine, ">= 1.0")
    line("`Particle<R, AccelerateThenDamp, Euler>` changing step / engine changing step",
         f"BM_Particles<{real}, damping::AccelerateThenDamp, position::Euler, true>", engine_varying,
         "(not a target)")
    line("full-featured system / engine", f"BM_System<FullFeatured<{real}>>", engine,
         ">= 10, 4, 2 (float); >= 5, 2 (double)")
    line("full-featured system / the same with uniform damping", f"BM_System<FullFeatured<{real}>>",
         f"BM_System<UniformDampingFeatured<{real}>>", ">= 0.67 at 100,000 (cost <= 1.5x)")
    big = ("1000000",)
    line("full-featured system / its memory bound", f"BM_System<FullFeatured<{real}>>",
         f"BM_BandwidthFullFeatured<{real}>", "(1 = at the bound)", big)
    line("its memory bound / engine", f"BM_BandwidthFullFeatured<{real}>", engine,
         "(the most the system can reach)", big)
    line("`Particle<R>` fixed step / its memory bound", particles,
         f"BM_BandwidthBytes<{real}, sizeof(Particle<{real}>)>", "(1 = at the bound)", big)
    line("hand-written lean struct loop / its memory bound", f"BM_HandStruct<{real}>",
         f"BM_BandwidthBytes<{real}, sizeof(HandParticle<{real}>)>", "(1 = at the bound)", big)
    line("`Particle<R>`'s bound / the lean struct's bound",
         f"BM_BandwidthBytes<{real}, sizeof(Particle<{real}>)>",
         f"BM_BandwidthBytes<{real}, sizeof(HandParticle<{real}>)>", "(the bytes' ratio)", big)
    print()
PY
publish_table "$POINTMASS_ROOT/docs/performance.md" engine "$tables"
