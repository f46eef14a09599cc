// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/decomposed_rank.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <numeric>

#include "kinestat/distributed/column_partition.hpp"
#include "kinestat/distributed/interior_reduction.hpp"
#include "kinestat/distributed/process_memory.hpp"
#include "kinestat/linalg/sparse_rank.hpp"

namespace kinestat::distributed {

namespace {

// This process's rows of `b` split into the interior columns of `part` and the interface
// columns (numbered as in `gamma`: the interface index of every column of b, −1 elsewhere).
struct LocalBlocks {
  Eigen::SparseMatrix<double> interior, interface;
  std::vector<Eigen::Index> interface_global;  ///< interface index of each column of `interface`
};

LocalBlocks local_blocks(const Eigen::SparseMatrix<double>& b, const ColumnPartition& partition, int part,
                         const std::vector<Eigen::Index>& gamma) {
  std::vector<Eigen::Index> local_row(partition.row_part.size(), -1);
  Eigen::Index rows = 0;
  for (std::size_t i = 0; i < local_row.size(); ++i)
    if (partition.row_part[i] == part) local_row[i] = rows++;
  LocalBlocks out;
  std::vector<Eigen::Triplet<double>> interior, interface;
  Eigen::Index interior_columns = 0;
  for (Eigen::Index j = 0; j < b.outerSize(); ++j) {
    const int column_part = partition.column_part[static_cast<std::size_t>(j)];
    if (column_part == part) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(b, j); it; ++it)
        interior.emplace_back(local_row[static_cast<std::size_t>(it.row())], interior_columns, it.value());
      ++interior_columns;
    } else if (column_part == ColumnPartition::kInterface) {
      bool touched = false;
      for (Eigen::SparseMatrix<double>::InnerIterator it(b, j); it; ++it) {
        const Eigen::Index row = local_row[static_cast<std::size_t>(it.row())];
        if (row < 0) continue;
        interface.emplace_back(row, static_cast<Eigen::Index>(out.interface_global.size()), it.value());
        touched = true;
      }
      if (touched) out.interface_global.push_back(gamma[static_cast<std::size_t>(j)]);
    }
  }
  out.interior.resize(rows, interior_columns);
  out.interior.setFromTriplets(interior.begin(), interior.end());
  out.interface.resize(rows, static_cast<Eigen::Index>(out.interface_global.size()));
  out.interface.setFromTriplets(interface.begin(), interface.end());
  return out;
}

