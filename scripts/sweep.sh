#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Work-precision diagrams (time to simulate a scene's span against error), for every
# compile-time variant (float and double with every policy pair; float arithmetic with
# double or compensated positions with PerSecond + Euler and Exact + Exact): regenerates the
# plots docs/images/pareto-ballistic.svg, pareto-spring.svg and pareto-far.svg (shown in
# docs/performance.md) and the tables of docs/results/pareto.md between <!-- sweep:begin -->
# and <!-- sweep:end -->.
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
# 3. runs accuracy_comparison on the three scenes at 1/15 .. 1/480 s with those times (CSV in
#    build/sweep/pareto-ballistic.csv, pareto-spring.csv, pareto-far.csv; the time to
#    simulate the span is the time per step times the steps; it marks the Pareto front on
#    that time). The far scene is the ballistic shots launched 1e6 m out along every axis,
#    with the ballistic scene's times (a step costs the same wherever the particle is);
#    accuracy_comparison stops the sweep if the wide positions there lose float's
#    near-origin error (build/sweep/accuracy-far.txt has the check's table);
# 4. draws the work-precision diagrams with gnuplot and writes the tables into
#    docs/results/pareto.md.
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
doc="$POINTMASS_ROOT/docs/results/pareto.md"
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
# The sentence under the tables when the run was not quiet (nothing when it was).
noisy_note "$build/variant_steps.json" cpu_time >"$build/noise.txt"

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

for scene in ballistic spring far; do
  echo "== accuracy: $scene scene at 1/${frame_rates//,/, 1/} s"
  times=$scene
  [[ $scene == far ]] && times=ballistic  # the same shots: a step costs the same far away
  "$build/examples/accuracy_comparison" --scene "$scene" --frame-times "$frame_rates" \
    --times "$build/times-$times.csv" --csv "$build/pareto-$scene.csv" --summary-only \
    >"$build/accuracy-$scene.txt"
done
fi

