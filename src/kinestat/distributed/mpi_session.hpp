// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// MPI for the life of one object: the distributed backend's entry point. Only
// `kinestat analyze --backend petsc` and the mpi tests create one; nothing else in kinestat
// calls MPI. (The option keeps its name from the PETSc/MUMPS backend this one replaced; the
// decomposition needs MPI and SuiteSparseQR only, and no longer initialises PETSc, whose start
// cost every run about half a second.)

namespace kinestat::distributed {

/// Initialises MPI on construction (unless `initialise` is false: a process alone in its run,
/// which then decides serially; see started_alone) and finalises it on destruction. Collective
/// over MPI_COMM_WORLD; at most one per process.
class MpiSession {
 public:
  explicit MpiSession(bool initialise = true);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// This process's rank in MPI_COMM_WORLD (0: the one that writes reports; 0 without MPI).
  int rank() const { return rank_; }
  /// The number of processes in MPI_COMM_WORLD (1 without MPI).
  int size() const { return size_; }
  /// Whether this session initialised MPI.
  bool initialised() const { return initialised_; }

  /// Ends every process of the run with `exit_code` after an error on this one (MPI_Abort when
  /// MPI is initialised, so that no process waits forever in a collective call).
  [[noreturn]] static void abort(int exit_code);

 private:
  int rank_ = 0;
  int size_ = 1;
  bool initialised_ = false;
};

/// This process's rank in MPI_COMM_WORLD, 0 when MPI is not initialised (one process).
int world_rank();
/// The number of processes in MPI_COMM_WORLD, 1 when MPI is not initialised.
int world_size();

/// Whether the environment shows this process to be the only one of its run: a launcher's
/// size variable equal to 1 (OpenMPI's OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE as MPICH's Hydra
/// and srun set it), or no launcher variable at all (OMPI_COMM_WORLD_*, PMI_*, PMIX_* unset:
/// started without mpirun). Any other launcher variable without a size reads as "not alone", so that an
/// unknown launcher still gets MPI. `environment` is a NULL-terminated list of NAME=VALUE
/// strings (the caller's environ: the library reads no environment itself). At P = 1 the
/// decision is the serial one, and OpenMPI's MPI_Init alone costs about 0.5 s of wall time
/// (docs/scaling.md), so the command does not initialise MPI then.
bool started_alone(const char* const* environment);

}  // namespace kinestat::distributed
