// SPDX-License-Identifier: BSD-3-Clause
// analyse_null_spaces against hand-derived spaces and singular values.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kinestat/linalg/null_spaces.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "support/givens_mixing.hpp"
#include "support/subspace_angles.hpp"

namespace kinestat::linalg {
namespace {

// A = [I_n; diag(b); 0] (m = 2n + z rows), rows mixed by a fixed orthogonal matrix P (a product
// of Givens rotations) so that no structure is left: by hand, the singular values are
// √(1 + b_i²), the rank is n, and the left null space is P·span([−diag(b); I_n; 0] ⊕ [0; 0; I_z]).
struct TallCase {
  Eigen::MatrixXd a, left_null;
  Eigen::VectorXd singular_values;
};

TallCase tall_case(Eigen::Index n, Eigen::Index zeros) {
  const Eigen::Index m = 2 * n + zeros;
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b(i) = 0.25 + 0.5 * static_cast<double>(i);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n), left = Eigen::MatrixXd::Zero(m, m - n);
  a.topRows(n).setIdentity();
  a.middleRows(n, n) = b.asDiagonal();
  left.topLeftCorner(n, n) = -Eigen::MatrixXd(b.asDiagonal());
  left.block(n, 0, n, n).setIdentity();
  left.bottomRightCorner(zeros, zeros).setIdentity();
  const Eigen::MatrixXd p = testing::givens_mixing(m);
  Eigen::VectorXd s = (1.0 + b.array().square()).sqrt();
  std::sort(s.data(), s.data() + s.size(), [](double x, double y) { return x > y; });
  return {p * a, p * left, s};
}

TEST(NullSpaces, TallFullRankTakesTheQrRouteWithTheHandSpaces) {
  const TallCase c = tall_case(40, 25);
  const NullSpaces result = analyse_null_spaces(c.a);
  EXPECT_TRUE(result.from_qr);
  EXPECT_EQ(result.rank.rank, 40);
  EXPECT_EQ(result.null_space.rows(), 40);
  EXPECT_EQ(result.null_space.cols(), 0);
  ASSERT_EQ(result.left_null_space.cols(), 65);
  ASSERT_EQ(result.singular_values.size(), 40);
  for (Eigen::Index i = 0; i < 40; ++i) EXPECT_NEAR(result.singular_values(i), c.singular_values(i), 1e-13 * c.singular_values(0));
  const Eigen::VectorXd cosines = testing::principal_cosines(result.left_null_space, c.left_null);
  EXPECT_NEAR(cosines.minCoeff(), 1.0, 1e-12);
  const Eigen::MatrixXd gram = result.left_null_space.transpose() * result.left_null_space;
  EXPECT_NEAR((gram - Eigen::MatrixXd::Identity(65, 65)).norm(), 0.0, 1e-13);
}

TEST(NullSpaces, RankDeficientTallMatrixTakesTheSvdRoute) {
  // Column 3 = column 1 + column 2: one mode (1, 1, −1, 0, …), the rank one less.
  TallCase c = tall_case(10, 3);
  c.a.col(3) = c.a.col(1) + c.a.col(2);
  const NullSpaces result = analyse_null_spaces(c.a);
  EXPECT_FALSE(result.from_qr);
  EXPECT_EQ(result.rank.rank, 9);
  ASSERT_EQ(result.null_space.cols(), 1);
  Eigen::VectorXd mode = Eigen::VectorXd::Zero(10);
  mode << 0, 1, 1, -1, 0, 0, 0, 0, 0, 0;
  EXPECT_NEAR(testing::principal_cosines(result.null_space, mode)(0), 1.0, 1e-12);
  EXPECT_EQ(result.left_null_space.cols(), 23 - 9);
  EXPECT_NEAR((c.a.transpose() * result.left_null_space).norm(), 0.0, 1e-12);
}

TEST(NullSpaces, WideMatrixTakesTheSvdRoute) {
  const TallCase c = tall_case(6, 2);
  const NullSpaces result = analyse_null_spaces(c.a.transpose());
  EXPECT_FALSE(result.from_qr);
  EXPECT_EQ(result.rank.rank, 6);
  EXPECT_EQ(result.left_null_space.cols(), 0);
  // The null space of Aᵀ is the left null space of A.
  EXPECT_NEAR(testing::principal_cosines(result.null_space, c.left_null).minCoeff(), 1.0, 1e-12);
}

TEST(SingularValues, WithoutVectorsAreTheHandValues) {
  // singular_values takes LAPACK's values-only route: the same √(1 + b_i²), for A and Aᵀ.
  const TallCase c = tall_case(30, 7);
  for (const Eigen::MatrixXd& a : {c.a, Eigen::MatrixXd(c.a.transpose())}) {
    const Eigen::VectorXd s = singular_values(a);
    ASSERT_EQ(s.size(), 30);
    for (Eigen::Index i = 0; i < 30; ++i) EXPECT_NEAR(s(i), c.singular_values(i), 1e-13 * c.singular_values(0));
  }
}

}  // namespace
}  // namespace kinestat::linalg
