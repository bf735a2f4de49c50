# vcpkg port of pointmass (header-only). Replace REPO/REF/SHA512 with the published
# repository and release tag before submitting; see packaging/README.md.
vcpkg_from_github(
  OUT_SOURCE_PATH SOURCE_PATH
  REPO pointmass/pointmass
  REF "v${VERSION}"
  SHA512 0
  HEAD_REF main
)

vcpkg_cmake_configure(
  SOURCE_PATH "${SOURCE_PATH}"
  OPTIONS
    -DPOINTMASS_BUILD_TESTS=OFF
    -DPOINTMASS_BUILD_EXAMPLES=OFF
    -DPOINTMASS_BUILD_BENCHMARKS=OFF
)
vcpkg_cmake_install()

# The package installs its CMake files to share/cmake/pointmass and pointmass.pc to
# share/pkgconfig; move them where vcpkg expects them.
vcpkg_cmake_config_fixup(CONFIG_PATH share/cmake/pointmass)
vcpkg_fixup_pkgconfig()

# Header-only: nothing per configuration.
file(REMOVE_RECURSE "${CURRENT_PACKAGES_DIR}/debug")
set(VCPKG_POLICY_EMPTY_PACKAGE enabled)

file(INSTALL "${CMAKE_CURRENT_LIST_DIR}/usage" DESTINATION "${CURRENT_PACKAGES_DIR}/share/${PORT}")
vcpkg_install_copyright(FILE_LIST "${SOURCE_PATH}/LICENSE")
