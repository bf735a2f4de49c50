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
