# SPDX-License-Identifier: BSL-1.0
# What can be checked of the recipes without vcpkg, Conan or their registries:
#   cmake -DSOURCE=<repository> -DBINARY=<scratch dir> [-DPYTHON=python3]
#         [-DCOMPILER=c++] [-DGENERATOR=Ninja] -P check_recipes.cmake
# 1. vcpkg.json is valid JSON; its version is config.hpp's, its licence the project's
#    (POINTMASS_SPDX_LICENSE in CMakeLists.txt); conanfile.py is valid Python and declares the
#    same name and licence; packaging/README.md's `conan create` names the same version;
# 2. the licence file the recipes install exists, is the Boost Software License 1.0, and is
#    the file portfile.cmake and conanfile.py name;
# 3. an install configured with the portfile's own -D options (read from portfile.cmake) puts
#    the files where vcpkg looks, with no binaries; the CMake lines of the port's `usage` build
#    and run a program against it, without and with the units feature;
# 4. an install configured with the cache variables conanfile.py's generate() sets exports the
#    targets its package_info() names.
# Not checked (needs the tools): vcpkg_from_github's download and hash, vcpkg's and Conan's
# own post-build checks, the CMake files Conan generates in place of the package's own.
set(failures "")
macro(fail text)
  list(APPEND failures "${text}")
  message(SEND_ERROR "${text}")
endmacro()

# --- 1. versions, names and licences agree ---------------------------------------------------
file(STRINGS "${SOURCE}/include/pointmass/config.hpp" lines
     REGEX "^#define POINTMASS_VERSION_(MAJOR|MINOR|PATCH) [0-9]+$")
