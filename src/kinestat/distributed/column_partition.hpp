// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A domain decomposition of a sparse matrix's columns for the distributed rank decision:
// `parts` interiors and an interface such that no row has entries in the interiors of two
// different parts (docs/scaling.md, "The distributed rank decision").

#include <Eigen/SparseCore>

#include <vector>

namespace kinestat::distributed {

/// The part of every column and of every row. A row belongs to the part of its interior
/// columns (all of them are in one part) or, when it has entries in interface columns only, to
/// the interface.
struct ColumnPartition {
  static constexpr int kInterface = -1;
  int parts = 1;
  std::vector<int> column_part;  ///< per column: 0 … parts − 1, or kInterface
  /// per column: for an interface column its separator k (0 … parts − 2, between parts k and
  /// k + 1, the parts' order along the levels), −1 for an interior column
  std::vector<int> column_separator;
  std::vector<int> row_part;     ///< per row: 0 … parts − 1, or kInterface (also an empty row)
  Eigen::Index interface_columns = 0;
};

/// Splits the columns of `a` into `parts` interiors (some possibly empty) and an interface by
/// breadth-first levels of the column graph (two columns adjacent when a row has entries in
/// both), from a pseudo-peripheral column of each connected component: the columns of one
/// level separate those before it from those after it, since a row's columns lie in one level
/// or two adjacent ones. The separating levels are chosen so that the interiors hold about
/// equal numbers of columns. Deterministic: the same matrix gives the same partition on every
/// process. Memory O(nnz(a)).
ColumnPartition partition_columns(const Eigen::SparseMatrix<double>& a, int parts);

}  // namespace kinestat::distributed
