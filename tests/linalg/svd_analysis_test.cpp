// SPDX-License-Identifier: BSD-3-Clause
// The checked SVD: factors reconstruct A and are orthonormal, null spaces are exact to
// rounding, including on matrices with many equal singular values (where Eigen 3.4's
// divide-and-conquer SVD can fail).
#include <gtest/gtest.h>

#include <random>

#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::linalg {
namespace {

void expect_valid(const Eigen::MatrixXd& a) {
  const SvdAnalysis svd = analyse_svd(a);
  const auto m = a.rows(), n = a.cols();
  ASSERT_EQ(svd.u.rows(), m);
  ASSERT_EQ(svd.v.rows(), n);
  EXPECT_LT((svd.u.transpose() * svd.u - Eigen::MatrixXd::Identity(m, m)).norm(), 1e-12);
  EXPECT_LT((svd.v.transpose() * svd.v - Eigen::MatrixXd::Identity(n, n)).norm(), 1e-12);
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(m, n);
  for (Eigen::Index i = 0; i < svd.singular_values.size(); ++i) s(i, i) = svd.singular_values(i);
  EXPECT_LT((a - svd.u * s * svd.v.transpose()).norm(), 1e-12 * std::max(1.0, a.norm()));
  EXPECT_LT((a * svd.null_space()).norm(), 1e-12 * std::max(1.0, a.norm()));
  EXPECT_LT((a.transpose() * svd.left_null_space()).norm(), 1e-12 * std::max(1.0, a.norm()));
}

TEST(SvdAnalysis, StructuredZeroPlusMinusOneMatrices) {
  // Sparse 0/±1 matrices of rank below their size, wide and tall: many equal singular values.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> entry(-4, 4);
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 10 + trial % 25, n = 12 + (trial * 7) % 30;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) {
        const int e = entry(rng);
        a(i, j) = e == 1 ? 1.0 : (e == -1 ? -1.0 : 0.0);
      }
    a.row(m - 1) = a.row(0) - a.row(1);  // rank deficiency
    SCOPED_TRACE(trial);
    expect_valid(a);
    expect_valid(a.transpose());
  }
}

TEST(SvdAnalysis, RankDecisionEvidence) {
  Eigen::MatrixXd a(3, 3);
  a << 1, 0, 0, 0, 1e-3, 0, 0, 0, 1e-20;
  const auto rank = numerical_rank(a);
  EXPECT_EQ(rank.rank, 2);
  EXPECT_DOUBLE_EQ(rank.smallest_kept, 1e-3);
  EXPECT_DOUBLE_EQ(rank.largest_dropped, 1e-20);
  EXPECT_FALSE(rank.close());
  Eigen::MatrixXd near(2, 2);
  near << 1, 0, 0, 1e-6;  // far above rounding, far below one
  EXPECT_EQ(numerical_rank(near).rank, 2);
  RankTolerance loose;
  loose.relative = 1e-5;
  const auto dropped = numerical_rank(near, loose);
  EXPECT_EQ(dropped.rank, 1);
  EXPECT_TRUE(dropped.close());  // a dropped value far above rounding: close to another answer
}

}  // namespace
}  // namespace kinestat::linalg
