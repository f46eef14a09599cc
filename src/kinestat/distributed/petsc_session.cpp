// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/petsc_session.hpp"

#include <mpi.h>
#include <petscsys.h>
#include <slepcsys.h>

#include <cstdlib>
#include <stdexcept>

namespace kinestat::distributed {

PetscSession::PetscSession(bool petsc_traceback) {
  if (SlepcInitializeNoArguments() != 0) throw std::runtime_error("PETSc/SLEPc could not be initialised");
  // Errors come back as codes; the backend turns them into exceptions with PETSc's message
  // (with petsc_traceback PETSc's default handler stays and prints its own traceback too).
  if (!petsc_traceback) PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

PetscSession::~PetscSession() { SlepcFinalize(); }

std::string PetscSession::broadcast(const std::string& text) const {
  long long size = broadcast(static_cast<long long>(text.size()));
  std::string out = rank_ == 0 ? text : std::string(static_cast<std::size_t>(size), '\0');
  if (size > 0) MPI_Bcast(out.data(), static_cast<int>(size), MPI_CHAR, 0, PETSC_COMM_WORLD);
  return out;
}

long long PetscSession::broadcast(long long value) const {
  MPI_Bcast(&value, 1, MPI_LONG_LONG, 0, PETSC_COMM_WORLD);
  return value;
}

void PetscSession::abort(int exit_code) {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

}  // namespace kinestat::distributed
