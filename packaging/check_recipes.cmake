# What can be checked of the recipes without the vcpkg and Conan registries:
#   cmake -DSOURCE=<repository> -DBINARY=<scratch dir> [-DPYTHON=python3] -P check_recipes.cmake
# 1. vcpkg.json is valid JSON with the version of include/pointmass/config.hpp;
# 2. conanfile.py is valid Python;
# 3. the install the recipes run (tests, examples and benchmarks off) puts the files they name
#    where they look: headers, share/cmake/pointmass/pointmassConfig.cmake, pointmass.pc.
file(READ "${SOURCE}/packaging/vcpkg/vcpkg.json" manifest)
string(JSON port_version GET "${manifest}" version)
file(STRINGS "${SOURCE}/include/pointmass/config.hpp" lines
     REGEX "^#define POINTMASS_VERSION_(MAJOR|MINOR|PATCH) [0-9]+$")
set(parts "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE ".* ([0-9]+)$" "\\1" number "${line}")
  list(APPEND parts ${number})
endforeach()
list(JOIN parts "." library_version)
if(NOT port_version STREQUAL library_version)
  message(FATAL_ERROR "vcpkg.json has version ${port_version}, config.hpp ${library_version}")
endif()

if(PYTHON)
  execute_process(COMMAND "${PYTHON}" -c
                  "import ast, sys; ast.parse(open(sys.argv[1]).read())"
                  "${SOURCE}/packaging/conan/conanfile.py" RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "conanfile.py is not valid Python")
  endif()
endif()

file(REMOVE_RECURSE "${BINARY}")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE}" -B "${BINARY}/build"
                        -DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF
                        -DPOINTMASS_BUILD_BENCHMARKS=OFF
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configuring as the recipes do failed")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BINARY}/build" --prefix "${BINARY}/prefix"
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "installing as the recipes do failed")
endif()
foreach(file IN ITEMS include/pointmass/pointmass.hpp include/pointmass/particle_system.hpp
                      share/cmake/pointmass/pointmassConfig.cmake
                      share/cmake/pointmass/pointmassConfigVersion.cmake
                      share/pkgconfig/pointmass.pc)
  if(NOT EXISTS "${BINARY}/prefix/${file}")
    message(FATAL_ERROR "the install lacks ${file}, which the recipes expect")
  endif()
endforeach()
file(GLOB_RECURSE binaries "${BINARY}/prefix/lib/*" "${BINARY}/prefix/bin/*")
if(binaries)
  message(FATAL_ERROR "a header-only install holds binaries: ${binaries}")
endif()
message(STATUS "recipes: manifest ${port_version}, layout ok")
