// SPDX-License-Identifier: BSD-3-Clause
// linalg::pivoted_column_order (blocked, in panels of 32) against orders derived by hand: column
// norms that an orthogonal mixing of the rows leaves unchanged, ties to the earlier column, and
// near-parallel columns whose remaining norm must be recomputed after cancellation.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "kinestat/linalg/pivoted_qr.hpp"
#include "support/givens_mixing.hpp"

namespace kinestat::linalg {
namespace {

std::vector<Eigen::Index> indices(std::initializer_list<Eigen::Index> list) { return list; }

TEST(PivotedColumnOrder, OrthogonalColumnsComeByDecreasingNorm) {
  // Column j is d_j e_{(37 j) mod 100}, d_j = 1 + ((61 j) mod 100) / 100, mixed: orthogonal
  // columns keep their norms through every step, so the order is the d_j decreasing (100 columns:
  // four panels).
  const Eigen::Index n = 100, m = 110;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n);
  std::vector<double> d(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) {
    d[static_cast<std::size_t>(j)] = 1.0 + static_cast<double>((61 * j) % 100) / 100.0;
    a((37 * j) % 100, j) = d[static_cast<std::size_t>(j)];
  }
  std::vector<Eigen::Index> expected(static_cast<std::size_t>(n));
  std::iota(expected.begin(), expected.end(), Eigen::Index{0});
  std::sort(expected.begin(), expected.end(),
            [&d](Eigen::Index x, Eigen::Index y) { return d[static_cast<std::size_t>(x)] > d[static_cast<std::size_t>(y)]; });
  EXPECT_EQ(pivoted_column_order(testing::givens_mixing(m) * a), expected);
}

TEST(PivotedColumnOrder, EqualNormsGoToTheEarlierColumn) {
  // Orthogonal unit columns, except column 2 longer by 1e-12 (a tie: rounding) and column 4
  // longer by 1e-6 (a real difference): 4 first, then the rest in their order.
  const Eigen::Index n = 6, m = 8;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n);
  for (Eigen::Index j = 0; j < n; ++j) a(j, j) = 1.0;
  a(2, 2) += 1e-12;
  a(4, 4) += 1e-6;
  EXPECT_EQ(pivoted_column_order(testing::givens_mixing(m) * a), indices({4, 0, 1, 2, 3, 5}));
}

TEST(PivotedColumnOrder, DependentColumnIsTakenFirstWhenLongestAndTheRestTie) {
  // Columns e1, e2, e1 + e2 (2 rows): e1 + e2 (norm √2) first; then e1 and e2 both keep 1/√2,
  // a tie to the earlier; two rows allow two steps, the rest keeps its order.
  Eigen::MatrixXd a(2, 3);
  a << 1, 0, 1, 0, 1, 1;
  EXPECT_EQ(pivoted_column_order(a), indices({2, 0, 1}));
}

TEST(PivotedColumnOrder, NearParallelColumnsAreRecomputedAfterCancellation) {
  // Columns 0-34: d_i u_i with orthonormal u_i and d_i = 1 + i/100 (increasing). Columns 35-69:
  // twins d_i u_i + ε_i w_i, w_i orthonormal and orthogonal to every u, ε_i = 1e-6 (1 + (7i mod 35)).
  // A twin's norm exceeds its original's by ε²/(2d) ≤ 6.2e-10 relative (a tie: the original,
  // earlier, is taken), after which the twin keeps only ε_i: its downdated norm cancels to
  // nothing and must be recomputed. So: originals 34, 33, ..., 0, then the twins by ε decreasing.
  const Eigen::Index half = 35, n = 2 * half, m = 2 * half + 3;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n);
  std::vector<double> epsilon(static_cast<std::size_t>(half));
  for (Eigen::Index i = 0; i < half; ++i) {
    const double d = 1.0 + static_cast<double>(i) / 100.0;
    epsilon[static_cast<std::size_t>(i)] = 1e-6 * (1.0 + static_cast<double>((7 * i) % half));
    a(i, i) = d;
    a(i, half + i) = d;
    a(half + i, half + i) = epsilon[static_cast<std::size_t>(i)];
  }
  std::vector<Eigen::Index> expected;
  for (Eigen::Index i = half - 1; i >= 0; --i) expected.push_back(i);
  std::vector<Eigen::Index> twins(static_cast<std::size_t>(half));
  std::iota(twins.begin(), twins.end(), Eigen::Index{0});
  std::stable_sort(twins.begin(), twins.end(), [&epsilon](Eigen::Index x, Eigen::Index y) {
    return epsilon[static_cast<std::size_t>(x)] > epsilon[static_cast<std::size_t>(y)];
  });
  for (Eigen::Index i : twins) expected.push_back(half + i);
  EXPECT_EQ(pivoted_column_order(testing::givens_mixing(m) * a), expected);
}

TEST(PivotedColumnOrder, WideMatrixStopsAfterItsRowsAndKeepsTheRestInOrder) {
  // 3 rows, 40 columns: column j = (j + 1) e_{j mod 3}. The longest of each direction is taken
  // (40, 39, 38: columns 39, 38, 37); the remaining 37 columns then follow in their order.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 40);
  for (Eigen::Index j = 0; j < 40; ++j) a(j % 3, j) = static_cast<double>(j + 1);
  std::vector<Eigen::Index> expected = {39, 38, 37};
  for (Eigen::Index j = 0; j < 37; ++j) expected.push_back(j);
  EXPECT_EQ(pivoted_column_order(testing::givens_mixing(3) * a), expected);
}

TEST(PivotedColumnOrder, ZeroRemainderStopsEarly) {
  // Every column a multiple of e1, column 3 the longest: after it nothing is left (exactly), so
  // the rest keep their original order.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 5);
  a.row(0) << 2, 4, 6, 10, 8;
  EXPECT_EQ(pivoted_column_order(a), indices({3, 0, 1, 2, 4}));
}

}  // namespace
}  // namespace kinestat::linalg
