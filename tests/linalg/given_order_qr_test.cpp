// SPDX-License-Identifier: BSD-3-Clause
// The sparse QR with a caller's column order (SparseQr with column_order) and the nested
// dissection of a graph (nested_dissection_order) and of column groups
// (grouped_nested_dissection_order), against Eigen's dense SVD (an independent method) on
// matrices of known rank built from random factors, and the orders' properties on paths.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/linalg/nested_dissection.hpp"
#include "kinestat/linalg/sparse_qr.hpp"
#include "support/random_matrices.hpp"

namespace kinestat::linalg {
namespace {

TEST(GivenOrderQr, RankAndNullVectorsMatchTheDenseSvd) {
  for (int seed = 0; seed < 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(7300 + seed));
    const int rows = 60 + 5 * seed, cols = 50 + 3 * seed, rank = 30 + seed;
    const Eigen::SparseMatrix<double> a = testing::banded_of_rank(rng, rows, cols, rank);
    const Eigen::MatrixXd dense(a);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense);
    ASSERT_GT(svd.singularValues()(rank - 1), 1e-6);  // rank exactly `rank` by construction
    ASSERT_LT(svd.singularValues()(rank), 1e-12);
    std::vector<Eigen::Index> order(static_cast<std::size_t>(cols));
    std::iota(order.begin(), order.end(), Eigen::Index{0});
    std::shuffle(order.begin(), order.end(), rng);
    const SparseQr qr(a, 1e-9, order);
    EXPECT_EQ(qr.rank(), rank);
    // permutation() lists every column of a once.
    std::vector<Eigen::Index> sorted = qr.permutation();
    std::sort(sorted.begin(), sorted.end());
    for (int j = 0; j < cols; ++j) EXPECT_EQ(sorted[static_cast<std::size_t>(j)], j);
    const Eigen::MatrixXd null = qr.null_vectors(0, cols - rank);
    ASSERT_EQ(null.cols(), cols - rank);
    EXPECT_LT((dense * null).norm(), 1e-9 * null.norm());
    Eigen::FullPivLU<Eigen::MatrixXd> lu(null);
    EXPECT_EQ(lu.rank(), cols - rank);  // independent null vectors
    // The residual of a least-squares fit is orthogonal to the range of a.
    Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(rows, -1.0, 2.0);
    const Eigen::VectorXd residual = qr.least_squares_residual(a, g);
    EXPECT_LT((a.transpose() * residual).norm(), 1e-9 * g.norm());
  }
}

TEST(GivenOrderQr, RejectsAnOrderOfTheWrongLength) {
  Eigen::SparseMatrix<double> a(3, 2);
  a.insert(0, 0) = 1.0;
  EXPECT_THROW(SparseQr(a, 1e-9, std::vector<Eigen::Index>{0}), std::invalid_argument);
  EXPECT_THROW(SparseQr(a, 1e-9, std::vector<Eigen::Index>{1, 1}), std::invalid_argument);
  EXPECT_THROW(SparseQr(a, 1e-9, std::vector<Eigen::Index>{0, 2}), std::invalid_argument);
}

TEST(GivenOrderQr, GroupedOrderGivesTheRankByConstruction) {
  // The banded matrices of known rank with their columns in groups of 1, 2 or 3 consecutive
  // columns: the rank from the grouped order is the rank by construction.
  for (int seed = 0; seed < 9; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(9100 + seed));
    const int rows = 90 + 4 * seed, cols = 72, rank = 40 + seed, group_size = 1 + seed % 3;
    const Eigen::SparseMatrix<double> a = testing::banded_of_rank(rng, rows, cols, rank);
    std::vector<Eigen::Index> groups(static_cast<std::size_t>(cols));
    for (int j = 0; j < cols; ++j) groups[static_cast<std::size_t>(j)] = j / group_size;
    const std::vector<Eigen::Index> order = grouped_nested_dissection_order(a, groups);
    ASSERT_EQ(static_cast<int>(order.size()), cols);
    const SparseQr qr(a, 1e-9, order);
    EXPECT_EQ(qr.rank(), rank);
    const Eigen::MatrixXd null = qr.null_vectors(0, cols - rank);
    EXPECT_LT((Eigen::MatrixXd(a) * null).norm(), 1e-9 * null.norm());
  }
}

