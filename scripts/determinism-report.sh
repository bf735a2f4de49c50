#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Which builds reproduce the same trajectories: builds tests/hardening/determinism.cpp with each
# compiler and set of flags below, runs it, and prints its digest over every trajectory and
# whether the scalar and batch paths agreed bit for bit, as a Markdown table that it writes
# into docs/results/numerics.md ("Determinism") between the determinism markers. The 32-bit
# x86 build runs natively; the ARM ones, cross-compiled by clang, under qemu-user.
# Usage: scripts/determinism-report.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_packages g++ clang "${POINTMASS_CROSS_PACKAGES[@]}"
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
  "g++ -std=c++20 -O2 -ffast-math -fno-associative-math"
  "clang++ -std=c++20 -O2 -ffast-math"
  "g++ -m32 -msse2 -mfpmath=sse -std=c++20 -O2"
  "clang++ --target=aarch64-linux-gnu -std=c++20 -O2 -ffp-contract=off"
  "clang++ --target=arm-linux-gnueabihf -march=armv7-a -mfpu=vfpv3-d16 -std=c++20 -O2 -ffp-contract=off"
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
  run=()
  [[ $variant == *--target=aarch64* ]] && run=(qemu-aarch64 -L /usr/aarch64-linux-gnu)
  [[ $variant == *--target=arm-* ]] && run=(qemu-arm -L /usr/arm-linux-gnueabihf)
  output=$("${run[@]}" "$work/determinism" || true)
  digest=$(sed -n 's/^all //p' <<<"$output")
  configurations=$(grep -vc '^all \|^scalar and batch\|^MISMATCH' <<<"$output" || true)
  agree=$(grep -q "agree bit for bit" <<<"$output" && echo "agree" || echo "differ")
  rows+="| \`$variant\` | \`$digest\` | $agree |"$'\n'
done
{
  echo "Command: \`scripts/determinism-report.sh\`, on an x86-64 CPU $fma (g++ $gxx, clang $clangxx,"
  echo "glibc $glibc; the \`--target\` builds run under qemu-user); \"digest\""
  echo "is over all $configurations configurations."
  echo
  echo "| build | digest | scalar and batch |"
  echo "|---|---|---|"
  printf '%s' "$rows"
} >"$table"
publish_table "$POINTMASS_ROOT/docs/results/numerics.md" determinism "$table"
