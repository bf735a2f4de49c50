# SPDX-License-Identifier: BSL-1.0
# forces_step compares against Cyclone's particle and force registry, whose integrate,
# generators and registry live in their own translation unit (tests/support/reference_engine.cpp).
target_sources(forces_step PRIVATE "${PROJECT_SOURCE_DIR}/tests/support/reference_engine.cpp")
target_include_directories(forces_step PRIVATE "${PROJECT_SOURCE_DIR}/tests/support")
