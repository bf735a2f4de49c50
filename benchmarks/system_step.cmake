# SPDX-License-Identifier: BSL-1.0
# system_step uses the execution-policy overload: libstdc++ runs it on TBB.
find_package(TBB REQUIRED)
target_link_libraries(system_step PRIVATE TBB::tbb)
