// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The interface of the distributed rank decision reduced in a tree rather than on rank 0 alone
// (docs/scaling.md, "The interface in a tree"). The parts of a strip partition lie in a row,
// separator k between parts k and k + 1, and each process's interface block touches only the
// separators beside its part. Neighbouring groups of parts merge in log₂ P stages: the root of
// the left group stacks both groups' blocks with the interface rows of the separator between
// them, and reduces that separator's columns as a process reduces its interior
// (reduce_interior at the same threshold), keeping a block on the group's two outer separators
// only. So no process holds more than about three separators' columns, where rank 0 alone held
// all P − 1 of them.

#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

namespace kinestat::distributed {

/// A process's share of the interface: rows on some interface columns, `columns[j]` the global
/// interface index of column j.
struct InterfaceBlock {
  Eigen::SparseMatrix<double> rows;
  std::vector<Eigen::Index> columns;
};

/// What the tree's merges contribute to rank(A), the same on every process.
struct InterfaceTreeRank {
  Eigen::Index rank = 0;         ///< Σ of the merges' ranks
  double smallest_kept = 0.0;    ///< smallest kept pivot over the merges (0 when none was kept)
  Eigen::Index rows = 0;         ///< Σ of the rows stacked at the merges
  double seconds = 0.0;          ///< wall time of the whole tree on rank 0, seconds
  std::size_t peak_memory = 0;   ///< this process's SuiteSparse peak count over its merges, bytes
};

/// Collective over MPI_COMM_WORLD. `block`: this process's block after its interior;
/// `interface_rows`: the rows of A with entries in interface columns only (global interface
/// columns; the same on every process); `separator`: the separator (0 … P − 2) of every global
/// interface column (the same on every process); `threshold` the serial rule's absolute one.
/// Throws as reduce_interior.
InterfaceTreeRank reduce_interface_tree(InterfaceBlock block, const Eigen::SparseMatrix<double>& interface_rows,
                                        const std::vector<int>& separator, double threshold);

}  // namespace kinestat::distributed
