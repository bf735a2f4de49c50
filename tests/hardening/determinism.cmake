# SPDX-License-Identifier: BSL-1.0
# Compares the digests two runs of the determinism program print.
#   cmake -DFIRST=<program> [-DSECOND=<program>] [-DEMULATOR=...] -P determinism.cmake
# Runs FIRST, then SECOND (FIRST again if not given), and passes when both exit 0 and print
# the same "all <digest>" line: run after run, or build against build. A cross build passes
# its emulator's command line as EMULATOR, which runs both.
if(NOT DEFINED SECOND)
  set(SECOND "${FIRST}")
endif()
separate_arguments(emulator UNIX_COMMAND "${EMULATOR}")
foreach(which IN ITEMS FIRST SECOND)
  execute_process(COMMAND ${emulator} "${${which}}" RESULT_VARIABLE result OUTPUT_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${${which}} failed (${result}):\n${output}")
  endif()
  string(REGEX MATCH "all [0-9a-f]+" digest_${which} "${output}")
  message(STATUS "${${which}}: ${digest_${which}}")
endforeach()
if(NOT digest_FIRST STREQUAL digest_SECOND OR digest_FIRST STREQUAL "")
  message(FATAL_ERROR "digests differ: '${digest_FIRST}' and '${digest_SECOND}'")
endif()
