#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The whole test suite, as CI runs it: installs what is missing, then builds and runs every
# test with g++ (debug, contract checks on), with clang (release), and under AddressSanitizer
# and UndefinedBehaviorSanitizer (the behaviour tests; the tests of the build itself and the
# Kokkos step's bit-for-bit comparisons run in the other two). The Kokkos comparisons run for
# the default damping policy (POINTMASS_TEST_EVERY_KOKKOS_PAIR=ON adds the others: the same
# kernel, whose arithmetic for every policy pair the batch suite compares with Particle's bit
# for bit in every configuration). All warnings are errors.
# To fit two cores, the debug builds carry line tables only (-g1) and the sanitizers run
# unoptimised; the benchmarks and their smoke tests are built in the clang configuration,
# optimised as when they measure; the plain replay of the fuzzing inputs runs in the g++
# configuration only (clang's libFuzzer run replays them through clang's code, sanitized), and
# so does the batch suite's build without exceptions (clang builds the rest of that suite).
# The i386 configuration builds the behaviour tests and the fuzzing replay for 32-bit x86
# (g++ -m32 with SSE2 arithmetic): a 32-bit size_t in every size, index and handle, and the
# same bits as on x86-64 (docs/numerics.md, "Determinism"). The aarch64 configuration builds
# the same for 64-bit ARM with clang (cmake/toolchains/aarch64-linux-gnu-clang.cmake) and runs
# it under qemu-user: another instruction set, FPCR's flush-to-zero for FlushDenormals, a
# 113-bit long double, and again the same bits (contraction off, as the determinism rules say).
# The armv7 configuration runs the core, contract, batch and precision suites for 32-bit ARM,
# under qemu-user too: a long double that is double itself, and FPSCR's flush-to-zero.
#   scripts/test.sh            everything
#   scripts/test.sh gcc        one configuration: gcc, clang, sanitize, i386, aarch64 or armv7
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages "${POINTMASS_PACKAGES[@]}"

configurations=("$@")
((${#configurations[@]})) || configurations=(gcc clang sanitize i386 aarch64 armv7)

# Under qemu the two 10^6-step flights far from the origin take a minute or more each; their
# float and double arithmetic is x86-64's bit for bit there (docs/numerics.md, "Determinism"),
# and every other configuration runs them, so the ARM ones leave them out.
far_flights="far from the origin: within 1 mm"
times=()
for configuration in "${configurations[@]}"; do
  started=$SECONDS
  ctest_arguments=()
  dir="$POINTMASS_ROOT/build/test-$configuration"
  echo "== $configuration: configure and build in $dir"
  case "$configuration" in
    gcc)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=Debug \
        -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DPOINTMASS_BUILD_BENCHMARKS=OFF \
        -DPOINTMASS_TEST_EVERY_KOKKOS_PAIR=OFF
      ;;
    clang)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
        -DPOINTMASS_FUZZ_REPLAY=OFF -DPOINTMASS_TEST_EVERY_KOKKOS_PAIR=OFF \
        -DPOINTMASS_NO_EXCEPTIONS_EQUIVALENCE=OFF
      ;;
    sanitize)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=Debug \
        -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DPOINTMASS_BUILD_BENCHMARKS=OFF \
        -DPOINTMASS_BUILD_CHECKS=OFF -DPOINTMASS_TEST_KOKKOS_EQUIVALENCE=OFF \
        -DPOINTMASS_FUZZ_REPLAY=OFF \
        "-DCMAKE_CXX_FLAGS=-fno-omit-frame-pointer -fsanitize=address,undefined,float-divide-by-zero -fno-sanitize-recover=all"
      ;;
    i386)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=Debug \
        -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DPOINTMASS_BUILD_BENCHMARKS=OFF \
        -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_CHECKS=OFF \
        "-DCMAKE_CXX_FLAGS=-m32 -msse2 -mfpmath=sse" -DCMAKE_EXE_LINKER_FLAGS=-m32
      ;;
    aarch64)
      configure_and_build "$dir" \
        -DCMAKE_TOOLCHAIN_FILE="$POINTMASS_ROOT/cmake/toolchains/aarch64-linux-gnu-clang.cmake" \
        -DCMAKE_BUILD_TYPE=Release -DPOINTMASS_BUILD_BENCHMARKS=OFF \
        -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_CHECKS=OFF \
        -DCMAKE_CXX_FLAGS=-ffp-contract=off
      ctest_arguments=(--exclude-regex "$far_flights")
      ;;
    armv7)
      suites=(tests/pointmass_tests tests/pointmass_contract_tests
              tests/system/pointmass_system_tests tests/precision/pointmass_precision_tests)
      cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja \
        -DCMAKE_TOOLCHAIN_FILE="$POINTMASS_ROOT/cmake/toolchains/arm-linux-gnueabihf-clang.cmake" \
        -DCMAKE_BUILD_TYPE=Release -DPOINTMASS_BUILD_BENCHMARKS=OFF \
        -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_CHECKS=OFF \
        "-DCMAKE_CXX_FLAGS=-march=armv7-a -mfpu=vfpv3-d16 -mfloat-abi=hard -ffp-contract=off"
      cmake --build "$dir" --parallel "$(nproc)" --target "${suites[@]##*/}"
      echo "== $configuration: test"
      for suite in "${suites[@]}"; do
        qemu-arm -L /usr/arm-linux-gnueabihf "$dir/$suite" --test-case-exclude="*$far_flights*"
      done
      ;;
    *) echo "unknown configuration: $configuration (gcc, clang, sanitize, i386, aarch64, armv7)" >&2
       exit 2 ;;
  esac
  if [[ $configuration != armv7 ]]; then
    echo "== $configuration: test"
    ctest --test-dir "$dir" --output-on-failure --parallel "$(nproc)" "${ctest_arguments[@]}"
  fi
  elapsed=$((SECONDS - started))
  times+=("$configuration $((elapsed / 60))m$((elapsed % 60))s")
done
# What each configuration took, build and tests (the whole run should stay well under 30 min).
(IFS=';'; echo "== passed: ${times[*]}")