// The threshold fields of the serial rule, computed on rank 0 and broadcast.
linalg::RankDecision broadcast_threshold(const Eigen::SparseMatrix<double>& a, const linalg::RankTolerance& tolerance,
                                         int rank) {
  linalg::RankDecision decision;
  if (rank == 0) decision = linalg::sparse_rank_threshold(a, tolerance);
  std::array<double, 4> fields{decision.largest, decision.threshold, decision.rounding_level, decision.input_rounding};
  MPI_Bcast(fields.data(), static_cast<int>(fields.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  decision.largest = fields[0];
  decision.threshold = fields[1];
  decision.rounding_level = fields[2];
  decision.input_rounding = fields[3];
  decision.rows = a.rows();
  decision.cols = a.cols();
  decision.sparse = true;
  return decision;
}

// Every process's interface block (global interface columns) stacked on rank 0, under the
// interface-only rows of `b`; empty elsewhere.
Eigen::SparseMatrix<double> gather_interface(const Eigen::SparseMatrix<double>& b, const ColumnPartition& partition,
                                             const std::vector<Eigen::Index>& gamma, const LocalBlocks& local,
                                             const Eigen::SparseMatrix<double>& block, int rank, int size) {
  std::vector<long long> rows, cols;
  std::vector<double> values;
  for (Eigen::Index k = 0; k < block.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(block, k); it; ++it) {
      rows.push_back(it.row());
      cols.push_back(local.interface_global[static_cast<std::size_t>(it.col())]);
      values.push_back(it.value());
    }
  const std::array<long long, 2> mine{static_cast<long long>(values.size()), block.rows()};
  std::vector<long long> counts(2 * static_cast<std::size_t>(size));
  MPI_Gather(mine.data(), 2, MPI_LONG_LONG, counts.data(), 2, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  std::vector<int> sizes(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
  for (int p = 0; p < size; ++p) sizes[static_cast<std::size_t>(p)] = static_cast<int>(counts[2 * static_cast<std::size_t>(p)]);
  std::exclusive_scan(sizes.begin(), sizes.end(), offsets.begin(), 0);
  const int total = rank == 0 ? offsets.back() + sizes.back() : 0;
  std::vector<long long> all_rows(static_cast<std::size_t>(total)), all_cols(static_cast<std::size_t>(total));
  std::vector<double> all_values(static_cast<std::size_t>(total));
  const int n = static_cast<int>(values.size());
  MPI_Gatherv(rows.data(), n, MPI_LONG_LONG, all_rows.data(), sizes.data(), offsets.data(), MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  MPI_Gatherv(cols.data(), n, MPI_LONG_LONG, all_cols.data(), sizes.data(), offsets.data(), MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  MPI_Gatherv(values.data(), n, MPI_DOUBLE, all_values.data(), sizes.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (rank != 0) return {};
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::Index row_offset = 0;
  for (int p = 0; p < size; ++p) {
    const auto from = static_cast<std::size_t>(offsets[static_cast<std::size_t>(p)]);
    for (std::size_t k = from; k < from + static_cast<std::size_t>(sizes[static_cast<std::size_t>(p)]); ++k)
      entries.emplace_back(row_offset + all_rows[k], all_cols[k], all_values[k]);
    row_offset += counts[2 * static_cast<std::size_t>(p) + 1];
  }
  // The rows of b with entries in interface columns only, in their order.
  std::vector<Eigen::Index> interface_row(partition.row_part.size(), -1);
  for (std::size_t i = 0; i < interface_row.size(); ++i)
    if (partition.row_part[i] == ColumnPartition::kInterface) interface_row[i] = row_offset++;
  for (Eigen::Index j = 0; j < b.outerSize(); ++j) {
    if (partition.column_part[static_cast<std::size_t>(j)] != ColumnPartition::kInterface) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(b, j); it; ++it)
      if (const Eigen::Index row = interface_row[static_cast<std::size_t>(it.row())]; row >= 0)
        entries.emplace_back(row, gamma[static_cast<std::size_t>(j)], it.value());
  }
  Eigen::SparseMatrix<double> stacked(row_offset, partition.interface_columns);
  stacked.setFromTriplets(entries.begin(), entries.end());
  return stacked;
}

// The smallest of the kept pivots that exist (0 when none: the rank is 0).
double smaller_kept(double a, double b) {
  if (a == 0.0) return b;
  if (b == 0.0) return a;
  return std::min(a, b);
}

// Per-process figures gathered on rank 0.
std::vector<std::size_t> gather_sizes(std::size_t mine, int rank, int size) {
  std::vector<unsigned long long> all(rank == 0 ? static_cast<std::size_t>(size) : 0);
  const auto value = static_cast<unsigned long long>(mine);
  MPI_Gather(&value, 1, MPI_UNSIGNED_LONG_LONG, all.data(), 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  return {all.begin(), all.end()};
}

// P ≥ 2: the decomposition itself (the threshold already in `out.decision`).
void decide_decomposed(const Eigen::SparseMatrix<double>& b, DecomposedRank& out, int rank, std::size_t& factor_memory) {
  const double start = MPI_Wtime();
  const ColumnPartition partition = partition_columns(b, out.processes);
  std::vector<Eigen::Index> gamma(partition.column_part.size(), -1);
  Eigen::Index interface = 0;
  for (std::size_t j = 0; j < gamma.size(); ++j)
    if (partition.column_part[j] == ColumnPartition::kInterface) gamma[j] = interface++;
  const LocalBlocks local = local_blocks(b, partition, rank, gamma);
  const InteriorReduction reduced = reduce_interior(local.interior, local.interface, out.decision.threshold);
  factor_memory = reduced.peak_memory;
  const double interior_seconds = MPI_Wtime() - start;
  MPI_Reduce(&interior_seconds, &out.interior_seconds, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
  const long long interior_rank = reduced.rank;
  std::vector<long long> ranks(static_cast<std::size_t>(out.processes));
  MPI_Allgather(&interior_rank, 1, MPI_LONG_LONG, ranks.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD);
  out.interior_ranks.assign(ranks.begin(), ranks.end());
  double interior_kept = reduced.smallest_kept;
  {
    std::vector<double> kept(static_cast<std::size_t>(out.processes));
    MPI_Allgather(&interior_kept, 1, MPI_DOUBLE, kept.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
    interior_kept = std::accumulate(kept.begin(), kept.end(), 0.0, smaller_kept);
  }
  const Eigen::SparseMatrix<double> stacked =
      gather_interface(b, partition, gamma, local, reduced.interface_block, rank, out.processes);
  // rank 0 decides the interface; [rank, smallest kept bits] broadcast.
  std::array<double, 4> root{0.0, 0.0, 0.0, 0.0};
  if (rank == 0) {
    const double interface_start = MPI_Wtime();
    linalg::SparseRankCount count;
    if (stacked.rows() > 0 && stacked.cols() > 0) count = linalg::sparse_qr_rank(stacked, out.decision.threshold);
    factor_memory = std::max(factor_memory, count.peak_memory);
    root = {static_cast<double>(count.rank), count.smallest_pivot, static_cast<double>(stacked.rows()), MPI_Wtime() - interface_start};
  }
  MPI_Bcast(root.data(), static_cast<int>(root.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  out.interface_rank = static_cast<Eigen::Index>(root[0]);
  out.interface_columns = partition.interface_columns;
  out.interface_rows = static_cast<Eigen::Index>(root[2]);
  out.interface_seconds = root[3];
  const Eigen::Index rank_total = std::accumulate(out.interior_ranks.begin(), out.interior_ranks.end(), out.interface_rank);
  linalg::record_rank(out.decision, linalg::SparseRankCount{rank_total, smaller_kept(interior_kept, root[1]), 0});
}

}  // namespace

DecomposedRank decomposed_rank(const Eigen::SparseMatrix<double>& a, const linalg::RankTolerance& tolerance,
                               const std::vector<Eigen::Index>& column_groups, FactoredSide side) {
  int rank = 0;
  DecomposedRank out;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &out.processes);
  std::size_t factor_memory = 0;
  const double start = MPI_Wtime();
  const bool transpose = side == FactoredSide::transposed || a.rows() < a.cols();
  if (a.rows() == 0 || a.cols() == 0 || (out.processes == 1 && side == FactoredSide::taller)) {
    // Nothing to split: the serial decision itself (every process computes it when the matrix
    // is empty, which costs nothing).
    out.decision = linalg::sparse_numerical_rank(a, tolerance, &factor_memory, column_groups);
    out.interior_ranks.assign(static_cast<std::size_t>(out.processes), 0);
    out.interior_ranks[0] = out.decision.rank;
    out.interior_seconds = MPI_Wtime() - start;
  } else {
    out.decision = broadcast_threshold(a, tolerance, rank);
    out.threshold_seconds = MPI_Wtime() - start;
    const Eigen::SparseMatrix<double> b = transpose ? Eigen::SparseMatrix<double>(a.transpose()) : a;
    decide_decomposed(b, out, rank, factor_memory);
  }
  out.peak_memory = gather_sizes(peak_resident_bytes(), rank, out.processes);
  out.factor_memory = gather_sizes(factor_memory, rank, out.processes);
  return out;
}

}  // namespace kinestat::distributed
