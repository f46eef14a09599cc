// SPDX-License-Identifier: BSD-3-Clause
// R read from SuiteSparseQR's frontal blocks: sparse_qr_rank (the rank and smallest live pivot,
// R never assembled) and SparseQr (R assembled once, in trapezoidal form). Checked against a hand
// derivation (orthogonal columns, where every pivot is a column norm whatever the order), against
// the rank known by construction (random banded factors, confirmed by a dense SVD), and against
// the R and column permutation that SuiteSparseQR itself returns (its spqr_rconvert and
// spqr_trapezoidal, called here directly), on tall and wide matrices, with and without column
// singletons and empty columns, in METIS's order and in a given one.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <Eigen/SparseCore>

#include <algorithm>
#include <new>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinestat/linalg/cholmod_view.hpp"
#include "kinestat/linalg/sparse_qr.hpp"
#include "support/random_matrices.hpp"

#include <SuiteSparseQR.hpp>

namespace kinestat::linalg {
namespace {

// `a` with `extra` column singletons appended (each a new column with one entry in a new row),
// then `empty` columns without entries (SuiteSparseQR counts them as singleton columns without
// a row).
Eigen::SparseMatrix<double> with_singletons(const Eigen::SparseMatrix<double>& a, int extra, int empty) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < a.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) entries.emplace_back(it.row(), it.col(), it.value());
  for (int s = 0; s < extra; ++s) entries.emplace_back(a.rows() + s, a.cols() + s, 0.5 + s);
  Eigen::SparseMatrix<double> result(a.rows() + extra, a.cols() + extra + empty);
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

// SparseQr's R and permutation are exactly SuiteSparseQR's own: the same entries in the same
// places (SuiteSparseQR called directly on the columns in `order`, as SparseQr factors them).
void expect_suitesparse_r(const Eigen::SparseMatrix<double>& a, const std::vector<Eigen::Index>& order, const SparseQr& qr) {
  CholmodMatrix input(a.rows(), a.cols());
  std::vector<Eigen::Triplet<double, SuiteSparse_long>> entries;
  for (Eigen::Index k = 0; k < a.cols(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, order.empty() ? k : order[static_cast<std::size_t>(k)]); it; ++it)
      entries.emplace_back(it.row(), k, it.value());
  input.setFromTriplets(entries.begin(), entries.end());
  cholmod_sparse view = cholmod_view(input);
  cholmod_common cc{};
  cholmod_l_start(&cc);
  cholmod_sparse* r = nullptr;
  SuiteSparse_long* e = nullptr;
  const SuiteSparse_long rank =
      SuiteSparseQR<double>(order.empty() ? SPQR_ORDERING_METIS : SPQR_ORDERING_NATURAL, 1e-9, 0, &view, &r, &e, &cc);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(rank, qr.rank());
  const SparseFactorView mine = qr.r();
  ASSERT_EQ(static_cast<Eigen::Index>(r->nrow), mine.rows());
  ASSERT_EQ(static_cast<Eigen::Index>(r->ncol), mine.cols());
  const auto* p = static_cast<const SuiteSparse_long*>(r->p);
  const auto* i = static_cast<const SuiteSparse_long*>(r->i);
  const auto* x = static_cast<const double*>(r->x);
  ASSERT_EQ(p[r->ncol], mine.nonZeros());
  for (Eigen::Index k = 0; k <= mine.cols(); ++k) EXPECT_EQ(p[k], mine.outerIndexPtr()[k]) << "column start " << k;
  for (Eigen::Index t = 0; t < mine.nonZeros(); ++t) {
    EXPECT_EQ(i[t], mine.innerIndexPtr()[t]) << "entry " << t;
    EXPECT_EQ(x[t], mine.valuePtr()[t]) << "entry " << t;
  }
  for (Eigen::Index k = 0; k < a.cols(); ++k) {
    const Eigen::Index column = e != nullptr ? static_cast<Eigen::Index>(e[k]) : k;
    EXPECT_EQ(qr.permutation()[static_cast<std::size_t>(k)], order.empty() ? column : order[static_cast<std::size_t>(column)]);
  }
  cholmod_l_free_sparse(&r, &cc);
  if (e != nullptr) cholmod_l_free(static_cast<std::size_t>(a.cols()), sizeof(SuiteSparse_long), e, &cc);
  cholmod_l_finish(&cc);
}

// A banded matrix of rank 25 + seed (random banded factors), tall, or wide for every fourth seed.
Eigen::SparseMatrix<double> banded_for_seed(std::mt19937& rng, int seed) {
  const bool wide = seed % 4 == 3;
  return testing::banded_of_rank(rng, wide ? 40 + seed : 70 + 5 * seed, wide ? 90 : 50 + 3 * seed, 25 + seed);
}

int dense_rank(const Eigen::SparseMatrix<double>& a) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(a)};
  const Eigen::VectorXd s = svd.singularValues();
  return static_cast<int>((s.array() > 1e-9 * s(0)).count());
}

