# SPDX-License-Identifier: BSL-1.0
# large_worlds_step compares loops that are bound by their instructions in cache, where on some
# x86-64 processors (those with the jump conditional code erratum) a loop's speed also depends
# on where its branches fall against 32-byte boundaries: the same all-float loop, instantiated
# twice, ran at 2.9 and 3.4 G particle-steps/s here. The assembler keeps branches within those
# boundaries, for every loop of the program alike, so the table measures the arithmetic and
# not the code's placement.
# g++ passes the option to the assembler, clang takes it itself.
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag("-Wa,-mbranches-within-32B-boundaries"
                          POINTMASS_HAS_ASSEMBLER_BRANCH_ALIGNMENT)
  check_cxx_compiler_flag("-mbranches-within-32B-boundaries" POINTMASS_HAS_BRANCH_ALIGNMENT)
  if(POINTMASS_HAS_ASSEMBLER_BRANCH_ALIGNMENT)
    target_compile_options(large_worlds_step PRIVATE "-Wa,-mbranches-within-32B-boundaries")
  elseif(POINTMASS_HAS_BRANCH_ALIGNMENT)
    target_compile_options(large_worlds_step PRIVATE "-mbranches-within-32B-boundaries")
  endif()
endif()
