#!/usr/bin/env bash
# Run time against error, for every compile-time variant: regenerates the plots
# docs/images/pareto-ballistic.svg and docs/images/pareto-spring.svg and the section of
# docs/performance.md between <!-- sweep:begin --> and <!-- sweep:end -->.
#
#   scripts/sweep.sh [repetitions]      (default 5; about 2 minutes on 2 cores)
#   SWEEP_PNG=/tmp scripts/sweep.sh     also writes PNG copies of the plots there
#   SWEEP_REDRAW=1 scripts/sweep.sh     redraws plots and tables from the last run's files
#
# 1. builds benchmarks/variant_steps.cpp and examples/accuracy_comparison.cpp (Release,
#    -O3, no -march) in build/sweep;
# 2. runs variant_steps with interleaved repetitions and keeps the medians (JSON in
#    build/sweep/variant_steps.json), then writes the time of each variant per scene as
#    "variant,ns_per_step" (build/sweep/times-ballistic.csv, times-spring.csv);
# 3. runs accuracy_comparison on both scenes at 1/15 .. 1/480 s with those times (CSV in
#    build/sweep/pareto-ballistic.csv, pareto-spring.csv; it marks the Pareto front);
# 4. draws the plots with gnuplot and writes the tables into docs/performance.md.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
# What the configuration below needs: Boost (the development targets and the examples' Odeint
# reference), Google Benchmark and TBB (the benchmarks), gnuplot (the plots).
ensure_packages cmake ninja-build g++ libboost-dev libbenchmark-dev libtbb-dev gnuplot-nox python3
repetitions=${1:-5}
[[ $repetitions =~ ^[1-9][0-9]*$ ]] || { echo "repetitions: a positive integer, not '$repetitions'" >&2; exit 2; }
frame_rates=15,30,60,120,240,480
build="$POINTMASS_ROOT/build/sweep"
images="$POINTMASS_ROOT/docs/images"
doc="$POINTMASS_ROOT/docs/performance.md"
grep -q '<!-- sweep:begin -->' "$doc" && grep -q '<!-- sweep:end -->' "$doc" ||
  { echo "$doc has no <!-- sweep:begin --> ... <!-- sweep:end --> markers" >&2; exit 1; }

if [[ -z ${SWEEP_REDRAW:-} ]]; then  # SWEEP_REDRAW=1: redraw from the last run's files
echo "== build (Release) in $build"
cmake -S "$POINTMASS_ROOT" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_EXAMPLES=ON -DPOINTMASS_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target variant_steps accuracy_comparison --parallel "$(nproc)"

echo "== benchmark: every variant, $repetitions interleaved repetitions"
"$build/benchmarks/variant_steps" --benchmark_repetitions="$repetitions" \
  --benchmark_enable_random_interleaving=true --benchmark_min_time=0.05 \
  --benchmark_report_aggregates_only=true --benchmark_format=json \
  >"$build/variant_steps.json"

# Medians in ns per particle-step: cpu_time (ns per iteration) / particle-steps per iteration.
python3 - "$build" <<'PY'
import json, sys
build = sys.argv[1]
data = json.load(open(f"{build}/variant_steps.json"))
ns = {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") == "median":
        assert b["time_unit"] == "ns", b["time_unit"]
        ns[b["run_name"]] = b["cpu_time"] / b["steps"]
for scene in ("ballistic", "spring"):
    with open(f"{build}/times-{scene}.csv", "w") as out:
        out.write("variant,ns_per_step\n")
        for name, value in ns.items():
            if name.startswith(f"Particle/{scene}/"):
                out.write(f"{name.split('/', 2)[2]},{value:.4f}\n")
json.dump(ns, open(f"{build}/medians.json", "w"), indent=1)
PY

for scene in ballistic spring; do
  echo "== accuracy: $scene scene at 1/${frame_rates//,/, 1/} s"
  "$build/examples/accuracy_comparison" --scene "$scene" --frame-times "$frame_rates" \
    --times "$build/times-$scene.csv" --csv "$build/pareto-$scene.csv" --summary-only \
    >"$build/accuracy-$scene.txt"
done
fi

# Plot: one point per variant and frame time; colour = frame time, shape = position policy,
# open = float, filled = double; the Pareto front as a line, its points numbered and listed.
plot() {  # plot SCENE TERMINAL OUTPUT
  local scene=$1 terminal=$2 output=$3 csv="$build/pareto-$1.csv" title
  case "$scene" in
    ballistic) title="Ballistic shots (5 s): error against time per step, every variant and frame time" ;;
    spring) title="Mass on a spring (10 s): error against time per step, every variant and frame time" ;;
  esac
  python3 - "$csv" "$build/plot-$scene.dat" "$build/plot-$scene.gp" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
