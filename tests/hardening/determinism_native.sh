#!/bin/sh
# SPDX-License-Identifier: BSL-1.0
# The determinism program built for this machine's vectors and fused multiply-adds
# (-O3 -march=native, no contraction flag) prints the digest of PORTABLE (the build's own
# program: no -march, so no fused multiply-add) and exits 0 (scalar and batch agree).
#   determinism_native.sh COMPILER PORTABLE OUTPUT direct SOURCE FLAGS...
#       compiles SOURCE (determinism.cpp) with COMPILER -O3 -march=native FLAGS
#   determinism_native.sh COMPILER PORTABLE OUTPUT cmake PROJECT GENERATOR EXTENSIONS LIBRARY CMAKE
#       builds the consumer PROJECT (strict_fp/, on pointmass::strict_fp from LIBRARY's
#       source) with CMAKE in the directory OUTPUT, with CMAKE_CXX_EXTENSIONS=EXTENSIONS
#   determinism_native.sh COMPILER - OUTPUT run SOURCE FLAGS...
#       compiles SOURCE with COMPILER -march=native FLAGS and passes as it does
# Skipped (77) where -march=native gives no fused multiply-add.
set -eu
compiler=$1 portable=$2 output=$3 how=$4
shift 4
if ! "$compiler" -march=native -dM -E -x c++ /dev/null | grep -q '__FMA__'; then
  echo "skipped: -march=native has no fused multiply-add here (no __FMA__)"
  exit 77
fi
case "$how" in
  direct)
    source=$1
    shift
    "$compiler" "$@" -O3 -march=native -I"$(dirname "$source")/../../include" "$source" \
      -o "$output"
    program=$output
    ;;
  cmake)
    rm -rf "$output"
    "$5" -S "$1" -B "$output" -G "$2" -DCMAKE_CXX_COMPILER="$compiler" \
      -DCMAKE_CXX_EXTENSIONS="$3" -DPOINTMASS_SOURCE_DIR="$4" >/dev/null
    "$5" --build "$output" >/dev/null
    program=$output/determinism
    ;;
  run)
    source=$1
    shift
    "$compiler" "$@" -march=native -I"$(dirname "$source")/../../include" "$source" \
      -o "$output"
    exec "$output"
    ;;
  *) echo "unknown mode $how" >&2; exit 2 ;;
esac
expected=$("$portable" | grep '^all ')
if ! got=$("$program"); then
  printf '%s\n' "$got" | grep -E '^(MISMATCH|scalar)'
  echo "FAILED: scalar and batch differ at -O3 -march=native"
  exit 1
fi
got=$(printf '%s\n' "$got" | grep '^all ')
echo "portable: $expected; -O3 -march=native: $got"
if [ "$got" != "$expected" ]; then
  echo "FAILED: the digest depends on the flags"
  exit 1
fi
echo "the portable digest, scalar and batch agree"