// Groups of two columns (x, y) on a path of `groups` groups: row 2g couples x of groups g and
// g + 1 only, row 2g + 1 (when `full`) all four columns of both.
Eigen::SparseMatrix<double> path_of_pairs(int groups, bool full) {
  std::vector<Eigen::Triplet<double>> entries;
  int row = 0;
  for (int g = 0; g + 1 < groups; ++g) {
    entries.emplace_back(row, 2 * g, 1.0);
    entries.emplace_back(row, 2 * g + 2, -1.0);
    ++row;
    if (full) {
      for (int c = 0; c < 4; ++c) entries.emplace_back(row, 2 * g + c, 1.0 + c);
      ++row;
    }
  }
  Eigen::SparseMatrix<double> a(row, 2 * groups);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

TEST(GroupedNestedDissection, KeepsGroupsTogetherAndPutsASeparatorLast) {
  const int groups = 101;
  const Eigen::SparseMatrix<double> a = path_of_pairs(groups, true);
  std::vector<Eigen::Index> group_of_column(2 * groups);
  for (int j = 0; j < 2 * groups; ++j) group_of_column[static_cast<std::size_t>(j)] = j / 2;
  const std::vector<Eigen::Index> order = grouped_nested_dissection_order(a, group_of_column);
  ASSERT_EQ(static_cast<int>(order.size()), 2 * groups);
  std::vector<Eigen::Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int j = 0; j < 2 * groups; ++j) EXPECT_EQ(sorted[static_cast<std::size_t>(j)], j);
  // Each group's two columns next to each other, x before y.
  for (int k = 0; k < 2 * groups; k += 2) {
    EXPECT_EQ(order[static_cast<std::size_t>(k)] % 2, 0);
    EXPECT_EQ(order[static_cast<std::size_t>(k) + 1], order[static_cast<std::size_t>(k)] + 1);
  }
  // The last group separates the path: not an end of it.
  EXPECT_NE(order.back() / 2, 0);
  EXPECT_NE(order.back() / 2, groups - 1);
  EXPECT_EQ(grouped_nested_dissection_order(a, group_of_column), order);  // deterministic
  // A group number without columns (7 is skipped) changes nothing but the names.
  std::vector<Eigen::Index> gapped = group_of_column;
  for (Eigen::Index& g : gapped)
    if (g >= 7) ++g;
  EXPECT_EQ(grouped_nested_dissection_order(a, gapped), order);
  EXPECT_THROW(grouped_nested_dissection_order(a, std::vector<Eigen::Index>(3, 0)), std::invalid_argument);
  std::vector<Eigen::Index> negative = group_of_column;
  negative[4] = -1;
  EXPECT_THROW(grouped_nested_dissection_order(a, negative), std::invalid_argument);
}

TEST(GroupedNestedDissection, RefusesBelowTheShareOfCouplingsKept) {
  // Only x-x rows: each couples 1 column pair of the 2 × 2 its two groups join, share 1/4.
  const int groups = 40;
  std::vector<Eigen::Index> group_of_column(2 * groups);
  for (int j = 0; j < 2 * groups; ++j) group_of_column[static_cast<std::size_t>(j)] = j / 2;
  const Eigen::SparseMatrix<double> sparse = path_of_pairs(groups, false);
  EXPECT_TRUE(grouped_nested_dissection_order(sparse, group_of_column, 0.26).empty());
  EXPECT_EQ(grouped_nested_dissection_order(sparse, group_of_column, 0.24).size(), 2u * groups);
  // With the full rows as well: (1 + 4) of (4 + 4) pairs per group pair, share 5/8.
  const Eigen::SparseMatrix<double> full = path_of_pairs(groups, true);
  EXPECT_TRUE(grouped_nested_dissection_order(full, group_of_column, 0.63).empty());
  EXPECT_EQ(grouped_nested_dissection_order(full, group_of_column, 0.62).size(), 2u * groups);
}

TEST(NestedDissection, IsADeterministicPermutationThatPutsTheSeparatorLast) {
  // A path 0-1-...-(n-1) with loops and repeated edges: any nested dissection order is a
  // permutation, and its last vertex separates the path (it is an inner vertex, not an end).
  const Eigen::Index n = 301;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> edges;
  for (Eigen::Index v = 0; v + 1 < n; ++v) {
    edges.emplace_back(v, v + 1);
    edges.emplace_back(v + 1, v);
    edges.emplace_back(v, v);
  }
  const std::vector<Eigen::Index> order = nested_dissection_order(n, edges);
  ASSERT_EQ(static_cast<Eigen::Index>(order.size()), n);
  std::vector<Eigen::Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (Eigen::Index v = 0; v < n; ++v) EXPECT_EQ(sorted[static_cast<std::size_t>(v)], v);
  EXPECT_NE(order.back(), 0);
  EXPECT_NE(order.back(), n - 1);
  EXPECT_EQ(nested_dissection_order(n, edges), order);
  // No edges: the identity.
  EXPECT_EQ(nested_dissection_order(4, {}), (std::vector<Eigen::Index>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace kinestat::linalg
