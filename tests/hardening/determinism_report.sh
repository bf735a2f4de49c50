#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Which builds reproduce the same trajectories: builds determinism.cpp with each compiler and
# set of flags below, runs it, and prints its digest over every trajectory and whether the
# scalar and batch paths agreed bit for bit. docs/numerics.md ("Determinism") quotes this.
#   tests/hardening/determinism_report.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
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
fma=no
grep -qw fma /proc/cpuinfo 2>/dev/null && fma=yes
echo "CPU with FMA: $fma"
echo
echo "| build | digest | scalar and batch |"
echo "|---|---|---|"
for variant in "${variants[@]}"; do
  # shellcheck disable=SC2086
  $variant -I"$root/include" "$root/tests/hardening/determinism.cpp" -o "$work/determinism" 2>/dev/null
  output=$("$work/determinism" || true)
  digest=$(sed -n 's/^all //p' <<<"$output")
  agree=$(grep -q "agree bit for bit" <<<"$output" && echo "agree" || echo "differ")
  echo "| \`$variant\` | \`$digest\` | $agree |"
done
