// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Random sparse test matrices whose rank is known by construction.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdlib>
#include <random>

namespace kinestat::testing {

/// A banded rows × cols matrix of rank `rank`: the product of two random banded factors of inner
/// size `rank` (entries uniform in [−1, 1]), so its rank is `rank` by construction (for generic
/// draws; tests confirm it with a dense SVD).
inline Eigen::SparseMatrix<double> banded_of_rank(std::mt19937& rng, int rows, int cols, int rank) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::MatrixXd left = Eigen::MatrixXd::Zero(rows, rank), right = Eigen::MatrixXd::Zero(rank, cols);
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < rank; ++k)
      if (std::abs(i * rank / rows - k) <= 1) left(i, k) = value(rng);
  for (int k = 0; k < rank; ++k)
    for (int j = 0; j < cols; ++j)
      if (std::abs(j * rank / cols - k) <= 1) right(k, j) = value(rng);
  return (left * right).sparseView();
}

}  // namespace kinestat::testing
