# SPDX-License-Identifier: BSL-1.0
cmake_minimum_required(VERSION 3.21)
# cmake -DROOT=tests -P CheckTestNames.cmake
# Fails if the name of a doctest test case under ROOT holds a ';'. CTest keeps test names in
# CMake lists, so doctest_discover_tests would register such a test case as several tests
# whose names match no test case, and each of them would pass without running anything.
# A name may be written as adjacent string literals: all of them are read.
file(GLOB_RECURSE _sources "${ROOT}/*.cpp" "${ROOT}/*.hpp")
set(_bad 0)
foreach(_file IN LISTS _sources)
  file(READ "${_file}" _text)
  # ';' separates CMake list elements: mark it first, so that the matches stay whole.
  string(REPLACE ";" "<semicolon>" _text "${_text}")
  string(REGEX MATCHALL "TEST_CASE[A-Z_]*\\(([ \t\r\n]*\"[^\"]*\")+" _names "${_text}")
  foreach(_name IN LISTS _names)
    if(_name MATCHES "<semicolon>")
      string(REPLACE "<semicolon>" ";" _name "${_name}")
      message(SEND_ERROR "${_file}: a test case name holds ';': ${_name}")
      math(EXPR _bad "${_bad} + 1")
    endif()
  endforeach()
endforeach()
list(LENGTH _sources _count)
if(_bad GREATER 0)
  message(FATAL_ERROR "${_bad} file(s) with a ';' in a test case name")
endif()
message(STATUS "${_count} files: no test case name holds ';'")
