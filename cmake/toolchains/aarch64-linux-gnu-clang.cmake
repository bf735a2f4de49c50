# SPDX-License-Identifier: BSL-1.0
# Cross-compiling for 64-bit ARM Linux with clang, on a Debian host: the target's C and C++
# libraries come from Debian's libc6-dev-arm64-cross, libstdc++-12-dev-arm64-cross and
# libgcc-12-dev-arm64-cross, the linker from binutils-aarch64-linux-gnu; CTest runs the
# programs under qemu-user. Used by `scripts/test.sh aarch64`:
#   cmake -S . -B build/arm -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu-clang.cmake
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER clang)
set(CMAKE_CXX_COMPILER clang++)
set(CMAKE_C_COMPILER_TARGET aarch64-linux-gnu)
set(CMAKE_CXX_COMPILER_TARGET aarch64-linux-gnu)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)