# The work-precision diagram of a scene: x = error against the scene's own motion, y = time
# to simulate the scene's span with one particle (time per step x steps), both log scales.
# One line per variant through its frame times (halving the step moves a point along its own
# line: up in time, and left in error while the method, not rounding, limits it); colour =
# damping policy, marker = position policy, line and marker fill = precision: float dashed
# with open markers, double solid with filled ones, float with double positions dash-dotted
# with filled markers, float with compensated positions dotted with open markers.
# The Pareto front (no other variant and frame time simulates the span both faster and more
# accurately) is the black staircase; each of its points is numbered and named in the list.
# Opaque white background with dark text and lines, so it reads the same on light and dark
# pages.
plot() {  # plot SCENE TERMINAL OUTPUT
  local scene=$1 terminal=$2 output=$3 csv="$build/pareto-$1.csv"
  python3 - "$csv" "$scene" "$terminal" "$output" >"$build/plot-$scene.gp" <<'PY'
import csv, sys
path, scene, terminal, output = sys.argv[1:5]
rows = list(csv.DictReader(open(path)))
colour = {"None": "#E69F00", "PerFrame": "#56B4E9", "PerSecond": "#009E73",
          "AccelerateThenDamp": "#CC79A7", "Exact": "#0072B2"}
marker = {"Euler": 4, "ConstantAcceleration": 6, "SemiImplicit": 8, "VelocityVerlet": 10,
          "Exact": 12}  # open; +1 filled
marker_name = {"Euler": "square", "ConstantAcceleration": "circle", "SemiImplicit": "triangle",
               "VelocityVerlet": "inverted triangle", "Exact": "diamond"}
title = {"ballistic": "Ballistic shots (pistol, artillery, fireball, laser; 5 s)",
         "spring": "Mass on a spring (period 1 s, undamped and damped; 10 s)",
         "far": "The same ballistic shots launched 1e6 m from the origin (along every axis; 5 s)"}[scene]
# precision: (filled markers, dash type, line width, legend)
style = {"double": (1, 1, 2, "double: solid, filled"),
         "float": (0, 2, 1.5, "float: dashed, open"),
         "float/double-pos": (1, 4, 2, "float/double-pos: dash-dot"),
         "float/compensated-pos": (0, 3, 2, "float/compensated-pos: dotted")}
variants = {}
for r in rows:
    variants.setdefault(r["variant"], []).append(r)
front = sorted((r for r in rows if r["on_front"] == "1"), key=lambda r: float(r["error_m"]))
def rate(r):
    return round(1 / float(r["frame_time"]))
rates = sorted({rate(r) for r in rows})
print(f'set terminal {terminal}')
print(f'set output "{output}"')
print(f'set title "{title}\\ntime to simulate the span against error, frame times 1/{rates[0]} .. '
      f'1/{rates[-1]} s" font ",14"')
print('set xlabel "largest position error against the scene\'s motion (m)"')
print('set ylabel "time to simulate the span, one particle (µs)"')
print('set logscale xy')
print('set format x "10^{%L}"')
print('set grid xtics ytics mxtics mytics lc rgb "#d0d0d0" lw 1')
print('set border lc rgb "#202020"')
print('set key outside right top box opaque spacing 1.15 font ",12"')
print('set rmargin at screen 0.68')
print('set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05')
print('set style textbox opaque fc rgb "white" noborder margins 1,1')
# The front's points, numbered beside them, and listed under the key.
lines = ["Pareto front, most accurate first:"]
for k, r in enumerate(front, 1):
    dy = 0.9 if k % 2 else -0.9  # alternate above and below, so neighbours do not collide
    print(f'set label {k} "{k}" at {r["error_m"]},{r["us_per_span"]} offset 0.9,{dy} front '
          'boxed font ",12" tc rgb "black"')
    lines.append(f'{k:>2}  {r["variant"]}, 1/{rate(r)} s')
print(f'set label {len(front) + 1} "' + "\\n".join(lines) +
      '" at screen 0.695, screen 0.40 left font ",11" tc rgb "black"')
clauses = []
for variant, points in variants.items():
    points.sort(key=lambda r: float(r["frame_time"]), reverse=True)
    real, pair = variant.split(" ", 1)
    damping, position = pair.split(" + ")
    filled, dash, width, _ = style[real]
    clauses.append(
        f"'-' using 1:2 with linespoints lc rgb \"{colour[damping]}\" lw {width} "
        f"dt {dash} pt {marker[position] + filled} ps 1.3 notitle")
# the front: a staircase through its points (most accurate first)
clauses.append("'-' using 1:2 with steps lc rgb \"black\" lw 2.5 title \"Pareto front\"")
for damping, c in colour.items():
    clauses.append(f'NaN with lines lc rgb "{c}" lw 3 title "damping::{damping}"')
for position, pt in marker.items():
    clauses.append(f'NaN with points pt {pt + 1} ps 1.3 lc rgb "#404040" '
                   f'title "position::{position} ({marker_name[position]})"')
for real, (filled, dash, width, legend) in style.items():
    if any(v.split(" ", 1)[0] == real for v in variants):
        clauses.append(f'NaN with linespoints dt {dash} lw {width} pt {6 + filled} '
                       f'lc rgb "#404040" title "{legend}"')
print("plot " + ", \\\n     ".join(clauses))
for variant, points in variants.items():
    for r in points:
        print(f'{r["error_m"]} {r["us_per_span"]}')
    print("e")
for r in front:
    print(f'{r["error_m"]} {r["us_per_span"]}')
print("e")
PY
  gnuplot "$build/plot-$scene.gp"
}

mkdir -p "$images"
for scene in ballistic spring far; do
  plot "$scene" 'svg size 1280,760 dynamic background rgb "white" font "sans,13"' \
    "$images/pareto-$scene.svg"
  echo "wrote $images/pareto-$scene.svg"
  if [[ -n ${SWEEP_PNG:-} ]]; then  # a PNG copy to look at, e.g. SWEEP_PNG=/tmp
    plot "$scene" 'pngcairo size 1280,760 background rgb "white" font "sans,11"' \
      "$SWEEP_PNG/pareto-$scene.png"
  fi
done

