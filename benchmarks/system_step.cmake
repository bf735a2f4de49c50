# SPDX-License-Identifier: BSL-1.0
# system_step uses the execution-policy overload: libstdc++ runs it on TBB.
find_package(TBB REQUIRED)
target_link_libraries(system_step PRIVATE TBB::tbb)
if(TEST benchmark_smoke.system_step)
  set_tests_properties(benchmark_smoke.system_step PROPERTIES ENVIRONMENT POINTMASS_BENCHMARK_SMOKE=1)
endif()
