# SPDX-License-Identifier: BSD-3-Clause
# The optional distributed backend (src/kinestat/distributed, docs/scaling.md): rank decisions by
# domain decomposition over MPI, each process's part factored by SuiteSparseQR (Debian:
# libopenmpi-dev openmpi-bin). Its own library, kinestat_petsc: not part of the installed package
# and not linked into the Python module; the command links it and calls MPI only for
# `--backend petsc`. The option and target names keep "petsc" from the PETSc/MUMPS backend this
# one replaced (CI and the README name them). AUTO builds it when CMake finds MPI and mpirun.
# The sanitizer and fuzz builds never build it (MPI under ASan is not wanted).
set(KINESTAT_PETSC AUTO CACHE STRING "Distributed backend over MPI: ON, OFF or AUTO (when MPI is found)")
set_property(CACHE KINESTAT_PETSC PROPERTY STRINGS ON OFF AUTO)
set(KINESTAT_HAVE_PETSC OFF)
if(KINESTAT_PETSC STREQUAL "ON" AND (KINESTAT_SANITIZE OR KINESTAT_FUZZ))
  message(FATAL_ERROR "KINESTAT_PETSC=ON is not supported with KINESTAT_SANITIZE or KINESTAT_FUZZ")
endif()
if(NOT KINESTAT_PETSC STREQUAL "OFF" AND NOT KINESTAT_SANITIZE AND NOT KINESTAT_FUZZ)
  find_package(MPI QUIET COMPONENTS CXX)
  find_program(KINESTAT_MPIEXEC NAMES mpirun mpiexec)
  if(MPI_CXX_FOUND AND KINESTAT_MPIEXEC)
    set(KINESTAT_HAVE_PETSC ON)
  elseif(KINESTAT_PETSC STREQUAL "ON")
    message(FATAL_ERROR "KINESTAT_PETSC=ON but MPI (${MPI_CXX_FOUND}) or mpirun (${KINESTAT_MPIEXEC}) was not found: "
                        "install libopenmpi-dev openmpi-bin")
  endif()
endif()
message(STATUS "kinestat distributed backend (MPI): ${KINESTAT_HAVE_PETSC}")
