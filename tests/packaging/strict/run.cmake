# SPDX-License-Identifier: BSL-1.0
# cmake -DCOMPILER= -DINCLUDE=<include dir> -DSOURCE=strict.cpp -DBINARY=<program> -P run.cmake
# Builds SOURCE as a consumer would without CMake's help (plain -I, C++20) with strict
# warnings as errors, then runs it. With clang, -Weverything, less these warnings, which are
# about the consumer's style rather than about errors:
#   c++98-compat, c++98-compat-pedantic  the headers are C++20;
#   padded                               ContractViolation's layout has padding by nature
#                                        (pointers, long doubles, a char array).
set(flags -std=c++20 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion
          -Wfloat-equal -Wmissing-noreturn -Werror)
execute_process(COMMAND "${COMPILER}" --version OUTPUT_VARIABLE version)
if(version MATCHES "clang")
  list(APPEND flags -Weverything -Wno-c++98-compat -Wno-c++98-compat-pedantic -Wno-padded)
endif()
execute_process(COMMAND "${COMPILER}" ${flags} "-I${INCLUDE}" "${SOURCE}" -o "${BINARY}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the strict consumer does not build (${flags}):\n${output}")
endif()
execute_process(COMMAND "${BINARY}" RESULT_VARIABLE result OUTPUT_VARIABLE output)
message(STATUS "${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the strict consumer built but failed")
endif()
