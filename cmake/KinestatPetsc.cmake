# SPDX-License-Identifier: BSD-3-Clause
# The optional distributed backend (src/kinestat/distributed, docs/scaling.md): rank decisions
# and null spaces on PETSc / SLEPc / MUMPS over MPI (Debian: petsc-dev, slepc-dev,
# libopenmpi-dev). Its own library, kinestat_petsc: not part of the installed package and not
# linked into the Python module; the command links it and calls MPI only for `--backend petsc`.
# AUTO builds it when pkg-config finds PETSc and SLEPc and CMake finds MPI. The sanitizer and
# fuzz builds never build it (MPI under ASan is not wanted).
set(KINESTAT_PETSC AUTO CACHE STRING "Distributed backend on PETSc/SLEPc/MUMPS: ON, OFF or AUTO (when PETSc, SLEPc and MPI are found)")
set_property(CACHE KINESTAT_PETSC PROPERTY STRINGS ON OFF AUTO)
set(KINESTAT_HAVE_PETSC OFF)
if(KINESTAT_PETSC STREQUAL "ON" AND (KINESTAT_SANITIZE OR KINESTAT_FUZZ))
  message(FATAL_ERROR "KINESTAT_PETSC=ON is not supported with KINESTAT_SANITIZE or KINESTAT_FUZZ")
endif()
if(NOT KINESTAT_PETSC STREQUAL "OFF" AND NOT KINESTAT_SANITIZE AND NOT KINESTAT_FUZZ)
  pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  pkg_check_modules(SLEPC QUIET IMPORTED_TARGET slepc)
  find_package(MPI QUIET COMPONENTS CXX)
  find_program(KINESTAT_MPIEXEC NAMES mpirun mpiexec)
  if(PETSC_FOUND AND SLEPC_FOUND AND MPI_CXX_FOUND)
    set(KINESTAT_HAVE_PETSC ON)
  elseif(KINESTAT_PETSC STREQUAL "ON")
    message(FATAL_ERROR "KINESTAT_PETSC=ON but PETSc (${PETSC_FOUND}), SLEPc (${SLEPC_FOUND}) or MPI (${MPI_CXX_FOUND}) "
                        "was not found: install petsc-dev slepc-dev libopenmpi-dev openmpi-bin")
  endif()
endif()
message(STATUS "kinestat distributed backend (PETSc/SLEPc/MUMPS): ${KINESTAT_HAVE_PETSC}")
