// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// MPI for the life of one object: the distributed backend's entry point. Only
// `kinestat analyze --backend petsc` and the mpi tests create one; nothing else in kinestat
// calls MPI. (The option keeps its name from the PETSc/MUMPS backend this one replaced; the
// decomposition needs MPI and SuiteSparseQR only, and no longer initialises PETSc, whose start
// cost every run about half a second.)

namespace kinestat::distributed {

/// Initialises MPI on construction and finalises it on destruction. Collective over
/// MPI_COMM_WORLD; at most one per process.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// This process's rank in MPI_COMM_WORLD (0: the one that writes reports).
  int rank() const { return rank_; }
  /// The number of processes in MPI_COMM_WORLD.
  int size() const { return size_; }

  /// Ends every process of the run with `exit_code` after an error on this one (MPI_Abort),
  /// so that no process waits forever in a collective call.
  [[noreturn]] static void abort(int exit_code);

 private:
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace kinestat::distributed
