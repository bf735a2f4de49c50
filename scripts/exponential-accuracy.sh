#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates the accuracy table of the library's exponential in docs/results/numerics.md:
# builds tests/reference/exponential_accuracy.cpp (g++, against __float128), runs it and
# writes its table between the exponential markers.
# Usage: scripts/exponential-accuracy.sh [samples per row]   (default 2000000)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev doctest-dev libbenchmark-dev libtbb-dev
samples=${1:-2000000}
build=${POINTMASS_ACCURACY_BUILD:-"$POINTMASS_ROOT/build/exponential-accuracy"}
cmake -S "$POINTMASS_ROOT" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER=g++ >/dev/null
cmake --build "$build" --target pointmass_exponential_accuracy >/dev/null
table="$build/exponential-table.md"
{
  echo "Command: \`scripts/exponential-accuracy.sh $samples\`."
  echo
  "$build/tests/reference/pointmass_exponential_accuracy" "$samples"
} >"$table"
cat "$table"
replace_between_markers "$POINTMASS_ROOT/docs/results/numerics.md" exponential "$table"
echo "updated docs/results/numerics.md"
