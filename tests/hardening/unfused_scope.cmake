# SPDX-License-Identifier: BSL-1.0
# Every header's code is in the library's uncontracted scope: each header that opens a
# namespace has POINTMASS_DETAIL_UNFUSED_BEGIN before its first namespace and
# POINTMASS_DETAIL_UNFUSED_END after its last (config.hpp, which defines them, apart).
#   cmake -DFILES=<headers> -P unfused_scope.cmake
set(_failed "")
foreach(_file IN LISTS FILES)
  get_filename_component(_name "${_file}" NAME)
  file(READ "${_file}" _text)
  if(_name STREQUAL "config.hpp" OR NOT _text MATCHES "\nnamespace ")
    continue()
  endif()
  string(FIND "${_text}" "\nnamespace " _first)
  string(FIND "${_text}" "\n}  // namespace" _last REVERSE)
  string(FIND "${_text}" "\nPOINTMASS_DETAIL_UNFUSED_BEGIN\n" _begin)
  string(FIND "${_text}" "\nPOINTMASS_DETAIL_UNFUSED_END\n" _end REVERSE)
  if(_begin EQUAL -1 OR _end EQUAL -1 OR _begin GREATER _first OR _end LESS _last)
    string(APPEND _failed "\n  ${_file}")
  endif()
endforeach()
if(_failed)
  message(FATAL_ERROR "outside POINTMASS_DETAIL_UNFUSED_BEGIN / _END:${_failed}")
endif()
list(LENGTH FILES _count)
message(STATUS "every header's code is in the uncontracted scope (${_count} headers)")
