# SPDX-License-Identifier: BSL-1.0
# Cross-compiling for 32-bit ARM Linux (hard-float ABI) with clang, on a Debian host: the
# target's libraries come from Debian's libc6-dev-armhf-cross, libstdc++-12-dev-armhf-cross and
# libgcc-12-dev-armhf-cross, the linker from binutils-arm-linux-gnueabihf; CTest and the test
# command run the programs under qemu-user. Give the processor in the flags, as
# `scripts/test.sh armv7` does:
#   cmake -S . -B build/arm32 -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/arm-linux-gnueabihf-clang.cmake
#         "-DCMAKE_CXX_FLAGS=-march=armv7-a -mfpu=vfpv3-d16 -mfloat-abi=hard"
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER clang)
set(CMAKE_CXX_COMPILER clang++)
set(CMAKE_C_COMPILER_TARGET arm-linux-gnueabihf)
set(CMAKE_CXX_COMPILER_TARGET arm-linux-gnueabihf)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm -L /usr/arm-linux-gnueabihf)
