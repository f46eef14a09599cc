// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Fill-reducing nested-dissection orderings (METIS, through CHOLMOD) of an undirected graph,
// and of the columns of a sparse matrix whose columns come in groups attached to the vertices
// of a much smaller graph (the coordinates of a framework's nodes): ordering that graph costs a
// fraction of ordering the column graph of AᵀA.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <utility>
#include <vector>

namespace kinestat::linalg {

/// Nested-dissection order of the `vertices` vertices of an undirected graph given by its
/// `edges` (pairs of vertex indices in [0, vertices); loops and repeated edges are ignored):
/// order[k] is the vertex placed k-th, separators after the parts they separate, postordered
/// by the elimination tree. METIS_NodeND with CHOLMOD's default options (deterministic: the
/// same graph gives the same order on every run). Throws std::bad_alloc when out of memory.
std::vector<Eigen::Index> nested_dissection_order(Eigen::Index vertices,
                                                  const std::vector<std::pair<Eigen::Index, Eigen::Index>>& edges);

/// A column order of `a` (order[k] is the column placed k-th, a permutation of 0 … cols − 1)
/// that keeps the columns of one group together: `group_of_column[j]` ≥ 0 is the group of column
/// j (for a framework's D(c), the node of each coordinate). Two groups are joined when one row
/// of `a` has non-zeros in both; the groups are placed in the nested_dissection_order of that
/// graph, and the columns of each group in increasing index.
///
/// The group graph treats every column of one group as coupled to every column of a joined
/// group, which loses the structural zeros of rows that do not touch all of a group's columns
/// (a bar along a coordinate axis has no entries in the other coordinates of its nodes); the
/// fill of a factorisation in this order grows accordingly. The share kept is the number of
/// column pairs of different groups that rows of `a` couple (summed over rows) over the number
/// the group graph joins (the products of the joined groups' sizes, summed over rows): 1 when
/// rows fill their groups. Below `min_share` no order is computed and the result is empty.
/// Throws std::invalid_argument when `group_of_column` does not name a group ≥ 0 for every column.
std::vector<Eigen::Index> grouped_nested_dissection_order(const Eigen::SparseMatrix<double>& a,
                                                          const std::vector<Eigen::Index>& group_of_column,
                                                          double min_share = 0.0);

}  // namespace kinestat::linalg