shape = {"Euler": 0, "Kinematic": 1, "SemiImplicit": 2, "Exact": 3}
front = sorted((r for r in rows if r["on_front"] == "1"), key=lambda r: float(r["ns_per_step"]))
with open(sys.argv[2], "w") as out:
    # index 0: every row (ns, error, frames per second, shape, filled); index 1: the front
    for r in rows:
        real, rest = r["variant"].split(" ", 1)
        out.write(f'{r["ns_per_step"]} {r["error_m"]} {round(1 / float(r["frame_time"]))} '
                  f'{shape[rest.split(" + ")[1]]} {1 if real == "double" else 0}\n')
    out.write("\n\n")
    for r in front:
        out.write(f'{r["ns_per_step"]} {r["error_m"]}\n')
with open(sys.argv[3], "w") as out:  # numbers beside the front's points, and their list
    lines = ["Pareto front (fastest first):"]
    for k, r in enumerate(front, 1):
        dy = 0.9 if k % 2 else -0.9
        out.write(f'set label "{k}" at {r["ns_per_step"]},{r["error_m"]} offset 0.7,{dy} '
                  'front font ",10" tc rgb "black"\n')
        lines.append(f'{k}  {r["variant"]}, 1/{round(1 / float(r["frame_time"]))} s')
    out.write('set label "' + "\\n".join(lines) +
              '" at screen 0.745, screen 0.40 left font ",10"\n')
PY
  gnuplot <<GNUPLOT
set terminal $terminal
set output "$output"
set title "$title"
set xlabel "time per particle-step (ns, log scale; measured at 1/60 s, the same at every frame time)"
set ylabel "largest position error (m, log scale)"
set logscale xy
set format y "10^{%L}"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top box
set rmargin at screen 0.74
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
colour(rate) = rate == 15 ? 0xd62728 : rate == 30 ? 0xff7f0e : rate == 60 ? 0xbcbd22 : \
               rate == 120 ? 0x2ca02c : rate == 240 ? 0x1f77b4 : 0x9467bd
# point types: open/filled square, circle, triangle, diamond
pt(shape, filled) = (shape == 0 ? 4 : shape == 1 ? 6 : shape == 2 ? 8 : 12) + filled
data = "$build/plot-$scene.dat"
load "$build/plot-$scene.gp"
plot for [rate in "15 30 60 120 240 480"] data index 0 \
       using 1:(\$3 == rate ? \$2 : 1/0):(pt(\$4, \$5)) with points pt variable ps 1.1 \
       lc rgb colour(rate + 0) notitle, \
     data index 1 using 1:2 with steps lw 2 lc rgb "black" title "Pareto front", \
     for [rate in "15 30 60 120 240 480"] NaN with points pt 7 ps 1.1 \
       lc rgb colour(rate + 0) title "frame time 1/".rate." s", \
     NaN with points pt 4 lc rgb "black" title "float (open)", \
     NaN with points pt 5 lc rgb "black" title "double (filled)", \
     NaN with points pt 5 lc rgb "gray" title "Euler: square", \
     NaN with points pt 7 lc rgb "gray" title "Kinematic: circle", \
     NaN with points pt 9 lc rgb "gray" title "SemiImplicit: triangle", \
     NaN with points pt 13 lc rgb "gray" title "Exact: diamond"
GNUPLOT
}

mkdir -p "$images"
for scene in ballistic spring; do
  plot "$scene" 'svg size 1200,650 dynamic font "sans,12"' "$images/pareto-$scene.svg"
  echo "wrote $images/pareto-$scene.svg"
  if [[ -n ${SWEEP_PNG:-} ]]; then  # a PNG copy to look at, e.g. SWEEP_PNG=/tmp
    plot "$scene" 'pngcairo size 1200,650 font "sans,10"' "$SWEEP_PNG/pareto-$scene.png"
  fi
