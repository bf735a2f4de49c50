# SPDX-License-Identifier: BSL-1.0
# cmake -DROOT=<project> -P CheckReleaseTag.cmake
#
# The release a consumer pins is one release: the README's FetchContent GIT_TAG (vX.Y.Z) names
# the newest release of CHANGELOG.md ("## [X.Y.Z] - date"), and config.hpp's version is that
# release or the one after it (0.x: the next minor or patch). Fails naming what disagrees.
file(READ "${ROOT}/README.md" _readme)
file(READ "${ROOT}/CHANGELOG.md" _changelog)
file(READ "${ROOT}/include/pointmass/config.hpp" _config)
string(REGEX MATCH "GIT_TAG +v([0-9]+\\.[0-9]+\\.[0-9]+)" _ "${_readme}")
set(_tag "${CMAKE_MATCH_1}")
string(REGEX MATCH "\n## \\[([0-9]+\\.[0-9]+\\.[0-9]+)\\] - [0-9]" _ "${_changelog}")
set(_released "${CMAKE_MATCH_1}")
foreach(_part IN ITEMS MAJOR MINOR PATCH)
  string(REGEX MATCH "#define POINTMASS_VERSION_${_part} ([0-9]+)" _ "${_config}")
  list(APPEND _version "${CMAKE_MATCH_1}")
endforeach()
list(JOIN _version "." _version)
if(NOT _tag)
  message(FATAL_ERROR "README.md has no FetchContent 'GIT_TAG vX.Y.Z'")
endif()
if(NOT _released)
  message(FATAL_ERROR "CHANGELOG.md names no release ('## [X.Y.Z] - YYYY-MM-DD')")
endif()
if(NOT _tag VERSION_EQUAL _released)
  message(FATAL_ERROR "README.md pins v${_tag}, but CHANGELOG.md's newest release is ${_released}")
endif()
if(_version VERSION_LESS _released)
  message(FATAL_ERROR "config.hpp says ${_version}, older than the release ${_released}")
endif()
message(STATUS "release: README pins v${_tag}, CHANGELOG's newest; config.hpp ${_version}")
