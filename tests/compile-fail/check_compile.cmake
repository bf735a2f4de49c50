# SPDX-License-Identifier: BSL-1.0
# Compiles one snippet (cmake -P): -DCOMPILER, -DSOURCE, -DINCLUDE_DIRS (separated by |),
# -DSYSTEM_INCLUDE_DIRS (optional, the same), -DEXPECT=pass|fail. With EXPECT=fail the compilation must fail and its output must contain
# the text of one of the snippet's "// expected-error: TEXT" lines (one line per compiler's
# wording where g++ and clang differ).
include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/PointmassScripts.cmake")
pointmass_include_flags(include_flags "${INCLUDE_DIRS}")
# -DSYSTEM_INCLUDE_DIRS (optional, separated by |): a library's headers (Kokkos'), searched as
# system headers, so that their own warnings are not the project's errors.
set(system_flags)
string(REPLACE "|" ";" system_dirs "${SYSTEM_INCLUDE_DIRS}")
foreach(dir IN LISTS system_dirs)
  if(dir)
    list(APPEND system_flags -isystem "${dir}")
  endif()
endforeach()

string(REPLACE "|" ";" extra_flags "${EXTRA_FLAGS}")  # optional: flags of the snippet's own

execute_process(
  COMMAND "${COMPILER}" -std=c++20 -fsyntax-only ${extra_flags}
          -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror
          ${include_flags} ${system_flags} "${SOURCE}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)

if(EXPECT STREQUAL "pass")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${SOURCE} must compile, but failed:\n${output}")
  endif()
  message(STATUS "compiles, as it must")
  return()
endif()

file(STRINGS "${SOURCE}" expected_lines REGEX "// expected-error: ")
if(NOT expected_lines)
  message(FATAL_ERROR "${SOURCE} has no '// expected-error: ' line")
endif()
set(expected_texts)
foreach(line IN LISTS expected_lines)
  string(REGEX REPLACE "^.*// expected-error: " "" text "${line}")
  list(APPEND expected_texts "${text}")
endforeach()

if(result EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled, but must fail with: ${expected_texts}")
endif()
foreach(text IN LISTS expected_texts)
  string(FIND "${output}" "${text}" position)
  if(NOT position EQUAL -1)
    message(STATUS "fails to compile with '${text}', as it must")
    return()
  endif()
endforeach()
message(FATAL_ERROR
  "${SOURCE} failed to compile, but not with any of '${expected_texts}':\n${output}")