done

echo "== tables into $doc"
python3 - "$build" "$doc" "$repetitions" <<'PY'
import csv, json, sys
build, doc, repetitions = sys.argv[1], sys.argv[2], sys.argv[3]
ns = json.load(open(f"{build}/medians.json"))
context = json.load(open(f"{build}/variant_steps.json"))["context"]
rows = {scene: list(csv.DictReader(open(f"{build}/pareto-{scene}.csv")))
        for scene in ("ballistic", "spring")}

def base(scene, variant):
    return ns[f"hand-written/{scene}/{variant.split(' ')[0]}"]

def frame(r):
    return f"1/{round(1 / float(r['frame_time']))}"

out = []
out.append(f"Measured by `scripts/sweep.sh {repetitions}` on {context.get('num_cpus')} CPUs at "
           f"{context.get('mhz_per_cpu')} MHz (Release, `-O3`), medians of {repetitions} "
           "interleaved repetitions. Absolute times vary between machines and runs; the ratios "
           "(taken within one run) are the figures to compare.\n")
titles = {"ballistic": "Ballistic shots (`pareto-ballistic.svg`)",
          "spring": "Mass on a spring (`pareto-spring.svg`)"}
for scene in ("ballistic", "spring"):
    out.append(f"#### Pareto front: {titles[scene]}\n")
    out.append("| variant | frame time (s) | error (m) | ns per step | / hand-written |")
    out.append("|---|---|---|---|---|")
    front = sorted((r for r in rows[scene] if r["on_front"] == "1"),
                   key=lambda r: float(r["ns_per_step"]))
    for r in front:
        t = float(r["ns_per_step"])
        out.append(f"| {r['variant']} | {frame(r)} | {float(r['error_m']):.2e} | {t:.2f} | "
                   f"{t / base(scene, r['variant']):.1f} |")
    out.append("")

out.append("#### Error at each frame time (m, largest over the scene)\n")
rates = sorted({frame(r) for r in rows["ballistic"]}, key=lambda s: int(s[2:]))
out.append("| variant | scene | " + " | ".join(rates) + " |")
out.append("|---|---|" + "---|" * len(rates))
for scene in ("ballistic", "spring"):
    errors = {}
    for r in rows[scene]:
        errors.setdefault(r["variant"], {})[frame(r)] = float(r["error_m"])
    for variant, by_rate in errors.items():
        out.append(f"| {variant} | {scene} | " +
                   " | ".join(f"{by_rate[rate]:.1e}" for rate in rates) + " |")
out.append("")

out.append("#### Time per particle-step (ns) and ratio to the hand-written loop\n")
out.append("| variant | `Particle`, ballistic | ratio | `Particle`, spring | ratio | "
           "`ParticleSystem`, sparks | ratio |")
out.append("|---|---|---|---|---|---|---|")
for real in ("float", "double"):
    hand = [ns[f"hand-written/{s}/{real}"] for s in ("ballistic", "spring", "sparks")]
    out.append(f"| **hand-written loop, {real}** | {hand[0]:.2f} | 1 | {hand[1]:.2f} | 1 | "
               f"{hand[2]:.3f} | 1 |")
    for variant in dict.fromkeys(r["variant"] for r in rows["ballistic"]):
        if not variant.startswith(real + " "):
            continue
        cells = []
        for kind, scene, h in (("Particle", "ballistic", hand[0]), ("Particle", "spring", hand[1]),
                               ("ParticleSystem", "sparks", hand[2])):
            t = ns[f"{kind}/{scene}/{variant}"]
            cells += [f"{t:.3f}" if kind == "ParticleSystem" else f"{t:.2f}", f"{t / h:.1f}"]
        out.append(f"| {variant} | " + " | ".join(cells) + " |")
out.append("")

text = open(doc).read()
begin, end = "<!-- sweep:begin -->", "<!-- sweep:end -->"
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(doc, "w").write(head + begin + "\n" + "\n".join(out) + end + tail)
PY
echo "updated $doc"
