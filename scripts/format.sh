#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Formats every C++ file of the project with clang-format 14 and the project's .clang-format
# (installing clang-format-14 when missing: other versions format differently).
#   scripts/format.sh           format in place
#   scripts/format.sh --check   change nothing; fail, naming each line, where a file differs
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages clang-format-14
cd "$POINTMASS_ROOT"
mapfile -t files < <(find include tests examples benchmarks -type f \
                       \( -name '*.hpp' -o -name '*.cpp' -o -name '*.cu' \) | sort)
case "${1:-}" in
  "") clang-format-14 --style=file -i "${files[@]}" ;;
  --check) clang-format-14 --style=file --dry-run --Werror "${files[@]}" ;;
  *) echo "usage: scripts/format.sh [--check]" >&2; exit 2 ;;
esac
