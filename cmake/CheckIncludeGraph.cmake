# SPDX-License-Identifier: BSL-1.0
cmake_minimum_required(VERSION 3.21)
# cmake -DDOCUMENT=docs/design.md -DINCLUDE_DIR=include/pointmass [-DPLANT=ON -DWORK=dir]
#       -P CheckIncludeGraph.cmake
# The include graph written in DOCUMENT must be the headers' own. The graph is the fenced
# block right after the line "<!-- include-graph -->", one line per header under INCLUDE_DIR:
#   particle.hpp: config.hpp damping.hpp ...
# (the header, relative to INCLUDE_DIR, a colon, then every project header it includes
# directly, in any order). The headers' edges are their `#include "..."` lines (and
# `#include <pointmass/...>`), resolved against the including header's folder, wherever they
# stand (under #if too). Fails naming each difference: a header missing from the block, a
# line for a header that does not exist, an edge in one and not the other.
# PLANT=ON first writes a copy of DOCUMENT to WORK with the last edge of the block's first
# line that has one deleted, and checks the copy: the check must then fail (the test
# docs.include_graph.finds_a_planted_edge).
foreach(_variable IN ITEMS DOCUMENT INCLUDE_DIR)
  if(NOT DEFINED ${_variable})
    message(FATAL_ERROR "CheckIncludeGraph.cmake: ${_variable} is not set")
  endif()
endforeach()
cmake_path(ABSOLUTE_PATH INCLUDE_DIR NORMALIZE)
set(_marker "<!-- include-graph -->")

# The block's text in _block (its lines, without the fences), from the document's text.
function(read_block text out)
  string(FIND "${text}" "${_marker}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "${DOCUMENT}: no line \"${_marker}\" before the include graph's block")
  endif()
  string(SUBSTRING "${text}" ${_at} -1 _rest)
  if(NOT _rest MATCHES "^${_marker}[ \t]*\n```[a-z]*\n")
    message(FATAL_ERROR "${DOCUMENT}: \"${_marker}\" must be followed by a fence (```text)")
  endif()
  string(LENGTH "${CMAKE_MATCH_0}" _skip)
  string(SUBSTRING "${_rest}" ${_skip} -1 _rest)
  string(FIND "${_rest}" "\n```" _end)
  if(_end EQUAL -1)
    message(FATAL_ERROR "${DOCUMENT}: the include graph's block is not closed")
  endif()
  string(SUBSTRING "${_rest}" 0 ${_end} _rest)
  set(${out} "${_rest}" PARENT_SCOPE)
endfunction()

file(READ "${DOCUMENT}" _document)
if(PLANT)
  if(NOT DEFINED WORK)
    message(FATAL_ERROR "CheckIncludeGraph.cmake: PLANT needs WORK (a folder for the copy)")
  endif()
  read_block("${_document}" _block)
  string(REPLACE "\n" ";" _lines "${_block}")
  set(_planted "")
  foreach(_line IN LISTS _lines)
    if(_line MATCHES "^([^: ]+):(.* )([^ ]+)[ \t]*$")
      set(_planted "${CMAKE_MATCH_1} -> ${CMAKE_MATCH_3}")
      string(REGEX REPLACE "[ \t]+$" "" _shorter "${CMAKE_MATCH_1}:${CMAKE_MATCH_2}")
      string(REPLACE "\n${_line}\n" "\n${_shorter}\n" _document "${_document}")
      break()
    endif()
  endforeach()
  if(_planted STREQUAL "")
    message(FATAL_ERROR "PLANT: the block has no edge to delete")
  endif()
  file(MAKE_DIRECTORY "${WORK}")
  set(DOCUMENT "${WORK}/include-graph-planted.md")
  file(WRITE "${DOCUMENT}" "${_document}")
  message(STATUS "planted: deleted the edge ${_planted} in ${DOCUMENT}")
endif()

