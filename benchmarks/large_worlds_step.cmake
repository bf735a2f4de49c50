# SPDX-License-Identifier: BSL-1.0
# The smoke test skips the 10^7 sizes (large_worlds_step.cpp's main), which take most of a
# minute to set up in a debug build.
if(TEST benchmark_smoke.large_worlds_step)
  set_tests_properties(benchmark_smoke.large_worlds_step PROPERTIES
                       ENVIRONMENT POINTMASS_BENCHMARK_SMOKE=1)
endif()
