// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// MPI, PETSc and SLEPc for the life of one object: the distributed backend's entry point. Only
// `kinestat analyze --backend petsc` and the mpi tests create one; nothing else in kinestat
// calls MPI.

#include <string>

namespace kinestat::distributed {

/// Initialises SLEPc (and with it PETSc and MPI) on construction and finalises them on
/// destruction. Collective over MPI_COMM_WORLD; at most one per process. PETSc errors are
/// returned to kinestat (turned into exceptions by the backend), not printed by PETSc, unless
/// `petsc_traceback`: then PETSc also prints its own traceback (the command sets it from
/// KINESTAT_PETSC_TRACEBACK; the library reads no environment).
class PetscSession {
 public:
  explicit PetscSession(bool petsc_traceback = false);
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

  /// This process's rank in MPI_COMM_WORLD (0: the one that reads the model and writes reports).
  int rank() const { return rank_; }
  /// The number of processes in MPI_COMM_WORLD.
  int size() const { return size_; }

  /// Broadcasts `text` from rank 0 to every process (collective); returns it on every rank.
  std::string broadcast(const std::string& text) const;
  /// Broadcasts `value` from rank 0 (collective).
  long long broadcast(long long value) const;

  /// Ends every process of the run with `exit_code` after an error on this one (MPI_Abort),
  /// so that no process waits forever in a collective call.
  [[noreturn]] static void abort(int exit_code);

 private:
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace kinestat::distributed
