# SPDX-License-Identifier: BSL-1.0
# What the project's cmake -P scripts share (cmake/CheckDocBlocks.cmake, cmake/CheckQuoted.cmake,
# tests/compile-fail/check_compile.cmake): reading a list of files into one text, -I flags
# from a "|"-separated list of directories, and walking the ```cpp blocks of a document.
include_guard(GLOBAL)

# pointmass_read_files(OUT FILE...): the files' texts, each followed by a newline, in one string.
function(pointmass_read_files out)
  set(_all "")
  foreach(_file IN LISTS ARGN)
    file(READ "${_file}" _text)
    string(APPEND _all "${_text}\n")
  endforeach()
  set(${out} "${_all}" PARENT_SCOPE)
endfunction()

# pointmass_include_flags(OUT DIRS): the list of -I flags for DIRS, directories separated by
# "|" (empty ones skipped).
function(pointmass_include_flags out dirs)
  string(REPLACE "|" ";" _dirs "${dirs}")
  set(_flags)
  foreach(_dir IN LISTS _dirs)
    if(_dir)
      list(APPEND _flags "-I${_dir}")
    endif()
  endforeach()
  set(${out} "${_flags}" PARENT_SCOPE)
endfunction()

# pointmass_next_cpp_block(REST BEFORE BLOCK): finds the first ```cpp fence in the variable
# named REST and sets BLOCK to the block's text (up to the closing ```), BEFORE to the text
# before the fence, and REST to the text from the closing fence on. Where REST has no ```cpp
# fence, BLOCK is left undefined.
function(pointmass_next_cpp_block rest_var before_var block_var)
  set(_text "${${rest_var}}")
  string(FIND "${_text}" "```cpp\n" _start)
  if(_start EQUAL -1)
    unset(${block_var} PARENT_SCOPE)
    return()
  endif()
  string(SUBSTRING "${_text}" 0 ${_start} _before)
  math(EXPR _start "${_start} + 7")
  string(SUBSTRING "${_text}" ${_start} -1 _text)
  string(FIND "${_text}" "```" _end)
  string(SUBSTRING "${_text}" 0 ${_end} _block)
  string(SUBSTRING "${_text}" ${_end} -1 _text)
  set(${before_var} "${_before}" PARENT_SCOPE)
  set(${block_var} "${_block}" PARENT_SCOPE)
  set(${rest_var} "${_text}" PARENT_SCOPE)
endfunction()
