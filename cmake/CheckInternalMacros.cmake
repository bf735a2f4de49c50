# SPDX-License-Identifier: BSL-1.0
cmake_minimum_required(VERSION 3.21)
# cmake -DCOMPILER=c++ "-DINCLUDE_DIRS=x|y" -DSOURCE=all.cpp -P CheckInternalMacros.cmake
# SOURCE includes every public header. Preprocessed, no internal macro (POINTMASS_DETAIL_*)
# may be left defined at its end but POINTMASS_DETAIL_ALWAYS_INLINE, POINTMASS_DETAIL_IN_ORDER and
# POINTMASS_DETAIL_UNFUSED_BEGIN / _END, which config.hpp defines for every header
# (docs/design.md): the others are #undef'd by the header that defines them, so none reaches a
# user's code.
string(REPLACE "|" ";" _dirs "${INCLUDE_DIRS}")
list(REMOVE_ITEM _dirs "")
list(TRANSFORM _dirs PREPEND "-I")
execute_process(COMMAND "${COMPILER}" -std=c++20 -dM -E ${_dirs} "${SOURCE}"
                OUTPUT_VARIABLE _macros ERROR_VARIABLE _errors RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "preprocessing ${SOURCE} failed:\n${_errors}")
endif()
string(REGEX MATCHALL "#define POINTMASS_DETAIL_[A-Za-z0-9_]+" _defined "${_macros}")
list(TRANSFORM _defined REPLACE "#define " "")
list(FIND _defined POINTMASS_DETAIL_ALWAYS_INLINE _kept)
if(_kept EQUAL -1)
  message(FATAL_ERROR "POINTMASS_DETAIL_ALWAYS_INLINE is not defined: were the headers read?")
endif()
list(REMOVE_ITEM _defined POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_DETAIL_IN_ORDER
     POINTMASS_DETAIL_UNFUSED_BEGIN POINTMASS_DETAIL_UNFUSED_END)
if(_defined)
  list(JOIN _defined ", " _names)
  message(FATAL_ERROR "internal macros left defined for the user's code: ${_names}")
endif()
message(STATUS "no internal macro but POINTMASS_DETAIL_ALWAYS_INLINE, _IN_ORDER and _UNFUSED_* is left defined")
