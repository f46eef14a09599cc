// SPDX-License-Identifier: BSD-3-Clause
// The BLAS/LAPACK kernels of the dense path on small matrices computed by hand.

#include <gtest/gtest.h>

#include "kinestat/linalg/blas_kernels.hpp"

namespace kinestat::linalg {
namespace {

TEST(BlasKernels, RightDivideIsBTimesTheInverse) {
  // A = [[2, 1], [1, 1]] has A⁻¹ = [[1, −1], [−1, 2]]; B = [[1, 0], [0, 1], [3, 4]] gives B A⁻¹ =
  // [[1, −1], [−1, 2], [−1, 5]].
  Eigen::MatrixXd a(2, 2), b(3, 2), expected(3, 2);
  a << 2, 1, 1, 1;
  b << 1, 0, 0, 1, 3, 4;
  expected << 1, -1, -1, 2, -1, 5;
  const auto x = lapack_right_divide(b, a);
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR((*x - expected).norm(), 0.0, 1e-14);
}

TEST(BlasKernels, RightDivideBySingularIsNothing) {
  Eigen::MatrixXd a(2, 2), b = Eigen::MatrixXd::Identity(2, 2);
  a << 1, 2, 2, 4;
  EXPECT_FALSE(lapack_right_divide(b, a).has_value());
}

TEST(BlasKernels, ProjectionRemovesTheComponentsAlongTheKeptColumns) {
  // Basis columns e1, e2 (and a third column that is not kept): (1, 2, 3) and (4, 5, 6) keep
  // only their third entries.
  Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(3, 3), block(3, 2);
  block << 1, 4, 2, 5, 3, 6;
  blas_subtract_projection(basis, 2, block);
  Eigen::MatrixXd expected(3, 2);
  expected << 0, 0, 0, 0, 3, 6;
  EXPECT_NEAR((block - expected).norm(), 0.0, 1e-15);
}

TEST(BlasKernels, TransposedVectorProductOnABlockWithItsStride) {
  // The 2 × 2 block at rows 1-2, columns 1-2 of M (leading dimension 3) is [[5, 8], [6, 9]];
  // 2 [[5, 8], [6, 9]]ᵀ (1, −1) = 2 (5 − 6, 8 − 9) = (−2, −2).
  Eigen::MatrixXd m(3, 3);
  m << 1, 4, 7, 2, 5, 8, 3, 6, 9;
  const Eigen::Vector2d x(1, -1);
  Eigen::Vector2d y;
  blas_transposed_vector_product(2.0, &m(1, 1), 2, 2, 3, x.data(), y.data());
  EXPECT_NEAR((y - Eigen::Vector2d(-2, -2)).norm(), 0.0, 1e-15);
}

TEST(BlasKernels, SubtractProductTransposed) {
  // C = [[1, 1], [1, 1]] − V Fᵀ with V = (1, 2)ᵀ, F = (3, 4)ᵀ: V Fᵀ = [[3, 4], [6, 8]].
  Eigen::MatrixXd c = Eigen::MatrixXd::Ones(2, 2), expected(2, 2);
  const Eigen::Vector2d v(1, 2), f(3, 4);
  blas_subtract_product_transposed(v.data(), 2, f.data(), 2, c.data(), 2, 2, 2, 1);
  expected << -2, -3, -5, -7;
  EXPECT_NEAR((c - expected).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace kinestat::linalg
