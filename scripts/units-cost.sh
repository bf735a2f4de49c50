#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# What the SI particle costs against the plain one, in instructions executed (valgrind's
# count: exact and repeatable, unlike times on a shared machine), with g++ and clang at -O2.
# Prints a table and writes it into docs/units.md between the units-cost markers.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages cmake ninja-build g++ clang libboost-dev doctest-dev valgrind

count() {  # count BINARY ARGS...: instructions executed
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 >/dev/null |
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}

names=("float None + ConstantAcceleration" "float PerSecond + Euler" "double PerSecond + Euler"
       "double Exact + Exact")
table="| variant | compiler | plain (instructions/step) | SI (instructions/step) | SI / plain |
|---|---|---:|---:|---:|"
for compiler in g++ clang++; do
  dir="$POINTMASS_ROOT/build/units-cost-$compiler"
  cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER=$compiler \
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" \
    -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_BENCHMARKS=OFF >/dev/null
  cmake --build "$dir" --target units_instructions >/dev/null
  binary="$dir/tests/units/units_instructions"
  for variant in 0 1 2 3; do
    setup=$(count "$binary" setup $variant)
    plain=$(count "$binary" plain $variant)
    si=$(count "$binary" si $variant)
    steps=$((1024 * 150))
    row=$(awk -v s="$setup" -v p="$plain" -v u="$si" -v n=$steps \
      'BEGIN { printf "%.2f | %.2f | %.4f", (p - s) / n, (u - s) / n, (u - s) / (p - s) }')
    table+=$'\n'"| ${names[$variant]} | $compiler -O2 | $row |"
  done
done
echo "$table"

doc="$POINTMASS_ROOT/docs/units.md"
printf '%s\n' "$table" > "$dir/table.md"
replace_between_markers "$doc" units-cost "$dir/table.md"
echo "updated $doc"
