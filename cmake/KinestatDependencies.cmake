# SPDX-License-Identifier: BSD-3-Clause
# All dependencies come from Debian packages; nothing is downloaded at build time.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(GMPXX REQUIRED IMPORTED_TARGET gmpxx gmp)
# libyaml (Debian libyaml-dev) parses model files event by event (io/yaml_support.cpp); private.
pkg_check_modules(LIBYAML REQUIRED IMPORTED_TARGET yaml-0.1)

# SuiteSparseQR and OpenBLAS as imported targets (SuiteSparse::SPQR, kinestat::openblas); the
# same file is installed with the CMake package, so that the exported targets carry no path.
include(${CMAKE_CURRENT_LIST_DIR}/kinestatSuiteSparse.cmake)
if(NOT KinestatSuiteSparse_FOUND)
  message(FATAL_ERROR "kinestat needs SuiteSparseQR and OpenBLAS (Debian: libsuitesparse-dev libopenblas-dev)")
endif()
# For the tests and benchmarks that call SuiteSparse themselves.
add_library(kinestat_suitesparse INTERFACE)
target_link_libraries(kinestat_suitesparse INTERFACE SuiteSparse::SPQR kinestat::openblas)

# Optional readers of other programs' formats (docs/formats.md). Each option is ON when its
# Debian package is found; without it the format is refused with "rebuild with ...".
#   libtinyxml2-dev -> URDF (and line numbers for malformed SDFormat), libsdformat-dev -> SDFormat,
#   libmujoco-dev -> MJCF.
find_package(tinyxml2 QUIET)
find_package(sdformat12 QUIET)
# MuJoCo by its header and library, not its CMake package (which needs libgl-dev and libqhull-dev).
include(${CMAKE_CURRENT_LIST_DIR}/kinestatMuJoCo.cmake)
option(KINESTAT_WITH_TINYXML2 "URDF reader (libtinyxml2-dev)" ${tinyxml2_FOUND})
option(KINESTAT_WITH_SDFORMAT "SDFormat reader (libsdformat-dev)" ${sdformat12_FOUND})
option(KINESTAT_WITH_MUJOCO "MJCF reader (libmujoco-dev)" ${KinestatMuJoCo_FOUND})
# The include folders of imported target `imported` and of the imported targets it links,
# without the compiler's own /usr/include (naming it breaks libstdc++'s #include_next).
function(kinestat_include_folders imported out)
  set(folders "")
  set(pending ${imported})
  set(seen "")
  while(pending)
    list(POP_FRONT pending current)
    if(NOT TARGET ${current} OR current IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${current})
    get_target_property(dirs ${current} INTERFACE_INCLUDE_DIRECTORIES)
    if(dirs)
      list(APPEND folders ${dirs})
    endif()
    get_target_property(links ${current} INTERFACE_LINK_LIBRARIES)
    if(links)
      list(APPEND pending ${links})
    endif()
  endwhile()
  list(FILTER folders EXCLUDE REGEX "^/usr/include/?$|\\$<")
  list(REMOVE_DUPLICATES folders)
  set(${out} ${folders} PARENT_SCOPE)
endfunction()

# Adds the readers' libraries to `target` (kinestat), privately: KINESTAT_HAVE_<reader> = 0 or
# 1 and the libraries' include folders go to the reader sources only (so that the rest of the
# library compiles as without them), the libraries to the link. kinestat is a static library,
# so they travel with it: the installed package finds them again (kinestatReaders.cmake,
# included by kinestatConfig.cmake).
function(kinestat_add_readers target)
  set(dir ${PROJECT_SOURCE_DIR}/src/kinestat/io)
  set(readers TINYXML2 SDFORMAT MUJOCO)
  set(packages tinyxml2 sdformat12 mujoco)
  set(imported_targets tinyxml2::tinyxml2 sdformat12::sdformat12 mujoco::mujoco)
  # Which sources use which library (the SDFormat reader checks XML with tinyxml2).
  set(TINYXML2_sources ${dir}/urdf_reader.cpp ${dir}/sdformat_reader.cpp)
  set(SDFORMAT_sources ${dir}/sdformat_reader.cpp)
  set(MUJOCO_sources ${dir}/mjcf_reader.cpp)
  set(dependencies "include(CMakeFindDependencyMacro)\n")
  foreach(reader package imported IN ZIP_LISTS readers packages imported_targets)
    set(have 0)
    if(KINESTAT_WITH_${reader})
      set(have 1)
      if(reader STREQUAL "MUJOCO")
        if(NOT KinestatMuJoCo_FOUND)
          message(FATAL_ERROR "KINESTAT_WITH_MUJOCO needs mujoco/mujoco.h and libmujoco (Debian: libmujoco-dev)")
        endif()
        string(APPEND dependencies "include(\${CMAKE_CURRENT_LIST_DIR}/kinestatMuJoCo.cmake)\n"
               "if(NOT KinestatMuJoCo_FOUND)\n"
               "  set(kinestat_FOUND FALSE)\n"
               "  set(kinestat_NOT_FOUND_MESSAGE \"kinestat was built with the MJCF reader: it needs libmujoco (Debian: libmujoco-dev)\")\n"
               "  return()\n"
               "endif()\n")
      else()
        find_package(${package} REQUIRED)
        string(APPEND dependencies "find_dependency(${package})\n")
      endif()
      # As system headers (-isystem), so that their warnings do not stop a -Werror build.
      kinestat_include_folders(${imported} folders)
      set(options "")
      foreach(folder IN LISTS folders)
        list(APPEND options "-isystem${folder}")
      endforeach()
      set_property(SOURCE ${${reader}_sources} TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_OPTIONS ${options})
      target_link_libraries(${target} PRIVATE $<LINK_ONLY:${imported}>)
    endif()
    set_property(SOURCE ${dir}/urdf_reader.cpp ${dir}/sdformat_reader.cpp ${dir}/mjcf_reader.cpp TARGET_DIRECTORY ${target}
                 APPEND PROPERTY COMPILE_DEFINITIONS KINESTAT_HAVE_${reader}=${have})
  endforeach()
  if(KINESTAT_INSTALL)
    include(GNUInstallDirs)
    file(WRITE ${PROJECT_BINARY_DIR}/kinestatReaders.cmake "# The libraries of kinestat's optional readers.\n${dependencies}")
    install(FILES ${PROJECT_BINARY_DIR}/kinestatReaders.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kinestat)
  endif()
endfunction()
message(STATUS "kinestat readers: URDF ${KINESTAT_WITH_TINYXML2}, SDFormat ${KINESTAT_WITH_SDFORMAT}, MJCF ${KINESTAT_WITH_MUJOCO}")
