# SPDX-License-Identifier: BSD-3-Clause
# Install rules and the CMake package: `cmake --install build/release --prefix P` gives
#   P/lib/libkinestat.a (or, with KINESTAT_SHARED=ON, libkinestat.so.0.x.y with its SONAME link
#   libkinestat.so.0 and the development link libkinestat.so), P/include/kinestat/<layer>/*.hpp,
#   P/include/kinestat/kinestat.hpp, P/bin/kinestat (and P/bin/kinestat-mpi with the distributed
#   backend), P/lib/cmake/kinestat/ (kinestatConfig.cmake, version file, targets) and
#   P/lib/pkgconfig/kinestat.pc,
# so that a project finds it with find_package(kinestat) and links kinestat::kinestat, or with
# `pkg-config kinestat` (`pkg-config --static` for the static library).
# Components: Runtime (the library's SONAME file, the commands), Development (headers, the
# static library or development link, CMake package, pkg-config file), python (python/).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(KINESTAT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/kinestat)

install(TARGETS kinestat EXPORT kinestatTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Runtime NAMELINK_COMPONENT Development
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
        FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT Development)
install(TARGETS kinestat_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
# `kinestat analyze --backend petsc` runs kinestat-mpi from kinestat's own folder.
if(TARGET kinestat_mpi_cli)
  install(TARGETS kinestat_mpi_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
endif()
# The JSON Schemas of model files and reports (schemas/; docs/report.md, "Schemas and versions").
install(DIRECTORY ${PROJECT_SOURCE_DIR}/schemas/ DESTINATION ${CMAKE_INSTALL_DATADIR}/kinestat/schemas COMPONENT Runtime
        FILES_MATCHING PATTERN "*.schema.json")
# A shared libkinestat installed outside /usr: the commands find it beside them ($ORIGIN is
# where the program is); in /usr the dynamic linker finds it without a search path, as Debian wants.
if(KINESTAT_SHARED AND NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  foreach(program IN ITEMS kinestat_cli kinestat_mpi_cli)
    if(TARGET ${program})
      set_target_properties(${program} PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
    endif()
  endforeach()
endif()
install(EXPORT kinestatTargets NAMESPACE kinestat:: DESTINATION ${KINESTAT_CMAKE_DIR} COMPONENT Development)

# A static libkinestat brings its private dependencies to the consumer's link: the config
# finds them again there (SuiteSparse and OpenBLAS through kinestatSuiteSparse.cmake, the
# readers' libraries through kinestatReaders.cmake); a shared one has them in its own DT_NEEDED.
if(KINESTAT_SHARED)
  set(KINESTAT_STATIC_LIBRARY FALSE)
else()
  set(KINESTAT_STATIC_LIBRARY TRUE)
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/kinestatConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/kinestatConfig.cmake INSTALL_DESTINATION ${KINESTAT_CMAKE_DIR})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/kinestatConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/kinestatConfig.cmake ${PROJECT_BINARY_DIR}/kinestatConfigVersion.cmake
              ${KINESTAT_VIEWER_WORK}/viewer_built_in.cmake ${PROJECT_SOURCE_DIR}/cmake/kinestatSuiteSparse.cmake
              ${PROJECT_SOURCE_DIR}/cmake/kinestatMuJoCo.cmake
        DESTINATION ${KINESTAT_CMAKE_DIR} COMPONENT Development)

# pkg-config: the prefix is found from the file's own folder (${pcfiledir}), so the file is
# right wherever `cmake --install --prefix` puts it. A static library lists its private
# libraries (pkg-config --static); a shared one needs none of them to be installed.
string(REGEX REPLACE "[^/]+" ".." kinestat_pc_up "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
set(KINESTAT_PC_PRIVATE "")
# Libraries only (no Requires.private): their compile flags are not kinestat's concern, and some
# (ignition-math6 under sdformat12) would add -std=c++17 to a consumer's --cflags.
if(KINESTAT_STATIC_LIBRARY)
  set(libraries "-lfmt -lyaml -lspqr -lcholmod -lsuitesparseconfig -lopenblas")
  if(KINESTAT_WITH_SDFORMAT)
    string(APPEND libraries " -lsdformat12")
  endif()
  if(KINESTAT_WITH_TINYXML2)
    string(APPEND libraries " -ltinyxml2")
  endif()
  if(KINESTAT_WITH_MUJOCO)
    string(APPEND libraries " -lmujoco")
  endif()
  if(KINESTAT_FLINT)  # the exact path's elimination (cmake/KinestatFlint.cmake)
    string(APPEND libraries " -lflint")
  endif()
  set(KINESTAT_PC_PRIVATE "Libs.private: ${libraries} -lstdc++ -lm\n")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/kinestat.pc.in ${PROJECT_BINARY_DIR}/kinestat.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/kinestat.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT Development)

# The licence beside the documentation (docs/licensing.md: what the linked libraries imply).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT Runtime)