echo "== tables into $doc"
POINTMASS_PROCESSOR=$(processor_name) python3 - "$build" "$doc" "$repetitions" <<'PY'
import csv, json, os, sys
build, doc, repetitions = sys.argv[1], sys.argv[2], sys.argv[3]
ns = json.load(open(f"{build}/medians.json"))
context = json.load(open(f"{build}/variant_steps.json"))["context"]
processor = os.environ["POINTMASS_PROCESSOR"]
scenes = ("ballistic", "spring", "far")
rows = {scene: list(csv.DictReader(open(f"{build}/pareto-{scene}.csv"))) for scene in scenes}
# The precisions in the order of the tables; the wide positions' arithmetic is float's.
precisions = ("float", "double", "float/double-pos", "float/compensated-pos")
wide = ("float/double-pos", "float/compensated-pos")

def arithmetic(variant):
    real = variant.split(" ")[0]
    return "float" if real in wide else real

def base(scene, variant):
    # the far scene is the ballistic shots, timed as they are
    return ns[f"hand-written/{'ballistic' if scene == 'far' else scene}/{arithmetic(variant)}"]

def frame(r):
    return f"1/{round(1 / float(r['frame_time']))}"

out = []
out.append(f"Measured by `scripts/sweep.sh {repetitions}` on {processor}, {context.get('num_cpus')} CPUs at "
           f"{context.get('mhz_per_cpu')} MHz (Release, `-O3`), medians of {repetitions} "
           "interleaved repetitions. Absolute times vary between machines and runs; the ratios "
           "(taken within one run) are the figures to compare.\n")
titles = {"ballistic": "Ballistic shots (`pareto-ballistic.svg`)",
          "spring": "Mass on a spring (`pareto-spring.svg`)",
          "far": "Ballistic shots 1e6 m from the origin (`pareto-far.svg`)"}
for scene in scenes:
    out.append(f"## Pareto front: {titles[scene]}\n")
    out.append("Numbered as in the diagram, most accurate first; the front is taken on the time "
               "to simulate the span.\n")
    out.append("| # | variant | frame time (s) | error (m) | ns per step | µs for the span "
               "| / hand-written |")
    out.append("|---|---|---|---|---|---|---|")
    front = sorted((r for r in rows[scene] if r["on_front"] == "1"),
                   key=lambda r: float(r["error_m"]))
    for k, r in enumerate(front, 1):
        t = float(r["ns_per_step"])
        out.append(f"| {k} | {r['variant']} | {frame(r)} | {float(r['error_m']):.2e} | {t:.2f} | "
                   f"{float(r['us_per_span']):.3g} | {t / base(scene, r['variant']):.1f} |")
    out.append("")

out.append("## Error at each frame time (m, largest over the scene)\n")
out.append("The far scene's rows are the policy pairs swept with wide positions (every pair is "
           "in its plot and in `build/sweep/pareto-far.csv`).\n")
rates = sorted({frame(r) for r in rows["ballistic"]}, key=lambda s: int(s[2:]))
wide_pairs = {r["variant"].split(" ", 1)[1] for r in rows["far"] if r["variant"].split(" ")[0] in wide}
out.append("| variant | scene | " + " | ".join(rates) + " |")
out.append("|---|---|" + "---|" * len(rates))
for scene in scenes:
    errors = {}
    for r in rows[scene]:
        if scene == "far" and r["variant"].split(" ", 1)[1] not in wide_pairs:
            continue
        errors.setdefault(r["variant"], {})[frame(r)] = float(r["error_m"])
    for variant, by_rate in errors.items():
        out.append(f"| {variant} | {scene} | " +
                   " | ".join(f"{by_rate[rate]:.1e}" for rate in rates) + " |")
out.append("")

out.append("## Time per particle-step (ns) and ratio to the hand-written loop\n")
out.append("The far scene takes the ballistic column's times. Wide positions are compared "
           "with the float loop (their arithmetic).\n")
out.append("| variant | `Particle`, ballistic | ratio | `Particle`, spring | ratio | "
           "`ParticleSystem`, sparks | ratio |")
