// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/matrix_messages.hpp"

#include <mpi.h>

#include <array>
#include <type_traits>

namespace kinestat::distributed {

namespace {

static_assert(std::is_same_v<Eigen::SparseMatrix<double>::StorageIndex, int>);

// A matrix of the given shape with room for its entries, compressed, to be filled in place.
Eigen::SparseMatrix<double> shaped(const std::array<long long, 3>& shape) {
  Eigen::SparseMatrix<double> m(static_cast<Eigen::Index>(shape[0]), static_cast<Eigen::Index>(shape[1]));
  m.resizeNonZeros(static_cast<Eigen::Index>(shape[2]));
  return m;
}

}  // namespace

void send_matrix(const Eigen::SparseMatrix<double>& m, int to) {
  const std::array<long long, 3> shape{m.rows(), m.cols(), m.nonZeros()};
  MPI_Send(shape.data(), 3, MPI_LONG_LONG, to, 0, MPI_COMM_WORLD);
  MPI_Send(m.outerIndexPtr(), static_cast<int>(m.cols() + 1), MPI_INT, to, 0, MPI_COMM_WORLD);
  MPI_Send(m.innerIndexPtr(), static_cast<int>(m.nonZeros()), MPI_INT, to, 0, MPI_COMM_WORLD);
  MPI_Send(m.valuePtr(), static_cast<int>(m.nonZeros()), MPI_DOUBLE, to, 0, MPI_COMM_WORLD);
}

Eigen::SparseMatrix<double> receive_matrix(int from) {
  std::array<long long, 3> shape{};
  MPI_Recv(shape.data(), 3, MPI_LONG_LONG, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  Eigen::SparseMatrix<double> m = shaped(shape);
  MPI_Recv(m.outerIndexPtr(), static_cast<int>(shape[1] + 1), MPI_INT, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Recv(m.innerIndexPtr(), static_cast<int>(shape[2]), MPI_INT, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Recv(m.valuePtr(), static_cast<int>(shape[2]), MPI_DOUBLE, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

void broadcast_matrix(Eigen::SparseMatrix<double>& m) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) m.makeCompressed();
  std::array<long long, 3> shape{m.rows(), m.cols(), m.nonZeros()};
  MPI_Bcast(shape.data(), 3, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  if (rank != 0) {
    Eigen::SparseMatrix<double> received = shaped(shape);
    m.swap(received);
  }
  MPI_Bcast(m.outerIndexPtr(), static_cast<int>(shape[1] + 1), MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Bcast(m.innerIndexPtr(), static_cast<int>(shape[2]), MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Bcast(m.valuePtr(), static_cast<int>(shape[2]), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void send_indices(const std::vector<Eigen::Index>& indices, int to) {
  const std::vector<long long> values(indices.begin(), indices.end());
  const long long count = static_cast<long long>(values.size());
  MPI_Send(&count, 1, MPI_LONG_LONG, to, 0, MPI_COMM_WORLD);
  MPI_Send(values.data(), static_cast<int>(count), MPI_LONG_LONG, to, 0, MPI_COMM_WORLD);
}

std::vector<Eigen::Index> receive_indices(int from) {
  long long count = 0;
  MPI_Recv(&count, 1, MPI_LONG_LONG, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::vector<long long> values(static_cast<std::size_t>(count));
  MPI_Recv(values.data(), static_cast<int>(count), MPI_LONG_LONG, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return {values.begin(), values.end()};
}

}  // namespace kinestat::distributed
