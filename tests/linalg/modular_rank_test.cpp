// SPDX-License-Identifier: BSD-3-Clause
// Modular ranks (issue 12, item 4): a lower bound of the rational rank, equal to it for large
// primes; checked on matrices whose ranks are known by construction.
#include <gtest/gtest.h>

#include "kinestat/linalg/modular_rank.hpp"

namespace kinestat::linalg {
namespace {

TEST(ModularRank, ReducesFractionsExactly) {
  // 1/2 mod 7 = 4 (2 * 4 = 8 = 1 mod 7); -1/3 mod 7 = 2 (3 * 2 = 6 = -1).
  EXPECT_EQ(reduce(Rational(1, 2), 7), 4U);
  EXPECT_EQ(reduce(Rational(-1, 3), 7), 2U);
  EXPECT_FALSE(reduce(Rational(1, 14), 7).has_value());
}

TEST(ModularRank, RankOfProductOfThinFactors) {
  // A 6 x 5 matrix of rank 3: the product of 6 x 3 and 3 x 5 integer factors of full rank.
  RationalMatrix left(6, 3), right(3, 5);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 3; ++j) left(i, j) = (i + 1) * (j + 2) % 7 + (i == j ? 5 : 0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 5; ++j) right(i, j) = Rational((i + 2) * (j + 1) % 5 + (i == j ? 3 : 0), j + 1);
  const ModularRank r = modular_rank(left * right);
  EXPECT_EQ(r.rank, exact_rank(left * right));
  EXPECT_EQ(r.rank, 3);
  EXPECT_EQ(r.primes, 2);
  EXPECT_EQ(r.agreeing, 2);
}

TEST(ModularRank, SmallPrimeCanOnlyLowerTheRank) {
  // [[1, 0], [0, 7]] has rank 2 over Q but rank 1 modulo 7.
  ModularMatrix m(2, 2, 7);
  m(0, 0) = 1;
  m(1, 1) = 0;  // 7 mod 7
  EXPECT_EQ(modular_rank(m), 1);
  RationalMatrix q(2, 2);
  q(0, 0) = 1;
  q(1, 1) = 7;
  EXPECT_EQ(modular_rank(q).rank, 2);
}

TEST(ModularRank, HilbertMatrixIsNonSingular) {
  // The 12 x 12 Hilbert matrix is non-singular (its determinant is the reciprocal of an
  // integer), though its condition number (~1e16) makes floating-point SVD call it rank 11.
  RationalMatrix h(12, 12);
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) h(i, j) = Rational(1, i + j + 1);
  EXPECT_EQ(modular_rank(h).rank, 12);
}

}  // namespace
}  // namespace kinestat::linalg