set(parts "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE ".* ([0-9]+)$" "\\1" number "${line}")
  list(APPEND parts ${number})
endforeach()
list(JOIN parts "." library_version)

file(STRINGS "${SOURCE}/CMakeLists.txt" license_line REGEX "^set\\(POINTMASS_SPDX_LICENSE ")
string(REGEX REPLACE "^set\\(POINTMASS_SPDX_LICENSE \"([^\"]+)\"\\)$" "\\1" project_license
       "${license_line}")
if(NOT project_license STREQUAL "BSL-1.0")
  fail("CMakeLists.txt declares licence '${project_license}', not BSL-1.0")
endif()

file(READ "${SOURCE}/packaging/vcpkg/vcpkg.json" manifest)
string(JSON port_name GET "${manifest}" name)
string(JSON port_version GET "${manifest}" version)
string(JSON port_license ERROR_VARIABLE json_error GET "${manifest}" license)
if(NOT port_name STREQUAL "pointmass")
  fail("vcpkg.json names '${port_name}'")
endif()
if(NOT port_version STREQUAL library_version)
  fail("vcpkg.json has version ${port_version}, config.hpp ${library_version}")
endif()
if(NOT port_license STREQUAL project_license)
  fail("vcpkg.json has licence '${port_license}', CMakeLists.txt '${project_license}'")
endif()

if(PYTHON)
  execute_process(COMMAND "${PYTHON}" -c [=[
import ast, sys
tree = ast.parse(open(sys.argv[1]).read())
fields = {}
for node in ast.walk(tree):
    if isinstance(node, ast.ClassDef):
        for item in node.body:
            if isinstance(item, ast.Assign) and isinstance(item.value, ast.Constant):
                for target in item.targets:
                    if isinstance(target, ast.Name):
                        fields[target.id] = item.value.value
print(f"{fields.get('name')};{fields.get('license')};{fields.get('package_type')}", end="")
]=] "${SOURCE}/packaging/conan/conanfile.py"
                  RESULT_VARIABLE result OUTPUT_VARIABLE conan_fields ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    fail("conanfile.py is not valid Python: ${error}")
  else()
    list(GET conan_fields 0 conan_name)
    list(GET conan_fields 1 conan_license)
    list(GET conan_fields 2 conan_type)
    if(NOT conan_name STREQUAL "pointmass" OR NOT conan_type STREQUAL "header-library")
      fail("conanfile.py: name '${conan_name}', package_type '${conan_type}'")
    endif()
    if(NOT conan_license STREQUAL project_license)
      fail("conanfile.py has licence '${conan_license}', CMakeLists.txt '${project_license}'")
    endif()
  endif()
else()
  message(STATUS "python3 not found: conanfile.py not parsed")
endif()
file(READ "${SOURCE}/packaging/README.md" packaging_readme)
string(REGEX MATCHALL "conan create packaging/conan --version [0-9.]+" commands "${packaging_readme}")
if(NOT commands)
  fail("packaging/README.md gives no 'conan create ... --version'")
endif()
foreach(command IN LISTS commands)
  if(NOT command MATCHES " ${library_version}$")
    fail("packaging/README.md: '${command}', but the library is ${library_version}")
  endif()
endforeach()

# --- 2. the licence file -----------------------------------------------------------------------
set(license_file "${SOURCE}/LICENSE_1_0.txt")
if(NOT EXISTS "${license_file}")
  fail("LICENSE_1_0.txt is missing")
else()
  file(STRINGS "${license_file}" first_line LIMIT_COUNT 1)
  if(NOT first_line STREQUAL "Boost Software License - Version 1.0 - August 17th, 2003")
    fail("LICENSE_1_0.txt does not start as the Boost Software License 1.0: ${first_line}")
  endif()
endif()
file(READ "${SOURCE}/packaging/vcpkg/portfile.cmake" portfile)
if(NOT portfile MATCHES "vcpkg_install_copyright\\(FILE_LIST \"\\\${SOURCE_PATH}/LICENSE_1_0.txt\"\\)")
  fail("portfile.cmake does not install LICENSE_1_0.txt as the copyright")
endif()
file(READ "${SOURCE}/packaging/conan/conanfile.py" conanfile)
string(REGEX MATCHALL "\"LICENSE_1_0.txt\"" conan_mentions "${conanfile}")
list(LENGTH conan_mentions conan_mention_count)
if(conan_mention_count LESS 2)
  fail("conanfile.py must export LICENSE_1_0.txt and copy it to licenses/ (${conan_mention_count} mentions)")
endif()

# --- helpers: install with options, build a consumer -------------------------------------------
set(generator_args "")
if(GENERATOR)
  set(generator_args -G "${GENERATOR}")
endif()
set(compiler_args "")
if(COMPILER)
  set(compiler_args "-DCMAKE_CXX_COMPILER=${COMPILER}")
endif()
function(install_with name)
  file(REMOVE_RECURSE "${BINARY}/${name}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE}" -B "${BINARY}/${name}/build"
                          ${generator_args} ${compiler_args} ${ARGN}
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    fail("${name}: configuring with ${ARGN} failed:\n${output}")
    return()
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BINARY}/${name}/build"
                          --prefix "${BINARY}/${name}/prefix"
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    fail("${name}: installing failed:\n${output}")
  endif()
endfunction()
# Builds and runs main.cpp (including HEADER) with CMAKE_LINES as its CMakeLists' body.
function(build_consumer name prefix header cmake_lines)
  set(dir "${BINARY}/${name}")
  file(REMOVE_RECURSE "${dir}")
  file(WRITE "${dir}/CMakeLists.txt" "cmake_minimum_required(VERSION 3.21)\nproject(usage LANGUAGES CXX)\nadd_executable(main main.cpp)\n${cmake_lines}\n")
  file(WRITE "${dir}/main.cpp" "#include <${header}>\nint main() {\n  pointmass::Particle<double> particle;\n  particle.integrate(0.5);\n  return particle.position().y == 0.0 && pointmass::earth_gravity<double> > 9 ? 0 : 1;\n}\n")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${dir}" -B "${dir}/build" ${generator_args}
                          ${compiler_args} "-DCMAKE_PREFIX_PATH=${prefix}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(result EQUAL 0)
    execute_process(COMMAND "${CMAKE_COMMAND}" --build "${dir}/build"
                    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  endif()
  if(result EQUAL 0)
    file(GLOB_RECURSE program "${dir}/build/main" "${dir}/build/*/main")
    execute_process(COMMAND ${program} RESULT_VARIABLE result)
  endif()
  if(NOT result EQUAL 0)
    fail("${name}: the lines\n${cmake_lines}\ndo not build and run against ${prefix}:\n${output}")
  endif()
endfunction()

# --- 3. the vcpkg port -----------------------------------------------------------------------------
string(REGEX MATCHALL "\n    -D[A-Za-z_]+=[^\n]+" port_options "${portfile}")
string(REPLACE "\n    " "" port_options "${port_options}")
if(NOT port_options MATCHES "POINTMASS_INSTALL_CMAKEDIR=share/pointmass")
  fail("portfile.cmake: no -DPOINTMASS_INSTALL_CMAKEDIR=share/pointmass among ${port_options}")
endif()
file(READ "${SOURCE}/packaging/vcpkg/usage" usage)
string(REGEX MATCHALL "\n  (find_package|target_link_libraries)\\([^\n]+" usage_lines "${usage}")
string(REPLACE "\n  " "" usage_lines "${usage_lines}")
list(LENGTH usage_lines usage_count)
if(NOT usage_count EQUAL 4)
  fail("usage: expected two find_package and two target_link_libraries lines: ${usage_lines}")
else()
  list(SUBLIST usage_lines 0 2 core_lines)
  list(SUBLIST usage_lines 2 2 units_lines)
  list(JOIN core_lines "\n" core_lines)
  list(JOIN units_lines "\n" units_lines)
  # Without the units feature, as the portfile configures it (Boost disabled).
  install_with(vcpkg ${port_options} -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON)
  set(prefix "${BINARY}/vcpkg/prefix")
  foreach(file IN ITEMS include/pointmass/pointmass.hpp include/pointmass/units.hpp
                        share/pointmass/pointmassConfig.cmake
                        share/pointmass/pointmassConfigVersion.cmake
                        share/pointmass/pointmassTargets.cmake
                        share/pointmass/LICENSE_1_0.txt share/pkgconfig/pointmass.pc)
    if(NOT EXISTS "${prefix}/${file}")
      fail("vcpkg: the install lacks ${file}")
    endif()
  endforeach()
  if(EXISTS "${prefix}/share/pointmass/pointmassUnitsTargets.cmake")
    fail("vcpkg: without the units feature the install has pointmass::units")
  endif()
  file(GLOB_RECURSE binaries "${prefix}/lib/*" "${prefix}/bin/*")
  if(binaries)
    fail("vcpkg: a header-only install holds binaries: ${binaries}")
  endif()
  build_consumer(vcpkg-usage "${prefix}" pointmass/pointmass.hpp "${core_lines}")
  # With the units feature: Boost found, pointmass::units installed and usable.
  install_with(vcpkg-units ${port_options})
  build_consumer(vcpkg-usage-units "${BINARY}/vcpkg-units/prefix" pointmass/units.hpp
                 "${units_lines}")
endif()

# --- 4. the Conan recipe's install ----------------------------------------------------------------
string(REGEX MATCHALL "cache_variables\\[\"[A-Za-z_]+\"\\] = (True|False)" conan_settings
       "${conanfile}")
set(conan_options "")
foreach(setting IN LISTS conan_settings)
  string(REGEX REPLACE "cache_variables\\[\"([A-Za-z_]+)\"\\] = True" "-D\\1=ON" setting "${setting}")
  string(REGEX REPLACE "cache_variables\\[\"([A-Za-z_]+)\"\\] = False" "-D\\1=OFF" setting "${setting}")
  list(APPEND conan_options "${setting}")
endforeach()
if(NOT conan_options MATCHES "POINTMASS_BUILD_TESTS=OFF")
  fail("conanfile.py does not turn the tests off: ${conan_options}")
endif()
# As with options units=True: Boost not disabled, so both targets are exported.
list(FILTER conan_options EXCLUDE REGEX "CMAKE_DISABLE_FIND_PACKAGE_Boost")
install_with(conan ${conan_options})
string(REGEX MATCHALL "set_property\\(\"cmake_target_name\", \"[a-z:]+\"\\)" conan_targets "${conanfile}")
foreach(target IN LISTS conan_targets)
  string(REGEX REPLACE ".*\"([a-z:]+)\"\\)$" "\\1" target "${target}")
  file(GLOB exported "${BINARY}/conan/prefix/share/cmake/pointmass/*Targets.cmake")
  set(found FALSE)
  foreach(file IN LISTS exported)
    file(READ "${file}" text)
    if(text MATCHES "add_library\\(${target} INTERFACE IMPORTED\\)")
      set(found TRUE)
    endif()
  endforeach()
  if(NOT found)
    fail("conanfile.py declares ${target}, which the package does not export")
  endif()
endforeach()

if(failures)
  list(LENGTH failures count)
  message(FATAL_ERROR "recipes: ${count} check(s) failed")
endif()
message(STATUS "recipes: version ${port_version}, licence ${port_license}; vcpkg install and "
               "usage (with and without units), Conan install and targets: ok")
