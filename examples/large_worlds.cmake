# SPDX-License-Identifier: BSL-1.0
# The drift tables of docs/results/large-worlds.md (scripts/large-worlds.sh); the smoke test runs
# 10^4 steps and checks that the tables come out.
if(POINTMASS_BUILD_TESTS)
  add_test(NAME example.large_worlds COMMAND large_worlds --quick)
  set_tests_properties(example.large_worlds PROPERTIES PASS_REGULAR_EXPRESSION
    "Drift after 10000 steps.*\\| free flight from 1e6 m \\(None, Euler\\) \\|.*against an all-double particle")
endif()
# The drift compares trajectories computed from the same float numbers: without contraction
# into fused multiply-adds (which -march=native allows g++ to choose differently in each
# inlined copy of a step), the all-float particle's and the wide ones' velocities are the
# same bits, and the tables measure only what the position storage loses.
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(large_worlds PRIVATE -ffp-contract=off)
endif()
