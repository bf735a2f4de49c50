#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Which builds reproduce the same trajectories: builds tests/hardening/determinism.cpp with each
# compiler and set of flags below, runs it, and prints its digest over every trajectory and
# whether the scalar and batch paths agreed bit for bit, as a Markdown table that it writes
# into docs/numerics.md ("Determinism") between the determinism markers.
# Usage: scripts/determinism-report.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages g++ clang
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variants=(
  "g++ -std=c++20 -O0"
  "g++ -std=c++20 -O2"
  "g++ -std=gnu++20 -O3"
  "clang++ -std=c++20 -O2"
  "clang++ -std=gnu++20 -O3 -ffp-contract=fast"
  "g++ -std=c++20 -O3 -march=native"
  "g++ -std=gnu++20 -O3 -march=native"
  "g++ -std=gnu++20 -O3 -march=native -ffp-contract=off"
  "clang++ -std=c++20 -O3 -march=native"
  "clang++ -std=c++20 -O3 -march=native -ffp-contract=off"
  "g++ -std=c++20 -O2 -ffast-math"
)
fma="without FMA"
grep -qw fma /proc/cpuinfo 2>/dev/null && fma="with FMA"
gxx=$(g++ -dumpfullversion)
clangxx=$(clang++ --version | sed -n '1s/.*version \([0-9.]*\).*/\1/p')
glibc=$(ldd --version | sed -n '1s/.* \([0-9.]*\)$/\1/p')
table="$work/table.md"
rows=""
configurations=""
for variant in "${variants[@]}"; do
  # shellcheck disable=SC2086  # the variant is words
  $variant -I"$POINTMASS_ROOT/include" "$POINTMASS_ROOT/tests/hardening/determinism.cpp" \
    -o "$work/determinism"
  output=$("$work/determinism" || true)
  digest=$(sed -n 's/^all //p' <<<"$output")
  configurations=$(grep -vc '^all \|^scalar and batch\|^MISMATCH' <<<"$output" || true)
  agree=$(grep -q "agree bit for bit" <<<"$output" && echo "agree" || echo "differ")
  rows+="| \`$variant\` | \`$digest\` | $agree |"$'\n'
done
{
  echo "Command: \`scripts/determinism-report.sh\`, on an x86-64 CPU $fma (g++ $gxx, clang $clangxx,"
  echo "glibc $glibc); \"digest\" is over all $configurations configurations."
  echo
  echo "| build | digest | scalar and batch |"
  echo "|---|---|---|"
  printf '%s' "$rows"
} >"$table"
publish_table "$POINTMASS_ROOT/docs/numerics.md" determinism "$table"
