// SPDX-License-Identifier: BSD-3-Clause
// σ_min(R11) of a sparse QR's live block (SparseQr::smallest_singular_estimate) against Eigen's
// dense Jacobi SVD of the same block (an independent method), and Kahan's matrix, whose pivots
// are all far above its smallest singular value: the case where the smallest |R_ii| overstates
// how clear a sparse rank decision is.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <Eigen/SparseCore>

#include <cmath>
#include <random>
#include <string>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/linalg/sparse_qr.hpp"
#include "kinestat/linalg/sparse_rank.hpp"

namespace kinestat::linalg {
namespace {

// The live block R11 (rank × rank, upper triangular) as a dense matrix.
Eigen::MatrixXd live_block(const SparseQr& qr) {
  const SparseFactorView r = qr.r();
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(qr.rank(), qr.rank());
  for (Eigen::Index j = 0; j < qr.rank(); ++j)
    for (SparseFactorView::InnerIterator it(r, j); it; ++it)
      if (it.row() < qr.rank()) block(it.row(), j) = it.value();
  return block;
}

double smallest_singular_value(const Eigen::MatrixXd& m) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
  return svd.singularValues()(svd.singularValues().size() - 1);
}

// Kahan's n × n upper triangular matrix diag(1, s, …, s^(n−1)) (I − c·(strict upper ones)), s =
// sin θ, c = cos θ (Higham, Accuracy and Stability of Numerical Algorithms, §8.3). For n = 30,
// θ = 1.2 its pivots are s^k ≥ s^29 = 0.1299 while σ_min = 3.0845e-5 (numpy.linalg.svd).
Eigen::SparseMatrix<double> kahan(int n, double theta) {
  const double s = std::sin(theta), c = std::cos(theta);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const double scale = std::pow(s, i);
    k(i, i) = scale;
    for (int j = i + 1; j < n; ++j) k(i, j) = -c * scale;
  }
  return k.sparseView();
}

TEST(FactorConditioning, EstimateMatchesTheDenseSvdOfTheLiveBlock) {
  for (int seed = 0; seed < 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(9100 + seed));
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::bernoulli_distribution present(0.15);
    const int rows = 80 + 4 * seed, cols = 60 + 2 * seed;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
        if (i == j % rows || present(rng)) dense(i, j) = value(rng);
    const Eigen::SparseMatrix<double> a = dense.sparseView();
    const SparseQr qr(a, 1e-12);
    ASSERT_GT(qr.rank(), 0);
    const double sigma = smallest_singular_value(live_block(qr));
    const double estimate = qr.smallest_singular_estimate();
    // Inverse iteration approaches σ_min from above, and settles to 10⁻³ within its 8 steps
    // unless the two smallest singular values are close; 5 % covers that case too here.
    EXPECT_GE(estimate, sigma * (1.0 - 1e-9));
    EXPECT_LE(estimate, sigma * 1.05);
    EXPECT_LE(estimate, qr.smallest_pivot() * (1.0 + 1e-12));  // σ_min(R11) ≤ min |R_ii|
  }
}

TEST(FactorConditioning, KahanPivotsOverstateTheSmallestSingularValue) {
  const Eigen::SparseMatrix<double> a = kahan(30, 1.2);
  const double threshold = 1e-3;
  const SparseQr qr(a, threshold);
  ASSERT_EQ(qr.rank(), 30);  // every pivot is above the threshold
  EXPECT_GT(qr.smallest_pivot(), 0.12);
  const double estimate = qr.smallest_singular_estimate();
  EXPECT_NEAR(estimate, 3.0845e-5, 1e-3 * 3.0845e-5);
  EXPECT_NEAR(estimate, smallest_singular_value(Eigen::MatrixXd(a)), 1e-3 * estimate);

  // As rank evidence: the pivots alone call the decision clear (unproven, the best a sparse
  // decision gets); σ_min(R11) below the threshold makes it close.
  RankDecision decision;
  decision.sparse = true;
  decision.largest = 1.0;
  decision.threshold = threshold;
  record_rank(decision, qr);
  EXPECT_EQ(decision.status(), RankStatus::unproven);
  record_factor_smallest(decision, qr);
  EXPECT_TRUE(decision.factor_estimated);
  EXPECT_DOUBLE_EQ(decision.factor_smallest, estimate);
  EXPECT_EQ(decision.status(), RankStatus::close);
}

TEST(FactorConditioning, RankZeroHasNoEstimate) {
  const Eigen::SparseMatrix<double> a(4, 3);
  const SparseQr qr(a, 1e-9);
  EXPECT_EQ(qr.rank(), 0);
  EXPECT_EQ(qr.smallest_singular_estimate(), 0.0);
  RankDecision decision;
  decision.sparse = true;
  record_rank(decision, qr);
  record_factor_smallest(decision, qr);
  EXPECT_FALSE(decision.factor_estimated);
  EXPECT_EQ(decision.status(), RankStatus::unproven);
}

}  // namespace
}  // namespace kinestat::linalg
