# SPDX-License-Identifier: BSL-1.0
# vcpkg port of pointmass (header-only). Replace REPO/REF/SHA512 with the published
# repository and release tag before submitting; see packaging/README.md.
set(VCPKG_BUILD_TYPE release)  # header-only: nothing differs between configurations

vcpkg_from_github(
  OUT_SOURCE_PATH SOURCE_PATH
  REPO pointmass/pointmass
  REF "v${VERSION}"
  SHA512 0
  HEAD_REF main
)

# Without the "units" feature, no pointmass::units, whether or not Boost is installed.
set(feature_options "")
if(NOT "units" IN_LIST FEATURES)
  list(APPEND feature_options -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON)
endif()

# The CMake package goes straight to share/pointmass, where vcpkg looks for it, and the
# licence beside it. (packaging/check_recipes.cmake installs with these same -D options and
# builds the usage below against the result.)
vcpkg_cmake_configure(
  SOURCE_PATH "${SOURCE_PATH}"
  OPTIONS
    -DPOINTMASS_BUILD_TESTS=OFF
    -DPOINTMASS_BUILD_EXAMPLES=OFF
    -DPOINTMASS_BUILD_BENCHMARKS=OFF
    -DPOINTMASS_INSTALL=ON
    -DPOINTMASS_INSTALL_CMAKEDIR=share/pointmass
    -DPOINTMASS_INSTALL_LICENSEDIR=share/pointmass
    ${feature_options}
)
vcpkg_cmake_install()
vcpkg_cmake_config_fixup(CONFIG_PATH share/pointmass)
vcpkg_fixup_pkgconfig()

file(INSTALL "${CMAKE_CURRENT_LIST_DIR}/usage" DESTINATION "${CURRENT_PACKAGES_DIR}/share/${PORT}")
vcpkg_install_copyright(FILE_LIST "${SOURCE_PATH}/LICENSE_1_0.txt")
