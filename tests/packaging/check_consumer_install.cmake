# SPDX-License-Identifier: BSL-1.0
# cmake -DCOMPILER= -DGENERATOR= -DMODE=add_subdirectory|FetchContent -DSOURCE=<pointmass>
#       -DCONSUMER=<consumer project> -DBINARY=<scratch> -P check_consumer_install.cmake
# Builds and installs the consumer project, which takes pointmass by MODE. The install must
# hold the consumer's own program (so the install did run) and nothing of pointmass: no
# headers, no CMake package, no pointmass.pc, no licence file; and its configure log must hold
# no line of pointmass's (the optional parts are looked for only when asked).
file(REMOVE_RECURSE "${BINARY}")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${CONSUMER}" -B "${BINARY}/build" -G "${GENERATOR}"
                        "-DCMAKE_CXX_COMPILER=${COMPILER}" "-DPOINTMASS_CONSUMER_MODE=${MODE}"
                        "-DPOINTMASS_SOURCE_DIR=${SOURCE}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed:\n${output}")
endif()
# A subproject's configure says nothing of pointmass's optional parts.
if(output MATCHES "pointmass:|Kokkos|Boost")
  message(FATAL_ERROR "the consumer's configure (${MODE}) printed pointmass's lines:\n${output}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BINARY}/build"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "building the consumer failed:\n${output}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BINARY}/build" --prefix "${BINARY}/prefix"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "installing the consumer failed:\n${output}")
endif()
file(GLOB_RECURSE installed RELATIVE "${BINARY}/prefix" "${BINARY}/prefix/*")
if(NOT installed MATCHES "(^|;)bin/consumer(;|$)")
  message(FATAL_ERROR "the consumer's install lacks its own bin/consumer: ${installed}")
endif()
set(foreign "")
foreach(file IN LISTS installed)
  if(file MATCHES "pointmass|LICENSE_1_0")
    list(APPEND foreign "${file}")
  endif()
endforeach()
if(foreign)
  list(JOIN foreign "\n  " foreign)
  message(FATAL_ERROR "the consumer's install (${MODE}) holds files of pointmass:\n  ${foreign}")
endif()
message(STATUS "the consumer's install (${MODE}) holds only its own files: ${installed}")
