#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The whole test suite, as CI runs it: installs what is missing, then builds and runs the
# tests in six configurations. All warnings are errors. Each test case runs in the
# configurations where it says something new (POINTMASS_TEST_SUITES picks the suites):
#
#   gcc       g++ debug, contract checks on: every suite, the tests of the build itself
#             (compile-fail, documents' code, consumers, headers, vectorisation reports),
#             the batch and precision suites again at -O3 -march=native without contraction,
#             the batch suite without exceptions, the fuzzing corpus replayed, the format and
#             static analysis checks.
#   clang     clang -O3: the core, contract, batch, forces, precision and hardening suites
#             (libFuzzer under ASan and UBSan, g++ against clang digests), the benchmarks and
#             their smoke tests, the compile-fail snippets, the headers and the vectorisation
#             reports; the other tests of the build (documents, consumers, recipes) say
#             nothing new about the compiler and run in the gcc configuration.
#   sanitize  g++ with AddressSanitizer and UndefinedBehaviorSanitizer, unoptimised: the core,
#             contract, batch, forces and hardening suites, where the library's memory is.
#   i386      g++ -m32 (SSE2 arithmetic): the core, contract, batch, forces, precision and
#             hardening suites and the fuzzing replay, with a 32-bit size_t in every size,
#             index and handle, and the same bits as x86-64 (docs/numerics.md, "Determinism").
#   aarch64   clang for 64-bit ARM under qemu-user: the core, contract, batch, precision and
#             hardening suites: another instruction set, FPCR's flush-to-zero, a 113-bit long
#             double, and again the same bits (contraction off).
#   armv7     clang for 32-bit ARM under qemu-user: the core, contract, batch and precision
#             suites: a long double that is double itself, and FPSCR's flush-to-zero.
#
# The reference, units, stress, odr and kokkos suites and the examples are arithmetic the
# instruction set does not change; they run with g++ (and the Kokkos ones for the default
# damping policy: POINTMASS_TEST_EVERY_KOKKOS_PAIR=ON adds the others).
#   scripts/test.sh            everything
#   scripts/test.sh gcc        one configuration (or several): gcc, clang, sanitize, i386,
#                              aarch64, armv7
#   scripts/test.sh quick      the inner loop: g++ debug, the core, contract, batch and forces
#                              suites (cmake --workflow --preset dev, in build/dev)
set -euo pipefail
source "$(dirname "$0")/common.sh"

configurations=("$@")
((${#configurations[@]})) || configurations=(gcc clang sanitize i386 aarch64 armv7)

if [[ ${configurations[*]} == quick ]]; then
  ensure_packages cmake ninja-build g++ libboost-dev doctest-dev libtbb-dev
  cd "$POINTMASS_ROOT"
  cmake --preset dev
  cmake --build --preset dev
  ctest --preset dev --parallel "$(nproc)"
  exit
fi
ensure_packages "${POINTMASS_PACKAGES[@]}"

# Under qemu the long flights take a minute or more each; their arithmetic is x86-64's bit
# for bit there (docs/numerics.md, "Determinism"), and the x86 configurations run them.
qemu_long_cases="far from the origin: within 1 mm|the walk alternates between its size bounds"
debug=(-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1)
lean=(-DPOINTMASS_BUILD_BENCHMARKS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF -DPOINTMASS_BUILD_CHECKS=OFF)
times=()
for configuration in "${configurations[@]}"; do
  started=$SECONDS
  ctest_arguments=()
  dir="$POINTMASS_ROOT/build/test-$configuration"
  echo "== $configuration: configure and build in $dir"
  case "$configuration" in
    gcc)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=g++ "${debug[@]}" \
        -DPOINTMASS_BUILD_BENCHMARKS=OFF -DPOINTMASS_TEST_EVERY_KOKKOS_PAIR=OFF \
        -DPOINTMASS_LINT=ON
      ;;
    clang)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
        -DPOINTMASS_BUILD_EXAMPLES=OFF \
        "-DPOINTMASS_TEST_SUITES=core;contracts;system;forces;precision;hardening" \
        -DPOINTMASS_FUZZ_REPLAY=OFF -DPOINTMASS_NO_EXCEPTIONS_EQUIVALENCE=OFF
      ctest_arguments=(--exclude-regex
        "^(docs|packaging)\.|^hardening\.(packaging\.recipes|cuda|doxygen(\.no_internals)?)$")
      ;;
    sanitize)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=g++ "${debug[@]}" "${lean[@]}" \
        "-DPOINTMASS_TEST_SUITES=core;contracts;system;forces;hardening" \
        -DPOINTMASS_FUZZ_REPLAY=OFF \
        "-DCMAKE_CXX_FLAGS=-fno-omit-frame-pointer -fsanitize=address,undefined,float-divide-by-zero -fno-sanitize-recover=all"
      ;;
    i386)
      configure_and_build "$dir" -DCMAKE_CXX_COMPILER=g++ "${debug[@]}" "${lean[@]}" \
        "-DPOINTMASS_TEST_SUITES=core;contracts;system;forces;precision;hardening" \
        "-DCMAKE_CXX_FLAGS=-m32 -msse2 -mfpmath=sse" -DCMAKE_EXE_LINKER_FLAGS=-m32
      ;;
    aarch64)
      configure_and_build "$dir" \
        -DCMAKE_TOOLCHAIN_FILE="$POINTMASS_ROOT/cmake/toolchains/aarch64-linux-gnu-clang.cmake" \
        -DCMAKE_BUILD_TYPE=Release "${lean[@]}" \
        "-DPOINTMASS_TEST_SUITES=core;contracts;system;precision;hardening" \
        -DPOINTMASS_FUZZ_REPLAY=OFF -DCMAKE_CXX_FLAGS=-ffp-contract=off
      ctest_arguments=(--exclude-regex "$qemu_long_cases")
      ;;
    armv7)
      configure_and_build "$dir" \
        -DCMAKE_TOOLCHAIN_FILE="$POINTMASS_ROOT/cmake/toolchains/arm-linux-gnueabihf-clang.cmake" \
        -DCMAKE_BUILD_TYPE=Release "${lean[@]}" \
        "-DPOINTMASS_TEST_SUITES=core;contracts;system;precision" \
        "-DCMAKE_CXX_FLAGS=-march=armv7-a -mfpu=vfpv3-d16 -mfloat-abi=hard -ffp-contract=off"
      ctest_arguments=(--exclude-regex "$qemu_long_cases")
      ;;
    *) echo "unknown configuration: $configuration (gcc, clang, sanitize, i386, aarch64, armv7, quick)" >&2
       exit 2 ;;
  esac
  built=$((SECONDS - started))
  echo "== $configuration: test"
  ctest --test-dir "$dir" --output-on-failure --parallel "$(nproc)" "${ctest_arguments[@]}"
  elapsed=$((SECONDS - started))
  times+=("$configuration $((elapsed / 60))m$((elapsed % 60))s (build $((built / 60))m$((built % 60))s)")
done
# What each configuration took, build and tests, and the whole run.
(IFS=';'; echo "== passed: ${times[*]}")
echo "== total: $((SECONDS / 60))m$((SECONDS % 60))s"
