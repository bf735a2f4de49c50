#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The main job: integrates the same scenes with every compile-time variant and prints a
# table of error and time per step. Installs what is missing, builds (release), runs.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev  # the example alone, not the test suite's
dir="$POINTMASS_ROOT/build/release"
cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$dir" --target accuracy_comparison --parallel "$(nproc)"
"$dir/examples/accuracy_comparison" "$@"
