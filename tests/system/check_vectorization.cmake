# SPDX-License-Identifier: BSL-1.0
# One vectorisation probe (cmake -P): runs -DCOMMAND (the compiler and its arguments,
# separated by |) and passes when its report names the step loop at least -DCOUNT times: lines
# that match -DPATTERN. Counted here, line by line: a pass expression for the test that spans
# several reports, `A(.|\n)*A`, made CTest backtrack for half a minute over clang's output.
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE output
                ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the probe did not compile:\n${output}")
endif()
string(REGEX MATCHALL "${PATTERN}" reports "${output}")
list(LENGTH reports found)
if(found LESS COUNT)
  message(FATAL_ERROR "the step loop is reported vectorised ${found} times, not ${COUNT} "
                      "(lines matching ${PATTERN}); the compiler's report:\n${output}")
endif()
message(STATUS "the step loop is reported vectorised ${found} times (at least ${COUNT})")
