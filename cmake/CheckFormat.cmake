# SPDX-License-Identifier: BSL-1.0
cmake_minimum_required(VERSION 3.21)
# cmake -DCLANG_FORMAT=<clang-format-14> -DSTYLE=<.clang-format> (-DROOT=<source tree> |
#       -DFILES=<a;b>) -P CheckFormat.cmake
# Fails unless every C++ file (the sources and headers under include, tests, examples and
# benchmarks of ROOT, or the FILES given) is as clang-format formats it with the style file
# STYLE; clang-format names each line that differs.
foreach(_variable IN ITEMS CLANG_FORMAT STYLE)
  if(NOT DEFINED ${_variable})
    message(FATAL_ERROR "CheckFormat.cmake: ${_variable} is not set")
  endif()
endforeach()
if(DEFINED ROOT)
  set(_patterns)
  foreach(_directory IN ITEMS include tests examples benchmarks)
    foreach(_extension IN ITEMS hpp cpp cu)
      list(APPEND _patterns "${ROOT}/${_directory}/*.${_extension}")
    endforeach()
  endforeach()
  file(GLOB_RECURSE FILES LIST_DIRECTORIES false ${_patterns})
endif()
list(LENGTH FILES _count)
if(_count EQUAL 0)
  message(FATAL_ERROR "CheckFormat.cmake: no files to check (set ROOT or FILES)")
endif()
execute_process(COMMAND "${CLANG_FORMAT}" "--style=file:${STYLE}" --dry-run --Werror ${FILES}
                RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "${_count} files checked: not formatted as clang-format formats them "
                      "(scripts/format.sh formats them)")
endif()
message(STATUS "${_count} files formatted")
