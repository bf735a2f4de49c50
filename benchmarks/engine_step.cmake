# SPDX-License-Identifier: BSL-1.0
# engine_step compares against Cyclone's particle, whose integrate lives in its
# own translation unit (tests/support/reference_engine.cpp).
target_sources(engine_step PRIVATE "${PROJECT_SOURCE_DIR}/tests/support/reference_engine.cpp")
target_include_directories(engine_step PRIVATE "${PROJECT_SOURCE_DIR}/tests/support")
