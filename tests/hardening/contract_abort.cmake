# SPDX-License-Identifier: BSL-1.0
# cmake -DPROGRAM=... -DCASE=... -DEXPECTED=<regex> -P contract_abort.cmake
# Passes when PROGRAM CASE was killed by abort (SIGABRT) and its stderr matches EXPECTED.
execute_process(COMMAND "${PROGRAM}" "${CASE}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
message(STATUS "exit: ${result}")
message(STATUS "stderr: ${error}")
if(NOT result MATCHES "Child aborted|SIGABRT|Subprocess aborted")
  message(FATAL_ERROR "expected the program to abort, got '${result}' (stdout: ${output})")
endif()
if(NOT error MATCHES "${EXPECTED}")
  message(FATAL_ERROR "stderr does not match '${EXPECTED}'")
endif()
if(output MATCHES "survived")
  message(FATAL_ERROR "the program went on after the violation")
endif()
