# SPDX-License-Identifier: BSL-1.0
cmake_minimum_required(VERSION 3.21)
# cmake -DDOCUMENT=doc.md "-DQUOTED_FROM=a.cpp;b.cpp" -DCOMPILER=c++ "-DINCLUDE_DIRS=x|y"
#       -DWORK=dir -P CheckDocBlocks.cmake
# Every ```cpp block of the document must compile. A block that appears verbatim in one of
# QUOTED_FROM (the examples, which the build compiles) is checked there (that README.md and
# docs/examples.md quote the examples verbatim is checked on its own: CheckQuoted.cmake).
# Any other block is compiled here, after the prelude
#   #include <pointmass/pointmass.hpp>, <pointmass/particle_system.hpp>,
#            <pointmass/forces.hpp>, <pointmass/units.hpp>
# as the HTML comment right before its fence says (invisible when the document is shown):
#   (no comment)            the block is declarations at namespace scope;
#   <!-- cpp: declarations -->   the same, said explicitly;
#   <!-- cpp: statements -->     the block is the body of a function (a fragment of code);
#   <!-- cpp: program -->        the block is a whole translation unit (no prelude).
# Lines after the first of the comment, up to "-->", are set-up code placed at namespace
# scope before the block (the names a fragment uses), e.g.
#   <!-- cpp: statements
#   pointmass::Particle<double> body;
#   -->
# Blocks added later are checked the same way: the test reads the document when it runs.
include("${CMAKE_CURRENT_LIST_DIR}/PointmassScripts.cmake")
file(READ "${DOCUMENT}" _document)
pointmass_read_files(_sources ${QUOTED_FROM})
pointmass_include_flags(_include_flags "${INCLUDE_DIRS}")
get_filename_component(_document_name "${DOCUMENT}" NAME_WE)
file(MAKE_DIRECTORY "${WORK}")

set(_prelude "#include <pointmass/pointmass.hpp>\n#include <pointmass/particle_system.hpp>\n#include <pointmass/forces.hpp>\n#include <pointmass/units.hpp>\n")
set(_rest "${_document}")
set(_quoted 0)
set(_compiled 0)
set(_failed 0)
while(TRUE)
  pointmass_next_cpp_block(_rest _before _block)
  if(NOT DEFINED _block)
    break()
  endif()
  # The marker: an HTML comment ending just before the fence (blank lines allowed).
  string(STRIP "${_before}" _before)
  set(_kind "")
  set(_setup "")
  if(_before MATCHES "-->$")
    string(FIND "${_before}" "<!--" _open REVERSE)
    string(SUBSTRING "${_before}" ${_open} -1 _comment)
    if(_comment MATCHES "^<!-- cpp: ([a-z]+)")
      set(_kind "${CMAKE_MATCH_1}")
      string(FIND "${_comment}" "\n" _newline)
      if(NOT _newline EQUAL -1)
        math(EXPR _newline "${_newline} + 1")
        string(SUBSTRING "${_comment}" ${_newline} -1 _setup)
        string(REGEX REPLACE "-->$" "" _setup "${_setup}")
      endif()
    endif()
  endif()
  math(EXPR _index "${_quoted} + ${_compiled} + ${_failed} + 1")

  string(FIND "${_sources}" "${_block}" _at)
  if(_kind STREQUAL "" AND NOT _sources STREQUAL "" AND NOT _at EQUAL -1)
    math(EXPR _quoted "${_quoted} + 1")
    continue()
  endif()
  if(_kind STREQUAL "" OR _kind STREQUAL "declarations")
    set(_unit "${_prelude}${_setup}\n${_block}")
  elseif(_kind STREQUAL "statements")
    set(_unit "${_prelude}${_setup}\nvoid doc_block_${_index}() {\n${_block}}\n")
  elseif(_kind STREQUAL "program")
    set(_unit "${_setup}\n${_block}")
  else()
    message(SEND_ERROR "${DOCUMENT}: cpp block ${_index}: unknown marker 'cpp: ${_kind}'")
    math(EXPR _failed "${_failed} + 1")
    continue()
  endif()
  set(_file "${WORK}/${_document_name}_block_${_index}.cpp")
  file(WRITE "${_file}" "${_unit}")
  execute_process(COMMAND "${COMPILER}" -std=c++20 -fsyntax-only ${_include_flags} "${_file}"
                  RESULT_VARIABLE _result OUTPUT_VARIABLE _output ERROR_VARIABLE _output)
  if(_result EQUAL 0)
    math(EXPR _compiled "${_compiled} + 1")
  else()
    math(EXPR _failed "${_failed} + 1")
    message(SEND_ERROR "${DOCUMENT}: cpp block ${_index} is not quoted verbatim from the "
                       "examples and does not compile as ${_file}:\n${_block}\n${_output}")
  endif()
endwhile()
if(_failed GREATER 0)
  message(FATAL_ERROR "${DOCUMENT}: ${_failed} cpp block(s) fail")
endif()
message(STATUS "${DOCUMENT}: ${_quoted} cpp blocks quoted verbatim from the examples, "
               "${_compiled} compiled")