out.append("|---|---|---|---|---|---|---|")
for real in precisions:
    hand = [ns[f"hand-written/{s}/{arithmetic(real)}"] for s in ("ballistic", "spring", "sparks")]
    if real not in wide:
        out.append(f"| **hand-written loop, {real}** | {hand[0]:.2f} | 1 | {hand[1]:.2f} | 1 | "
                   f"{hand[2]:.3f} | 1 |")
    for variant in dict.fromkeys(r["variant"] for r in rows["ballistic"]):
        if variant.split(" ")[0] != real:
            continue
        cells = []
        for kind, scene, h in (("Particle", "ballistic", hand[0]), ("Particle", "spring", hand[1]),
                               ("ParticleSystem", "sparks", hand[2])):
            t = ns[f"{kind}/{scene}/{variant}"]
            cells += [f"{t:.3f}" if kind == "ParticleSystem" else f"{t:.2f}", f"{t / h:.1f}"]
        out.append(f"| {variant} | " + " | ".join(cells) + " |")
out.append("")

# The ratios the advice of docs/performance.md ("Which variant for what") quotes, from this
# run's times.
def t(kind, scene, variant):
    return ns[f"{kind}/{scene}/{variant}"]
def pairs(real):
    return [v for v in dict.fromkeys(r["variant"] for r in rows["ballistic"])
            if v.split(" ")[0] == real]
def span(values):
    lo, hi = min(values), max(values)
    return f"{lo:.2f}" if f"{lo:.2f}" == f"{hi:.2f}" else f"{lo:.2f} to {hi:.2f}"
out.append("## The ratios the advice quotes\n")
out.append("The ratios [performance.md](../performance.md#which-variant-for-what) quotes: "
           "each cell divides times of the table above, from this run. The `Particle` rows "
           "take both scenes (the ballistic shots and the spring), the SemiImplicit row every "
           "damping policy too, and the system's row every policy pair: a range is the least "
           "and the greatest of those ratios.\n")
out.append("| ratio of times | float | double |")
out.append("|---|---|---|")
def row(label, f):
    out.append(f"| {label} | " + " | ".join(f(real) for real in ("float", "double")) + " |")
def particle_row(a, b):  # pair a over pair b, Particle, both scenes
    row(f"`Particle`, `{a}` / `{b}`",
        lambda r: span([t("Particle", s, f"{r} {a}") / t("Particle", s, f"{r} {b}")
                        for s in ("ballistic", "spring")]))
particle_row("None + ConstantAcceleration", "None + Euler")
particle_row("Exact + Exact", "PerSecond + ConstantAcceleration")
particle_row("Exact + Exact", "PerSecond + Euler")
row("`Particle`, `D + SemiImplicit` / `D + Euler`, every damping D",
    lambda r: span([t("Particle", s, v.replace("Euler", "SemiImplicit")) / t("Particle", s, v)
                    for s in ("ballistic", "spring") for v in pairs(r) if v.endswith("+ Euler")]))
row("`ParticleSystem`, every pair / the hand-written loop",
    lambda r: span([t("ParticleSystem", "sparks", v) / ns[f"hand-written/sparks/{r}"]
                    for v in pairs(r)]))
row("`ParticleSystem`, `Exact + Exact` / `PerSecond + Euler`",
    lambda r: span([t("ParticleSystem", "sparks", f"{r} Exact + Exact") /
                    t("ParticleSystem", "sparks", f"{r} PerSecond + Euler")]))
out.append("")
out.append("| `float/double-pos PerSecond + Euler` / `double PerSecond + Euler` | ratio of times |")
out.append("|---|---|")
for label, kind, scene in (("`ParticleSystem`, sparks", "ParticleSystem", "sparks"),
                           ("`Particle`, ballistic", "Particle", "ballistic"),
                           ("`Particle`, spring", "Particle", "spring")):
    out.append(f"| {label} | {t(kind, scene, 'float/double-pos PerSecond + Euler') / t(kind, scene, 'double PerSecond + Euler'):.2f} |")
out.append("")
note = open(f"{build}/noise.txt").read().strip()
if note:
    out += [note, ""]

text = open(doc).read()
begin, end = "<!-- sweep:begin -->", "<!-- sweep:end -->"
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(doc, "w").write(head + begin + "\n" + "\n".join(out) + end + tail)
PY
echo "updated $doc"
