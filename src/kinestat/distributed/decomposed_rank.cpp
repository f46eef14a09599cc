// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/decomposed_rank.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <utility>

#include "kinestat/distributed/column_partition.hpp"
#include "kinestat/distributed/interface_tree.hpp"
#include "kinestat/distributed/interior_reduction.hpp"
#include "kinestat/distributed/matrix_messages.hpp"
#include "kinestat/distributed/mpi_session.hpp"
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

// What rank 0 tells every process before the decision: go (0) or cancelled (rank 0's exit
// code), the matrix's shape and side, and the serial rule's threshold fields.
struct DecisionHeader {
  std::array<long long, 4> integers{};  // status, rows, cols, transpose
  std::array<double, 4> reals{};        // largest, threshold, rounding_level, input_rounding
};

DecisionHeader broadcast_header(DecisionHeader header) {
  MPI_Bcast(header.integers.data(), static_cast<int>(header.integers.size()), MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  MPI_Bcast(header.reals.data(), static_cast<int>(header.reals.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return header;
}

// Rank 0's header: the threshold of `a` by the serial rule.
DecisionHeader root_header(const Eigen::SparseMatrix<double>& a, const linalg::RankTolerance& tolerance, bool transpose) {
  const linalg::RankDecision d = linalg::sparse_rank_threshold(a, tolerance);
  return {{0, a.rows(), a.cols(), transpose ? 1 : 0}, {d.largest, d.threshold, d.rounding_level, d.input_rounding}};
}

linalg::RankDecision decision_of(const DecisionHeader& header) {
  linalg::RankDecision decision;
  decision.rows = static_cast<Eigen::Index>(header.integers[1]);
  decision.cols = static_cast<Eigen::Index>(header.integers[2]);
  decision.largest = header.reals[0];
  decision.threshold = header.reals[1];
  decision.rounding_level = header.reals[2];
  decision.input_rounding = header.reals[3];
  decision.sparse = true;
  return decision;
}

// Rank 0's rows of `b` with entries in interface columns only, in their order, on the interface
// columns (global interface numbering): the stacked interface's last rows.
Eigen::SparseMatrix<double> interface_only_rows(const Eigen::SparseMatrix<double>& b, const ColumnPartition& partition,
                                                const std::vector<Eigen::Index>& gamma) {
  std::vector<Eigen::Index> interface_row(partition.row_part.size(), -1);
  Eigen::Index rows = 0;
  for (std::size_t i = 0; i < interface_row.size(); ++i)
    if (partition.row_part[i] == ColumnPartition::kInterface) interface_row[i] = rows++;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < b.outerSize(); ++j) {
    if (partition.column_part[static_cast<std::size_t>(j)] != ColumnPartition::kInterface) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(b, j); it; ++it)
      if (const Eigen::Index row = interface_row[static_cast<std::size_t>(it.row())]; row >= 0)
        entries.emplace_back(row, gamma[static_cast<std::size_t>(j)], it.value());
  }
  Eigen::SparseMatrix<double> out(rows, partition.interface_columns);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

void send_blocks(const LocalBlocks& blocks, int to) {
  send_matrix(blocks.interior, to);
  send_matrix(blocks.interface, to);
  send_indices(blocks.interface_global, to);
}

LocalBlocks receive_blocks() {
  LocalBlocks out;
  out.interior = receive_matrix(0);
  out.interface = receive_matrix(0);
  out.interface_global = receive_indices(0);
  return out;
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

// Rank 0 at P ≥ 2: partitions the columns of `b` (released here), sends every other process
// its blocks, and keeps its own and the interface-only rows.
struct RootShare {
  LocalBlocks local;
  Eigen::SparseMatrix<double> interface_only;
  Eigen::Index interface_columns = 0;
  std::vector<int> separator;  ///< the separator of each interface column (global numbering)
};

// Frees a matrix's storage now (Eigen 3.4's SparseMatrix has no move constructor: std::move
// copies it, so ownership is passed by reference and released by swapping).
void release(Eigen::SparseMatrix<double>& m) { Eigen::SparseMatrix<double>().swap(m); }

RootShare scatter_blocks(Eigen::SparseMatrix<double>& b, int size) {
  const ColumnPartition partition = partition_columns(b, size);
  std::vector<Eigen::Index> gamma(partition.column_part.size(), -1);
  Eigen::Index interface = 0;
  for (std::size_t j = 0; j < gamma.size(); ++j)
    if (partition.column_part[j] == ColumnPartition::kInterface) gamma[j] = interface++;
  // One block at a time, so that rank 0 holds b and one process's rows at most.
  for (int p = 1; p < size; ++p) send_blocks(local_blocks(b, partition, p, gamma), p);
  std::vector<int> separator(static_cast<std::size_t>(interface));
  for (std::size_t j = 0; j < gamma.size(); ++j)
    if (gamma[j] >= 0) separator[static_cast<std::size_t>(gamma[j])] = partition.column_separator[j];
  RootShare share{local_blocks(b, partition, 0, gamma), interface_only_rows(b, partition, gamma), partition.interface_columns,
                  std::move(separator)};
  release(b);
  return share;
}

// P ≥ 2: the decomposition itself (the threshold already in `out.decision`); `b` is the matrix
// factored on rank 0 (released once its rows are sent) and empty elsewhere.
void decide_decomposed(Eigen::SparseMatrix<double>& b, DecomposedRank& out, int rank, std::size_t& factor_memory) {
  const double start = MPI_Wtime();
  RootShare share = rank == 0 ? scatter_blocks(b, out.processes) : RootShare{receive_blocks(), {}, 0, {}};
  static_assert(sizeof(Eigen::Index) == sizeof(std::int64_t));
  Eigen::Index interface_columns = share.interface_columns;
  MPI_Bcast(&interface_columns, 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
  // Every process: the interface-only rows and the separator of each interface column (small:
  // about one row and one number per interface column), for the merges of the interface tree.
  broadcast_matrix(share.interface_only);
  share.separator.resize(static_cast<std::size_t>(interface_columns));
  MPI_Bcast(share.separator.data(), static_cast<int>(interface_columns), MPI_INT, 0, MPI_COMM_WORLD);
  const InteriorReduction reduced = reduce_interior(share.local.interior, share.local.interface, out.decision.threshold);
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
  // The interface reduced in a tree of merges (interface_tree.hpp).
  InterfaceBlock block;
  block.rows = reduced.interface_block;
  block.columns = share.local.interface_global;
  const InterfaceTreeRank tree = reduce_interface_tree(std::move(block), share.interface_only, share.separator,
                                                       out.decision.threshold);
  factor_memory = std::max(factor_memory, tree.peak_memory);
  out.interface_rank = tree.rank;
  out.interface_columns = interface_columns;
  out.interface_rows = tree.rows;
  out.interface_seconds = tree.seconds;
  const Eigen::Index rank_total = std::accumulate(out.interior_ranks.begin(), out.interior_ranks.end(), out.interface_rank);
  linalg::record_rank(out.decision, linalg::SparseRankCount{rank_total, smaller_kept(interior_kept, tree.smallest_kept), 0});
}

// One process (P = 1, or MPI not initialised): the serial decision itself.
void decide_alone(const Eigen::SparseMatrix<double>& a, const linalg::RankTolerance& tolerance,
                  const std::vector<Eigen::Index>& column_groups, FactoredSide side, DecomposedRank& out,
                  std::size_t& factor_memory) {
  if (side == FactoredSide::taller || a.rows() == 0 || a.cols() == 0) {
    out.decision = linalg::sparse_numerical_rank(a, tolerance, &factor_memory, column_groups);
  } else {  // a network's rule: the threshold of K, the counts-only QR of Kᵀ
    out.decision = linalg::sparse_rank_threshold(a, tolerance);
    const linalg::SparseRankCount count =
        linalg::sparse_qr_rank(Eigen::SparseMatrix<double>(a.transpose()), out.decision.threshold);
    factor_memory = count.peak_memory;
    linalg::record_rank(out.decision, count);
  }
  out.interior_ranks = {out.decision.rank};
}

}  // namespace

DecomposedRank decomposed_rank(Eigen::SparseMatrix<double>&& a, const linalg::RankTolerance& tolerance,
                               const std::vector<Eigen::Index>& column_groups, FactoredSide side) {
  DecomposedRank out;
  const int rank = world_rank();
  out.processes = world_size();
  std::size_t factor_memory = 0;
  const std::size_t before = peak_resident_bytes();
  const double start = out.processes == 1 ? 0.0 : MPI_Wtime();
  if (out.processes == 1) {
    const auto clock = std::chrono::steady_clock::now();
    decide_alone(a, tolerance, column_groups, side, out, factor_memory);
    out.interior_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    out.peak_memory = {peak_resident_bytes()};
    out.peak_before_decision = {before};
    out.factor_memory = {factor_memory};
    return out;
  }
  const bool transpose = side == FactoredSide::transposed || a.rows() < a.cols();
  const DecisionHeader header = broadcast_header(rank == 0 ? root_header(a, tolerance, transpose) : DecisionHeader{});
  if (header.integers[0] != 0) {
    out.cancelled = static_cast<int>(header.integers[0]);
    return out;
  }
  out.decision = decision_of(header);
  out.threshold_seconds = MPI_Wtime() - start;
  if (out.decision.rows == 0 || out.decision.cols == 0) {
    out.interior_ranks.assign(static_cast<std::size_t>(out.processes), 0);  // nothing to split
  } else if (rank == 0 && header.integers[3] != 0) {
    Eigen::SparseMatrix<double> b = a.transpose();
    release(a);  // only the factored side is kept
    decide_decomposed(b, out, rank, factor_memory);
  } else {
    decide_decomposed(a, out, rank, factor_memory);  // rank 0's matrix, or nothing elsewhere
  }
  out.peak_memory = gather_sizes(peak_resident_bytes(), rank, out.processes);
  out.peak_before_decision = gather_sizes(before, rank, out.processes);
  out.factor_memory = gather_sizes(factor_memory, rank, out.processes);
  return out;
}

void cancel_decomposed_rank(int exit_code) {
  if (world_size() == 1) return;
  DecisionHeader header;
  header.integers[0] = exit_code;
  broadcast_header(header);
}

}  // namespace kinestat::distributed
