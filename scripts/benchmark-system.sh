#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates docs/results/system.md (ParticleSystem against hand-written loops and the memory
# bound): builds benchmarks/system_step.cpp with -O3 -march=native (Release), runs it with
# interleaved repetitions, prints the medians (M particle-steps/s) and their ratios as
# Markdown, and writes them into docs/results/system.md between the system markers.
# Usage: scripts/benchmark-system.sh [repetitions]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
# What the configuration below needs: Boost (the project's development targets), Google
# Benchmark and TBB (the benchmarks); tests and examples are not configured.
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev python3
repetitions=${1:-15}
build="$POINTMASS_ROOT/build/benchmark-system"
build_release "$build" system_step "${POINTMASS_BENCHMARKS_ONLY[@]}"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
run_repetitions "$json" "$build/benchmarks/system_step" "$repetitions" 0.05
tables="$build/tables.md"
median_table "$json" "$repetitions" >"$tables" <<'PY'
print(f"Machine: {processor}, {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz; "
      f"{ctx.get('library_build_type', '')} Google Benchmark; medians of "
      f"{sys.argv[2]} interleaved repetitions (`scripts/benchmark-system.sh {sys.argv[2]}`), "
      "M particle-steps/s.\n")
for real in ("float", "double"):
    print(f"## {real}\n")
    print("| loop | 1,000 | 100,000 | 10,000,000 |\n|---|---|---|---|")
    rows = [("scalar `Particle` objects (one object per particle)", "BM_Particles<%s>"),
            ("hand-written loop, staggered arrays", "BM_HandStaggered<%s>"),
            ("hand-written loop, alternating direction like the system", "BM_HandAlternating<%s>"),
            ("`ParticleSystem<%s>::step`", "BM_System<Sparks<%s>>"),
            ("read-modify-write bandwidth (6 arrays)", "BM_Bandwidth<%s>"),
            ("`pointmass::step(par_unseq, ...)`, 2 threads", "BM_SystemParallel<Sparks<%s>>"),
            ("read-modify-write bandwidth, 2 threads", "BM_BandwidthParallel<%s>")]
    for label, name in rows:
        cells = []
        for n in ("1000", "100000", "10000000"):
            key = (name % real) + "/" + n + ("/real_time" if "Parallel" in name else "")
            cells.append(f"{rate[key]:,.0f}" if key in rate else "")
        print(f"| {label.replace('%s', real)} | " + " | ".join(cells) + " |")
    def r(a, b, n):
        ka, kb = a % real + "/" + n, b % real + "/" + n
        ka += "/real_time" if "Parallel" in a else ""
        kb += "/real_time" if "Parallel" in b else ""
        return rate[ka] / rate[kb]
    print("\n| ratio | value |\n|---|---|")
    for n in ("1000", "100000", "10000000"):
        print(f"| system / hand-written, {int(n):,} | {r('BM_System<Sparks<%s>>', 'BM_HandStaggered<%s>', n):.2f} |")
    for n in ("1000", "100000", "10000000"):
        print(f"| system / hand-written alternating, {int(n):,} | {r('BM_System<Sparks<%s>>', 'BM_HandAlternating<%s>', n):.2f} |")
    print(f"| system / scalar Particles, 100,000 | {r('BM_System<Sparks<%s>>', 'BM_Particles<%s>', '100000'):.1f} |")
    print(f"| parallel system / parallel bandwidth, 10,000,000 | {r('BM_SystemParallel<Sparks<%s>>', 'BM_BandwidthParallel<%s>', '10000000'):.2f} |")
    print()
print("## Walking forwards and backwards in turn (hand-written loop)\n")
print("| real | particles | arrays (KiB) | alternating / forwards |\n|---|---|---|---|")
for real, n in (("float", "1000"), ("double", "1000"), ("double", "100000"),
                ("double", "300000"), ("double", "1000000"), ("double", "3000000")):
    ratio = (rate[f"BM_HandAlwaysAlternating<{real}>/{n}"] /
             rate[f"BM_HandStaggered<{real}>/{n}"])
    size = 4 if real == "float" else 8
    print(f"| {real} | {int(n):,} | {int(n) * 6 * size / 1024:,.0f} | {ratio:.2f} |")
print()
print("## What each choice costs (float, 100,000 particles)\n")
print("| configuration | M particle-steps/s | / default |\n|---|---|---|")
base = rate["BM_System<Sparks<float>>/100000"]
for label, name in [("default: uniform per-second damping and gravity", "Sparks"),
                    ("damping::None", "Undamped"), ("damping::PerFrame", "PerFrame"),
                    ("+ features::Lifetime", "WithLifetime"), ("+ features::ForceAccumulator", "WithForces"),
                    ("+ features::PerParticleAcceleration", "WithAcceleration"),
                    ("+ features::PerParticleDamping (d^t kept per particle)", "WithDamping")]:
    v = rate[f"BM_System<{name}<float>>/100000"]
    print(f"| {label} | {v:,.0f} | {v / base:.2f} |")
print()
print("## Forces at second order (float, the step alone, with features::ForceAccumulator)\n")
print("| particles | `SemiImplicit` | `VelocityVerlet` | time, Verlet / SemiImplicit |\n|---|---|---|---|")
for n in ("1000", "100000"):
    semi = rate[f"BM_System<ForcesSemiImplicit<float>>/{n}"]
    verlet = rate[f"BM_System<ForcesVelocityVerlet<float>>/{n}"]
    print(f"| {int(n):,} | {semi:,.0f} | {verlet:,.0f} | {semi / verlet:.2f} |")
print("\nBytes stored per particle: SemiImplicit 40, VelocityVerlet 56 (the credited kick and its half step).")
PY
publish_table "$POINTMASS_ROOT/docs/results/system.md" system "$tables"
