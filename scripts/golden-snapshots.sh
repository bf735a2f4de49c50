#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates the committed snapshots, tests/system/snapshots/*.snapshot and hashes.txt, which
# the test "snapshot: the committed snapshots load, ..." reads in every configuration: builds
# the batch suite (g++, debug) and runs that test case with POINTMASS_WRITE_GOLDEN set to the
# folder. Run it when the byte format's version or the scene's arithmetic changes on purpose,
# and say why in the commit.
# Usage: scripts/golden-snapshots.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages cmake ninja-build g++ libboost-dev doctest-dev
build="$POINTMASS_ROOT/build/golden-snapshots"
cmake -S "$POINTMASS_ROOT" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DPOINTMASS_TEST_SUITES=system -DPOINTMASS_BUILD_CHECKS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF \
  -DPOINTMASS_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" --target pointmass_system_tests >/dev/null
folder="$POINTMASS_ROOT/tests/system/snapshots"
mkdir -p "$folder"
POINTMASS_WRITE_GOLDEN="$folder" "$build/tests/system/pointmass_system_tests" \
  --test-case="snapshot: the committed snapshots load*"
ls -l "$folder"
