# SPDX-License-Identifier: BSL-1.0
# Settings for the project's own targets (tests, examples, benchmarks); never for consumers.

# Strict warnings, as errors, for everything the project builds itself.
add_library(pointmass_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(pointmass_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror)
endif()

# Helper: an executable of the project's, strict warnings, linked to the library.
function(pointmass_add_executable name)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE pointmass::pointmass pointmass_warnings)
endfunction()

# Boost (headers only): Odeint for the reference solutions, Units for units.hpp.
find_package(Boost 1.74 REQUIRED)

# Project-internal support code shared by tests, examples and benchmarks (never installed):
# tolerances, reference solutions, measurement helpers. Lives in tests/support/.
add_library(pointmass_support INTERFACE)
target_include_directories(pointmass_support INTERFACE "${PROJECT_SOURCE_DIR}/tests/support")
target_link_libraries(pointmass_support INTERFACE pointmass::pointmass Boost::headers)

# A cross build runs its programs under CMAKE_CROSSCOMPILING_EMULATOR (qemu-user, say). CTest
# adds it to a test whose command is a target; a script test (cmake -P) that runs a program
# itself takes it as -DEMULATOR=${POINTMASS_EMULATOR}, one argument, and splits it again
# (separate_arguments). Empty on a native build.
string(REPLACE ";" " " POINTMASS_EMULATOR "${CMAKE_CROSSCOMPILING_EMULATOR}")