TEST(FrontalBlocksQr, OrthogonalColumnsGiveTheirNormsByHand) {
  // Directions on disjoint pairs of rows, so all columns of different directions are
  // orthogonal. Direction d (rows 2d, 2d + 1) holds (3, 4)·scale_d; directions 0-3 hold it once,
  // 4-6 also hold 2× and −1× its multiple (dead whichever comes first: the live one's pivot is
  // its own norm, 5·scale_d, 10·scale_d or 5·scale_d). Plus two column singletons and an empty
  // column. Rank: 7 directions + 2 singletons = 9; smallest pivot: direction 2's 5 × 0.01.
  const std::vector<double> scale = {1.0, 3.0, 0.01, 7.0, 2.0, 0.5, 4.0};
  std::vector<Eigen::Triplet<double>> entries;
  int column = 0;
  for (int d = 0; d < 7; ++d) {
    const std::vector<double> multiples = d < 4 ? std::vector<double>{1.0} : std::vector<double>{1.0, 2.0, -1.0};
    for (const double m : multiples) {
      entries.emplace_back(2 * d, column, 3.0 * scale[static_cast<std::size_t>(d)] * m);
      entries.emplace_back(2 * d + 1, column, 4.0 * scale[static_cast<std::size_t>(d)] * m);
      ++column;
    }
  }
  entries.emplace_back(14, column++, -0.2);  // singleton, pivot 0.2
  entries.emplace_back(15, column++, 6.0);   // singleton, pivot 6
  ++column;                                  // empty column: dead
  Eigen::SparseMatrix<double> a(17, column);
  a.setFromTriplets(entries.begin(), entries.end());
  for (const bool given : {false, true}) {
    SCOPED_TRACE(given ? "given order" : "METIS");
    std::vector<Eigen::Index> order;
    if (given) {
      order.resize(static_cast<std::size_t>(column));
      std::iota(order.rbegin(), order.rend(), Eigen::Index{0});
    }
    const SparseRankCount count = sparse_qr_rank(a, 1e-9, order);
    EXPECT_EQ(count.rank, 9);
    EXPECT_NEAR(count.smallest_pivot, 0.05, 1e-15);
    EXPECT_GT(count.peak_memory, 0u);
  }
}

