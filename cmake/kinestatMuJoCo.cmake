# SPDX-License-Identifier: BSD-3-Clause
# mujoco::mujoco from MuJoCo's header and library (Debian: libmujoco-dev), for the MJCF reader;
# sets KinestatMuJoCo_FOUND. Not MuJoCo's own CMake package: Debian's asks for OpenGL
# (find_dependency(OpenGL): libgl-dev, which brings Mesa and LLVM) and names libqhull-dev's
# headers, and the reader uses neither (it includes mujoco/mujoco.h and calls the compiler
# only). Installed with the CMake package, so that a consumer of a static libkinestat finds the
# library again on its own machine (kinestatReaders.cmake).
if(NOT TARGET mujoco::mujoco)
  find_path(KINESTAT_MUJOCO_INCLUDE_DIR mujoco/mujoco.h)
  find_library(KINESTAT_MUJOCO_LIBRARY mujoco)
  mark_as_advanced(KINESTAT_MUJOCO_INCLUDE_DIR KINESTAT_MUJOCO_LIBRARY)
  if(KINESTAT_MUJOCO_INCLUDE_DIR AND KINESTAT_MUJOCO_LIBRARY)
    add_library(mujoco::mujoco UNKNOWN IMPORTED)
    set_target_properties(mujoco::mujoco PROPERTIES
      IMPORTED_LOCATION "${KINESTAT_MUJOCO_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${KINESTAT_MUJOCO_INCLUDE_DIR}")
  endif()
endif()
if(TARGET mujoco::mujoco)
  set(KinestatMuJoCo_FOUND TRUE)
else()
  set(KinestatMuJoCo_FOUND FALSE)
endif()
