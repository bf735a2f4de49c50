# SPDX-License-Identifier: BSL-1.0
# cmake -DFILES="a;b;..." -DEACH=N [-DTOTAL=M] -DWHAT=text -P CheckLineBounds.cmake
#
# Fails naming every file of FILES longer than EACH lines and, with TOTAL, when the files
# together are longer than TOTAL lines. The bounds the project holds itself to: headers short
# enough to read whole, and documentation that stays a manual (tests/CMakeLists.txt sets them).
foreach(_variable IN ITEMS FILES EACH WHAT)
  if(NOT DEFINED ${_variable})
    message(FATAL_ERROR "CheckLineBounds.cmake: ${_variable} is not set")
  endif()
endforeach()
set(_total 0)
set(_failures 0)
foreach(_file IN LISTS FILES)
  file(STRINGS "${_file}" _lines)
  # file(STRINGS) drops empty lines: count the newlines instead.
  file(READ "${_file}" _text)
  string(REGEX MATCHALL "\n" _newlines "${_text}")
  list(LENGTH _newlines _count)
  math(EXPR _total "${_total} + ${_count}")
  if(_count GREATER EACH)
    message(SEND_ERROR "${WHAT}: ${_file} has ${_count} lines, more than ${EACH}")
    math(EXPR _failures "${_failures} + 1")
  endif()
endforeach()
if(DEFINED TOTAL AND _total GREATER TOTAL)
  message(SEND_ERROR "${WHAT}: ${_total} lines in all, more than ${TOTAL}")
  math(EXPR _failures "${_failures} + 1")
endif()
if(_failures EQUAL 0)
  list(LENGTH FILES _files)
  message(STATUS "${WHAT}: ${_files} files, ${_total} lines, within the bounds")
endif()
