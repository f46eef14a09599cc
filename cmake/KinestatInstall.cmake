# SPDX-License-Identifier: BSD-3-Clause
# Install rules and the CMake package: `cmake --install build/release --prefix P` gives
#   P/lib/libkinestat.a, P/include/kinestat/<layer>/*.hpp, P/include/kinestat/kinestat.hpp,
#   P/bin/kinestat (and P/bin/kinestat-mpi with the distributed backend), P/lib/cmake/kinestat/ (kinestatConfig.cmake, version file, targets),
# so that a project finds it with find_package(kinestat) and links kinestat::kinestat.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(KINESTAT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/kinestat)

# SuiteSparse (private, but a static library's link dependencies travel with it): exported
# as kinestat::suitesparse with the library paths found on this machine.
set_target_properties(kinestat_suitesparse PROPERTIES EXPORT_NAME suitesparse)
install(TARGETS kinestat kinestat_suitesparse EXPORT kinestatTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS kinestat_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# `kinestat analyze --backend petsc` runs kinestat-mpi from kinestat's own folder.
if(TARGET kinestat_mpi_cli)
  install(TARGETS kinestat_mpi_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT kinestatTargets NAMESPACE kinestat:: DESTINATION ${KINESTAT_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/kinestatConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/kinestatConfig.cmake INSTALL_DESTINATION ${KINESTAT_CMAKE_DIR})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/kinestatConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/kinestatConfig.cmake ${PROJECT_BINARY_DIR}/kinestatConfigVersion.cmake
              ${KINESTAT_VIEWER_WORK}/viewer_built_in.cmake
        DESTINATION ${KINESTAT_CMAKE_DIR})
# The licence beside the documentation (docs/licensing.md: what the linked libraries imply).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
