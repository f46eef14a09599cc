// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The rank of a large sparse matrix decided on many processes by domain decomposition with the
// serial sparse QR (docs/scaling.md, "The distributed rank decision"): rank 0 holds the matrix,
// splits its columns into one interior per process and an interface (partition_columns) and
// sends each process only the rows that touch its interior; each process reduces
// the rows that touch its interior with SuiteSparseQR at the serial rule's absolute threshold
// (reduce_interior) to a block on the interface of at most its interface columns' rows; the
// blocks and the interface-only rows are reduced in a tree of merges, one separator at a time,
// at the same threshold (reduce_interface_tree). rank(A) = Σ interior ranks + Σ the merges' ranks.

#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"

namespace kinestat::distributed {

/// Outcome of a decomposed rank decision; the same on every process but where noted.
struct DecomposedRank {
  /// The decision in the serial sparse form: rank, threshold, largest (σ_max, the serial
  /// Lanczos estimate), rounding_level, smallest_kept (the smallest kept |R_kk| over the
  /// interiors' and the interface's factors), largest_dropped 0 (SuiteSparseQR drops columns
  /// without reporting them, as in the serial path), `sparse` set.
  linalg::RankDecision decision;
  int processes = 1;
  /// Columns of the matrix factored (A, or Aᵀ when A is wider than tall, as the serial path
  /// chooses) in the interface, and the rows stacked at the interface tree's merges (the
  /// processes' blocks and the interface-only rows; at P = 2 the one stack). 0 at P = 1 (no
  /// decomposition).
  Eigen::Index interface_columns = 0, interface_rows = 0;
  std::vector<Eigen::Index> interior_ranks;  ///< per process (at P = 1: the whole rank)
  Eigen::Index interface_rank = 0;  ///< Σ of the interface tree's merges' ranks
  /// Wall time, seconds: σ_max and the threshold (rank 0), the slowest process's interior
  /// (partition, assembly, factorisations, compression), the interface tree on rank 0 (from
  /// the end of its own interior, so including its wait for the others').
  double threshold_seconds = 0.0, interior_seconds = 0.0, interface_seconds = 0.0;
  /// Per process (index = MPI rank; rank 0 only): peak resident memory, the peak when the
  /// decision began (reading the model and building the matrix: rank 0 only, since the others
  /// receive their rows), and SuiteSparse's own count of its factorisations' peak, bytes.
  std::vector<std::size_t> peak_memory, peak_before_decision, factor_memory;
  /// On processes other than 0: the exit code rank 0 passed to cancel_decomposed_rank when it
  /// could not build the matrix (nothing was decided); 0 otherwise.
  int cancelled = 0;
};

/// Which matrix is factored: rank(A) = rank(Aᵀ), but which one a rank-revealing QR factors
/// decides which near-threshold values it keeps, so the backend factors the serial path's.
enum class FactoredSide {
  taller,      ///< A, or Aᵀ when A is wider than tall (linalg::sparse_numerical_rank: frameworks)
  transposed,  ///< Aᵀ always (a network's rank K from the QR of Kᵀ, network::analyse_network_sparse)
};

/// Decides rank(a) on all processes of MPI_COMM_WORLD (collective; without MPI initialised,
/// the one process alone). Only rank 0's `a` and `tolerance` are read (the other processes may
/// pass an empty matrix and a default tolerance): rank 0 computes the serial rule's threshold
/// (linalg::sparse_rank_threshold), partitions the columns and sends every other process the
/// rows that touch its interior, then releases `a` (taken over: on return it is empty; a copy
/// is made by passing Eigen::SparseMatrix<double>(m)). At one process the decision is the serial one:
/// linalg::sparse_numerical_rank with `column_groups` (a framework's node of each coordinate)
/// for FactoredSide::taller, the counts-only QR of aᵀ for FactoredSide::transposed. Throws
/// std::bad_alloc when memory runs out and std::runtime_error when SuiteSparseQR fails; the
/// caller aborts the run (the other processes would wait in a collective call).
DecomposedRank decomposed_rank(Eigen::SparseMatrix<double>&& a, const linalg::RankTolerance& tolerance,
                               const std::vector<Eigen::Index>& column_groups = {},
                               FactoredSide side = FactoredSide::taller);

/// On rank 0 instead of decomposed_rank, when the matrix cannot be built (bad model): the other
/// processes' decomposed_rank returns at once with DecomposedRank::cancelled = `exit_code`.
/// Collective; does nothing without MPI or at one process.
void cancel_decomposed_rank(int exit_code);

}  // namespace kinestat::distributed
