# SPDX-License-Identifier: BSL-1.0
"""Conan 2 recipe for pointmass, a header-only C++20 library.

Build from a checkout (from the repository's root):
    conan create packaging/conan --version 0.1.0
The recipe exports the headers and the CMake files from the checkout; see packaging/README.md.
"""
import os

from conan import ConanFile
from conan.tools.build import check_min_cppstd
from conan.tools.cmake import CMake, CMakeToolchain, cmake_layout
from conan.tools.files import copy

required_conan_version = ">=2.0"


class PointmassConan(ConanFile):
    name = "pointmass"
    license = "BSL-1.0"
    description = ("Header-only C++20 Newtonian point-mass (particle) integration with damping "
                   "and position policies, a structure-of-arrays batch, and optional "
                   "Boost.Units quantities.")
    topics = ("physics", "particles", "integration", "header-only", "game-physics")
    package_type = "header-library"
    settings = "os", "arch", "compiler", "build_type"
    options = {"units": [True, False]}
    default_options = {"units": False}
    no_copy_source = True

    def export_sources(self):
        root = os.path.join(self.recipe_folder, "..", "..")
        for pattern in ("CMakeLists.txt", "cmake/*", "include/*", "LICENSE_1_0.txt",
                        "README.md"):
            copy(self, pattern, src=root, dst=self.export_sources_folder)

    def layout(self):
        cmake_layout(self)

    def requirements(self):
        if self.options.units:
            self.requires("boost/[>=1.74]", options={"header_only": True})

    def validate(self):
        check_min_cppstd(self, 20)

    def package_id(self):
        self.info.clear()

    def generate(self):
        toolchain = CMakeToolchain(self)
        toolchain.cache_variables["POINTMASS_BUILD_TESTS"] = False
        toolchain.cache_variables["POINTMASS_BUILD_EXAMPLES"] = False
        toolchain.cache_variables["POINTMASS_BUILD_BENCHMARKS"] = False
        toolchain.cache_variables["POINTMASS_INSTALL"] = True
        if not self.options.units:  # no pointmass::units, whether or not Boost is installed
            toolchain.cache_variables["CMAKE_DISABLE_FIND_PACKAGE_Boost"] = True
        toolchain.generate()

    def build(self):
        pass  # header-only: nothing to build

    def package(self):
        cmake = CMake(self)
        cmake.configure()
        cmake.install()
        copy(self, "LICENSE_1_0.txt", src=self.source_folder,
             dst=os.path.join(self.package_folder, "licenses"))

    def package_info(self):
        self.cpp_info.bindirs = []
        self.cpp_info.libdirs = []
        self.cpp_info.set_property("cmake_file_name", "pointmass")
        # The package's own CMake files are not used: Conan generates its own.
        core = self.cpp_info.components["core"]
        core.set_property("cmake_target_name", "pointmass::pointmass")
        core.set_property("pkg_config_name", "pointmass")
        core.bindirs = []
        core.libdirs = []
        if self.options.units:
            units = self.cpp_info.components["units"]
            units.set_property("cmake_target_name", "pointmass::units")
            units.requires = ["core", "boost::headers"]
            units.bindirs = []
            units.libdirs = []
