#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Draws the four ballistic shots (side view: height against range) into
# docs/images/ballistics.svg, from the ballistics example's CSV output, with gnuplot.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev gnuplot-nox
dir="$POINTMASS_ROOT/build/release"
cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$dir" --target ballistics
csv="$dir/ballistics.csv"
"$dir/examples/ballistics" --csv "$csv"
mkdir -p "$POINTMASS_ROOT/docs/images"
out="$POINTMASS_ROOT/docs/images/ballistics.svg"
gnuplot <<GNUPLOT
set terminal svg size 800,400 dynamic font "sans,12"
set output "$out"
set datafile separator ","
set title "Ballistic shots, exact pair, step 1/60 s (side view)"
set xlabel "range z (m)"
set ylabel "height y (m)"
set key top right
set grid
plot for [shot in "pistol artillery fireball laser"] \
  "< grep '^" . shot . ",' $csv" using 5:4 with lines linewidth 2 title shot
GNUPLOT
echo "wrote $out"
