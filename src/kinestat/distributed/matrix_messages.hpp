// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Compressed sparse matrices sent whole between the processes of the distributed decision
// (their shape, then their three arrays), over MPI_COMM_WORLD with tag 0. Counts are MPI's
// `int`: a matrix must hold fewer than 2³¹ entries.

#include <Eigen/SparseCore>

#include <vector>

namespace kinestat::distributed {

/// Sends compressed `m` to process `to` (blocking; matched by receive_matrix on `to`).
void send_matrix(const Eigen::SparseMatrix<double>& m, int to);

/// Receives a matrix sent by send_matrix from process `from`.
Eigen::SparseMatrix<double> receive_matrix(int from);

/// Rank 0's `m` on every process (collective; `m` is read on rank 0 and replaced elsewhere).
void broadcast_matrix(Eigen::SparseMatrix<double>& m);

/// Sends a list of indices (the global interface column of each block column) to process `to`.
void send_indices(const std::vector<Eigen::Index>& indices, int to);

/// Receives a list of indices sent by send_indices from process `from`.
std::vector<Eigen::Index> receive_indices(int from);

}  // namespace kinestat::distributed
