# SPDX-License-Identifier: BSD-3-Clause
# A Debian package of what `cmake --install` installs: `cpack -G DEB` in a build configured
# with -DCMAKE_INSTALL_PREFIX=/usr (scripts/check-deb.sh builds one with the shared library and
# installs it into a clean Debian 12 root). Depends: the Debian runtime packages of the
# libraries the programs link (found by dpkg-shlibdeps, package dpkg-dev) and, with the Python
# module, python3 and python3-numpy.
set(CPACK_PACKAGE_NAME kinestat)
set(CPACK_PACKAGE_VENDOR "the kinestat authors")
set(CPACK_PACKAGE_CONTACT "the kinestat authors <kinestat@users.noreply.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "how free and how constrained a mechanism, flexure or structure is")
set(CPACK_PACKAGE_DESCRIPTION "kinestat reads a coupling network, framework or structure model and tells its
nett degrees of freedom and constraint, which motions and self-stresses exist and
where, and one minimal set of changes that makes the design exactly constrained.
This package holds the command kinestat, the C++ library with its headers, CMake
package and pkg-config file, and the Python module.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # kinestat_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The package's own libkinestat.so.0: its shlibs file is generated, and dpkg-shlibdeps finds the
# library (needed by the command and the Python module) in the build tree.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_BINARY_DIR}/src/kinestat)
set(kinestat_depends "")
if(KINESTAT_PYTHON_BUILT)
  set(kinestat_depends "python3, python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${kinestat_depends}")
# What a C++ program that includes kinestat's headers needs (public dependencies), and, for the
# static library, what its link needs.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libeigen3-dev, libgmp-dev, nlohmann-json3-dev, pkg-config")
include(CPack)
