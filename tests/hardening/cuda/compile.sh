#!/bin/sh
# SPDX-License-Identifier: BSL-1.0
# compile.sh NVCC INCLUDE_DIR SOURCE OUTPUT: compiles SOURCE with nvcc -std=c++20, warnings as
# errors. Exits 77 (CTest: skipped) with the reason when nvcc is missing.
nvcc=$1 include=$2 source=$3 output=$4
if [ -z "$nvcc" ] || [ ! -x "$nvcc" ]; then
  echo "skipped: nvcc not found (install the CUDA toolkit or set POINTMASS_NVCC)"
  exit 77
fi
"$nvcc" --version | tail -n 2
exec "$nvcc" -std=c++20 -Werror all-warnings -Xcompiler -Wall,-Wextra -I"$include" \
  -c "$source" -o "$output"