# The document's graph: _listed (headers) and, for each, _doc_<header> (its edges).
read_block("${_document}" _block)
string(REPLACE "\n" ";" _lines "${_block}")
set(_listed)
set(_bad 0)
foreach(_line IN LISTS _lines)
  string(STRIP "${_line}" _line)
  if(_line STREQUAL "")
    continue()
  endif()
  if(NOT _line MATCHES "^([^: ]+):(.*)$")
    message(SEND_ERROR "include graph: the line \"${_line}\" is not \"header: includes...\"")
    math(EXPR _bad "${_bad} + 1")
    continue()
  endif()
  set(_header "${CMAKE_MATCH_1}")
  string(STRIP "${CMAKE_MATCH_2}" _edges)
  string(REGEX REPLACE "[ \t]+" ";" _edges "${_edges}")
  if(_header IN_LIST _listed)
    message(SEND_ERROR "include graph: ${_header} has two lines")
    math(EXPR _bad "${_bad} + 1")
  endif()
  list(APPEND _listed "${_header}")
  set(_doc_${_header} ${_edges})
endforeach()

# The headers' graph: _headers and, for each, _real_<header>.
file(GLOB_RECURSE _files LIST_DIRECTORIES false RELATIVE "${INCLUDE_DIR}"
     "${INCLUDE_DIR}/*.hpp" "${INCLUDE_DIR}/*.h")
list(SORT _files)
set(_headers ${_files})
foreach(_header IN LISTS _headers)
  file(STRINGS "${INCLUDE_DIR}/${_header}" _includes
       REGEX "^[ \t]*#[ \t]*include[ \t]*(\"[^\"]+\"|<pointmass/[^>]+>)")
  cmake_path(GET _header PARENT_PATH _folder)
  set(_edges)
  foreach(_include IN LISTS _includes)
    if(_include MATCHES "\"([^\"]+)\"")
      set(_target "${INCLUDE_DIR}/${_folder}/${CMAKE_MATCH_1}")
    elseif(_include MATCHES "<pointmass/([^>]+)>")
      set(_target "${INCLUDE_DIR}/${CMAKE_MATCH_1}")
    endif()
    cmake_path(NORMAL_PATH _target)
    cmake_path(RELATIVE_PATH _target BASE_DIRECTORY "${INCLUDE_DIR}")
    list(APPEND _edges "${_target}")
  endforeach()
  list(REMOVE_DUPLICATES _edges)
  set(_real_${_header} ${_edges})
endforeach()

# The differences.
foreach(_header IN LISTS _headers)
  if(NOT _header IN_LIST _listed)
    list(JOIN _real_${_header} " " _edges)
    message(SEND_ERROR "include graph: ${_header} is not listed (add the line "
                       "\"${_header}: ${_edges}\")")
    math(EXPR _bad "${_bad} + 1")
    continue()
  endif()
  foreach(_edge IN LISTS _real_${_header})
    if(NOT _edge IN_LIST _doc_${_header})
      message(SEND_ERROR "include graph: ${_header} includes ${_edge}, "
                         "which the document's line for it does not list")
      math(EXPR _bad "${_bad} + 1")
    endif()
  endforeach()
  foreach(_edge IN LISTS _doc_${_header})
    if(NOT _edge IN_LIST _real_${_header})
      message(SEND_ERROR "include graph: the document says ${_header} includes ${_edge}, "
                         "which it does not")
      math(EXPR _bad "${_bad} + 1")
    endif()
  endforeach()
endforeach()
foreach(_header IN LISTS _listed)
  if(NOT _header IN_LIST _headers)
    message(SEND_ERROR "include graph: the document lists ${_header}, which is no header "
                       "under ${INCLUDE_DIR}")
    math(EXPR _bad "${_bad} + 1")
  endif()
endforeach()

list(LENGTH _headers _count)
if(_bad GREATER 0)
  message(FATAL_ERROR "${DOCUMENT}: ${_bad} difference(s) between the include graph and the "
                      "${_count} headers under ${INCLUDE_DIR}")
endif()
message(STATUS "${DOCUMENT}: the include graph is the ${_count} headers' own")
