// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/interface_tree.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>

#include "kinestat/distributed/interior_reduction.hpp"
#include "kinestat/distributed/matrix_messages.hpp"

namespace kinestat::distributed {

namespace {

// One merge's stack: the rows of both blocks and the interface rows of `eliminated`, with the
// separator's columns split from the others (each group in increasing global order).
struct Stack {
  Eigen::SparseMatrix<double> inner, outer;
  std::vector<Eigen::Index> outer_columns;
};

Stack stack_for_merge(const InterfaceBlock& left, const InterfaceBlock& right, const Eigen::SparseMatrix<double>& interface_rows,
                      const std::vector<int>& separator, int eliminated) {
  // The interface rows of this separator: every entry of such a row lies in one separator.
  std::vector<bool> row_here(static_cast<std::size_t>(interface_rows.rows()), false);
  for (Eigen::Index j = 0; j < interface_rows.outerSize(); ++j)
    if (separator[static_cast<std::size_t>(j)] == eliminated)
      for (Eigen::SparseMatrix<double>::InnerIterator it(interface_rows, j); it; ++it) row_here[static_cast<std::size_t>(it.row())] = true;
  // Local column numbers: the separator's columns and the others, each in global order.
  std::map<Eigen::Index, Eigen::Index> inner_index, outer_index;
  const auto note = [&](Eigen::Index global) {
    (separator[static_cast<std::size_t>(global)] == eliminated ? inner_index : outer_index).emplace(global, 0);
  };
  for (const Eigen::Index global : left.columns) note(global);
  for (const Eigen::Index global : right.columns) note(global);
  for (Eigen::Index j = 0; j < interface_rows.outerSize(); ++j)
    if (separator[static_cast<std::size_t>(j)] == eliminated && interface_rows.col(j).nonZeros() > 0) note(j);
  Eigen::Index next = 0;
  for (auto& [global, local] : inner_index) local = next++;
  next = 0;
  Stack out;
  for (auto& [global, local] : outer_index) {
    local = next++;
    out.outer_columns.push_back(global);
  }
  std::vector<Eigen::Triplet<double>> inner, outer;
  const auto place = [&](Eigen::Index row, Eigen::Index global, double value) {
    if (const auto at = inner_index.find(global); at != inner_index.end()) inner.emplace_back(row, at->second, value);
    else outer.emplace_back(row, outer_index.at(global), value);
  };
  Eigen::Index row_offset = 0;
  for (const InterfaceBlock* block : {&left, &right}) {
    for (Eigen::Index k = 0; k < block->rows.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(block->rows, k); it; ++it)
        place(row_offset + it.row(), block->columns[static_cast<std::size_t>(k)], it.value());
    row_offset += block->rows.rows();
  }
  std::vector<Eigen::Index> local_row(row_here.size(), -1);
  for (std::size_t i = 0; i < row_here.size(); ++i)
    if (row_here[i]) local_row[i] = row_offset++;
  for (Eigen::Index j = 0; j < interface_rows.outerSize(); ++j)
    if (separator[static_cast<std::size_t>(j)] == eliminated)
      for (Eigen::SparseMatrix<double>::InnerIterator it(interface_rows, j); it; ++it)
        place(local_row[static_cast<std::size_t>(it.row())], j, it.value());
  out.inner.resize(row_offset, static_cast<Eigen::Index>(inner_index.size()));
  out.inner.setFromTriplets(inner.begin(), inner.end());
  out.outer.resize(row_offset, static_cast<Eigen::Index>(outer_index.size()));
  out.outer.setFromTriplets(outer.begin(), outer.end());
  return out;
}

}  // namespace

InterfaceTreeRank reduce_interface_tree(InterfaceBlock block, const Eigen::SparseMatrix<double>& interface_rows,
                                        const std::vector<int>& separator, double threshold) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const double start = MPI_Wtime();
  long long merged_rank = 0, merged_rows = 0;
  double kept = std::numeric_limits<double>::infinity();
  InterfaceTreeRank out;
  // Stage `step`: groups of `step` parts, [r, r + step − 1], rooted at their first process r;
  // the group at r (r a multiple of 2·step) takes in the one at r + step, across separator
  // r + step − 1. A root that sends its block is done.
  for (int step = 1; step < size; step *= 2) {
    if (rank % (2 * step) == step) {
      send_matrix(block.rows, rank - step);
      send_indices(block.columns, rank - step);
      break;
    }
    if (rank % (2 * step) != 0 || rank + step >= size) continue;
    InterfaceBlock right;
    right.rows = receive_matrix(rank + step);
    right.columns = receive_indices(rank + step);
    const Stack stack = stack_for_merge(block, right, interface_rows, separator, rank + step - 1);
    merged_rows += stack.inner.rows();
    InterfaceBlock next;
    if (stack.inner.cols() == 0) {  // no such separator (an empty part): nothing to reduce
      next.rows = stack.outer;
    } else {
      const InteriorReduction reduced = reduce_interior(stack.inner, stack.outer, threshold);
      merged_rank += reduced.rank;
      if (reduced.rank > 0) kept = std::min(kept, reduced.smallest_kept);
      out.peak_memory = std::max(out.peak_memory, reduced.peak_memory);
      next.rows = reduced.interface_block;
    }
    next.columns = stack.outer_columns;
    block.rows.swap(next.rows);
    block.columns.swap(next.columns);
  }
  std::array<long long, 2> sums{merged_rank, merged_rows};
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), 2, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &kept, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  double seconds = MPI_Wtime() - start;
  MPI_Bcast(&seconds, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  out.rank = static_cast<Eigen::Index>(sums[0]);
  out.rows = static_cast<Eigen::Index>(sums[1]);
  out.smallest_kept = kept == std::numeric_limits<double>::infinity() ? 0.0 : kept;
  out.seconds = seconds;
  return out;
}

}  // namespace kinestat::distributed