TEST(FrontalBlocksQr, RankByConstructionAndSuiteSparsesOwnR) {
  for (int seed = 0; seed < 16; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(4100 + seed));
    const int rank = 25 + seed, singletons = seed % 2 == 0 ? 0 : 1 + seed % 5;
    const Eigen::SparseMatrix<double> a = with_singletons(banded_for_seed(rng, seed), singletons, seed % 3);
    ASSERT_EQ(dense_rank(a), rank + singletons);
    std::vector<Eigen::Index> shuffled(static_cast<std::size_t>(a.cols()));
    std::iota(shuffled.begin(), shuffled.end(), Eigen::Index{0});
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    for (const std::vector<Eigen::Index>& order : {std::vector<Eigen::Index>{}, shuffled}) {
      SCOPED_TRACE(order.empty() ? "METIS" : "given order");
      const SparseRankCount count = sparse_qr_rank(a, 1e-9, order);
      const SparseQr qr = order.empty() ? SparseQr(a, 1e-9) : SparseQr(a, 1e-9, order);
      EXPECT_EQ(count.rank, rank + singletons);
      EXPECT_EQ(count.rank, qr.rank());
      // The same factorisation: the very same numbers, read from the blocks or from R.
      EXPECT_EQ(count.smallest_pivot, qr.smallest_pivot());
      EXPECT_GT(count.smallest_pivot, 1e-9);
      // Without R assembled the factorisation needs less memory at its peak.
      EXPECT_LE(count.peak_memory, qr.peak_memory());
      expect_suitesparse_r(a, order, qr);
    }
  }
}

TEST(FrontalBlocksQr, AThresholdAskedForAfterTheOrderGivesSuiteSparsesOwnFactorisation) {
  // SparseQr(a, threshold function) orders and analyses `a` before it asks for the threshold
  // when every column has two or more entries (no column singletons whatever the threshold),
  // else asks first; either way R, the permutation and the rank are SuiteSparseQR's own with
  // that threshold (METIS order), and the function is asked once.
  for (int seed = 0; seed < 8; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(4300 + seed));
    // Seeds 0-3: every column holds several entries (the product of two banded factors); 4-7:
    // with column singletons or an empty column, where the threshold decides the singletons.
    const int singletons = seed >= 4 && seed % 2 == 0 ? 2 : 0;
    const Eigen::SparseMatrix<double> a =
        seed < 4 ? banded_for_seed(rng, seed) : with_singletons(banded_for_seed(rng, seed), singletons, seed % 2);
    ASSERT_EQ(dense_rank(a), 25 + seed + singletons);
    int asked = 0;
    const SparseQr late(a, [&asked] {
      ++asked;
      return 1e-9;
    });
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(late.rank(), dense_rank(a));
    expect_suitesparse_r(a, {}, late);
  }
}

TEST(FrontalBlocksQr, AThresholdThatCannotBeHadEndsTheFactorisation) {
  // The caller's computation of the threshold failed (e.g. out of memory on another thread):
  // its exception comes out of SparseQr, and what SuiteSparse made is released (the ASan build
  // checks for leaks).
  std::mt19937 rng(4400);
  const Eigen::SparseMatrix<double> a = testing::banded_of_rank(rng, 60, 40, 20);
  EXPECT_THROW(SparseQr(a, []() -> double { throw std::bad_alloc(); }), std::bad_alloc);
  EXPECT_THROW(SparseQr(with_singletons(a, 1, 1), []() -> double { throw std::runtime_error("no threshold"); }),
               std::runtime_error);
  EXPECT_THROW(SparseQr(a, [] { return -1.0; }), std::invalid_argument);
}

TEST(FrontalBlocksQr, EmptyMatricesAndBadOrders) {
  EXPECT_EQ(sparse_qr_rank(Eigen::SparseMatrix<double>(0, 3), 1e-9).rank, 0);
  EXPECT_EQ(sparse_qr_rank(Eigen::SparseMatrix<double>(4, 0), 1e-9).rank, 0);
  const SparseRankCount zero = sparse_qr_rank(Eigen::SparseMatrix<double>(5, 4), 1e-9);
  EXPECT_EQ(zero.rank, 0);
  EXPECT_EQ(zero.smallest_pivot, 0.0);
  Eigen::SparseMatrix<double> a(3, 2);
  a.insert(0, 0) = 1.0;
  EXPECT_THROW(sparse_qr_rank(a, 1e-9, std::vector<Eigen::Index>{0}), std::invalid_argument);
  EXPECT_THROW(sparse_qr_rank(a, 1e-9, std::vector<Eigen::Index>{1, 1}), std::invalid_argument);
  EXPECT_THROW(sparse_qr_rank(a, 1e-9, std::vector<Eigen::Index>{0, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace kinestat::linalg
