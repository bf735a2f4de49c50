# SPDX-License-Identifier: BSL-1.0
cmake_minimum_required(VERSION 3.21)
# cmake -DPROGRAM=generator -DEXPECTED=doc.md -DOUTPUT=build/doc.md [-DEMULATOR=...]
#       -P CheckGenerated.cmake
# Runs PROGRAM, which writes a document to standard output, and fails unless the output is
# EXPECTED byte for byte: a generated document in the source tree must be what its generator
# writes now. On a difference it prints the lines that differ and how to regenerate. A cross
# build passes its emulator's command line as EMULATOR, which runs PROGRAM.
separate_arguments(_emulator UNIX_COMMAND "${EMULATOR}")
execute_process(COMMAND ${_emulator} "${PROGRAM}" OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed: ${_status}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${EXPECTED}" "${OUTPUT}"
                RESULT_VARIABLE _differ)
if(_differ)
  find_program(_diff diff)
  if(_diff)
    execute_process(COMMAND "${_diff}" -u "${EXPECTED}" "${OUTPUT}" OUTPUT_VARIABLE _lines)
  endif()
  message(FATAL_ERROR "${EXPECTED} is not what its generator writes now:\n${_lines}\n"
                      "Regenerate it: ${PROGRAM} > ${EXPECTED}")
endif()
message(STATUS "${EXPECTED}: what ${PROGRAM} writes")
