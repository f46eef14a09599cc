# SPDX-License-Identifier: BSD-3-Clause
# Imported targets for SuiteSparseQR and the BLAS kinestat pins, found on the machine that uses
# them: SuiteSparse::SPQR (with SuiteSparse::CHOLMOD and SuiteSparse::SuiteSparseConfig, the
# names SuiteSparse 7's own CMake packages use) and kinestat::openblas. Included by kinestat's
# build and, for a static libkinestat, by the installed kinestatConfig.cmake, so that the
# exported targets name these targets and carry no path of the machine kinestat was built on.
# SuiteSparse 5 (Debian 12) ships no CMake package for SPQR: the libraries are found by name.
if(NOT TARGET SuiteSparse::SPQR)
  find_package(SPQR CONFIG QUIET)  # SuiteSparse 7 and later
endif()
if(NOT TARGET SuiteSparse::SPQR)
  find_path(KINESTAT_SUITESPARSE_INCLUDE_DIR SuiteSparseQR.hpp PATH_SUFFIXES suitesparse)
  find_library(KINESTAT_SPQR_LIBRARY spqr)
  find_library(KINESTAT_CHOLMOD_LIBRARY cholmod)
  find_library(KINESTAT_SUITESPARSECONFIG_LIBRARY suitesparseconfig)
  mark_as_advanced(KINESTAT_SUITESPARSE_INCLUDE_DIR KINESTAT_SPQR_LIBRARY KINESTAT_CHOLMOD_LIBRARY
                   KINESTAT_SUITESPARSECONFIG_LIBRARY)
  if(KINESTAT_SUITESPARSE_INCLUDE_DIR AND KINESTAT_SPQR_LIBRARY AND KINESTAT_CHOLMOD_LIBRARY
     AND KINESTAT_SUITESPARSECONFIG_LIBRARY)
    foreach(name IN ITEMS SuiteSparseConfig CHOLMOD SPQR)
      string(TOUPPER ${name} upper)
      add_library(SuiteSparse::${name} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${name} PROPERTIES IMPORTED_LOCATION ${KINESTAT_${upper}_LIBRARY}
                            INTERFACE_INCLUDE_DIRECTORIES ${KINESTAT_SUITESPARSE_INCLUDE_DIR})
    endforeach()
    set_target_properties(SuiteSparse::CHOLMOD PROPERTIES INTERFACE_LINK_LIBRARIES SuiteSparse::SuiteSparseConfig)
    set_target_properties(SuiteSparse::SPQR PROPERTIES INTERFACE_LINK_LIBRARIES SuiteSparse::CHOLMOD)
  endif()
endif()
# Debian's OpenBLAS (libopenblas-dev): SuiteSparse's dense kernels run on it, and kinestat
# calls it to set its threads.
if(NOT TARGET kinestat::openblas)
  find_library(KINESTAT_OPENBLAS_LIBRARY openblas)
  mark_as_advanced(KINESTAT_OPENBLAS_LIBRARY)
  if(KINESTAT_OPENBLAS_LIBRARY)
    add_library(kinestat::openblas UNKNOWN IMPORTED)
    set_target_properties(kinestat::openblas PROPERTIES IMPORTED_LOCATION ${KINESTAT_OPENBLAS_LIBRARY})
  endif()
endif()
if(TARGET SuiteSparse::SPQR AND TARGET kinestat::openblas)
  set(KinestatSuiteSparse_FOUND TRUE)
else()
  set(KinestatSuiteSparse_FOUND FALSE)
endif()
