// SPDX-License-Identifier: BSD-3-Clause
// σ_max of sparse matrices by Lanczos (linalg::estimate_largest_singular_value), the scale of
// the sparse rank threshold, against Eigen's dense Jacobi SVD (an independent method) and
// against matrices whose singular values are known by construction.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <Eigen/SparseCore>

#include <random>
#include <vector>

#include "kinestat/linalg/sparse_rank.hpp"

namespace kinestat::linalg {
namespace {

Eigen::SparseMatrix<double> random_sparse(std::mt19937& rng, int rows, int cols, double density) {
  std::uniform_real_distribution<double> value(-1.0, 1.0), coin(0.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      if (coin(rng) < density) entries.emplace_back(i, j, value(rng));
  Eigen::SparseMatrix<double> a(rows, cols);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

TEST(LargestSingularValue, MatchesTheDenseSvdOnRandomSparseMatrices) {
  for (int seed = 0; seed < 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(4100 + seed));
    const int rows = 40 + 13 * seed, cols = 30 + 11 * (seed % 7);
    const Eigen::SparseMatrix<double> a = random_sparse(rng, rows, cols, 0.08);
    const double exact = Eigen::JacobiSVD<Eigen::MatrixXd>(Eigen::MatrixXd(a)).singularValues()(0);
    const double estimate = estimate_largest_singular_value(a);
    EXPECT_NEAR(estimate, exact, 1e-6 * exact);  // the stopping rule: the estimate has settled to ~1e-6
    EXPECT_LE(estimate, exact * (1 + 1e-12));  // a Ritz value: from below
  }
}

TEST(LargestSingularValue, KnownSingularValues) {
  // Diagonal 1/k (k = 1 … 300) with its rows permuted: σ_max = 1, the next 1/2.
  const int n = 300;
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < n; ++k) entries.emplace_back((7 * k) % n, k, 1.0 / (k + 1));
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  EXPECT_NEAR(estimate_largest_singular_value(a), 1.0, 1e-6);
  // Rank one, u vᵀ with ‖u‖ = 5 and ‖v‖ = 13: σ_max = 65, found in one step (an invariant subspace).
  Eigen::SparseMatrix<double> outer(2, 2);
  outer.insert(0, 0) = 3 * 5;
  outer.insert(0, 1) = 3 * 12;
  outer.insert(1, 0) = 4 * 5;
  outer.insert(1, 1) = 4 * 12;
  EXPECT_NEAR(estimate_largest_singular_value(outer), 65.0, 1e-12 * 65);
  // Zero and empty matrices.
  EXPECT_EQ(estimate_largest_singular_value(Eigen::SparseMatrix<double>(5, 4)), 0.0);
  EXPECT_EQ(estimate_largest_singular_value(Eigen::SparseMatrix<double>(0, 4)), 0.0);
}

}  // namespace
}  // namespace kinestat::linalg
