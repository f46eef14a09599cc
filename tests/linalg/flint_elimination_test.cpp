// SPDX-License-Identifier: BSD-3-Clause
// FLINT elimination (issue 41, item 3) on small matrices whose ranks, null spaces, redundant
// rows and inverses are derived by hand in the comments; the same answers through the exact
// path's entry points (exact_rank, solve_homogeneous, with_free_variables), which use FLINT
// when it is built in and GMP elimination otherwise.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "kinestat/linalg/flint_elimination.hpp"
#include "kinestat/linalg/homogeneous_solution.hpp"

namespace kinestat::linalg {
namespace {

RationalMatrix matrix(const std::vector<std::vector<std::string>>& rows) {
  RationalMatrix m(static_cast<Eigen::Index>(rows.size()), rows.empty() ? 0 : static_cast<Eigen::Index>(rows[0].size()));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = Rational(rows[r][c]);
      m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)).canonicalize();
    }
  return m;
}

// A = [1 2 3; 2 4 6; 1 0 1]: row 2 = 2 row 1, rank 2. Pivots from the last column backwards:
// x3 and x2 are pivots, x1 is free; x1 = 1 gives x3 = -1, x2 = 1 (A (1, 1, -1) = 0 by hand:
// 1 + 2 - 3, 2 + 4 - 6, 1 + 0 - 1). From the bottom up, row 3 and row 2 are kept and row 1
// (= row 2 / 2) depends on them.
RationalMatrix dependent_rows() { return matrix({{"1", "2", "3"}, {"2", "4", "6"}, {"1", "0", "1"}}); }

// A = [1/2 1/3; 1/4 1/6]: row 1 = 2 row 2, rank 1; x2 is the pivot, x1 = 1 gives
// x2 = -(1/2)/(1/3) = -3/2; row 1 depends on row 2.
RationalMatrix fractions() { return matrix({{"1/2", "1/3"}, {"1/4", "1/6"}}); }

class FlintElimination : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!flint_available()) GTEST_SKIP() << "built without FLINT (KINESTAT_FLINT=OFF)";
  }
};

TEST_F(FlintElimination, RankNullSpaceAndRedundantRowsOfIntegers) {
  const RationalMatrix a = dependent_rows();
  EXPECT_EQ(flint_rank(a), 2);
  const RightPivotNullSpace reduced = flint_right_pivot_null_space(a);
  EXPECT_EQ(reduced.rank, 2);
  EXPECT_EQ(reduced.pivot_columns, (std::vector<Eigen::Index>{2, 1}));
  EXPECT_EQ(reduced.free_variables, std::vector<Eigen::Index>{0});
  EXPECT_EQ(reduced.null_basis, matrix({{"1"}, {"1"}, {"-1"}}));
  EXPECT_EQ(flint_redundant_rows(a), std::vector<Eigen::Index>{0});
}

TEST_F(FlintElimination, RankNullSpaceAndRedundantRowsOfFractions) {
  const RationalMatrix a = fractions();
  EXPECT_EQ(flint_rank(a), 1);
  const RightPivotNullSpace reduced = flint_right_pivot_null_space(a);
  EXPECT_EQ(reduced.free_variables, std::vector<Eigen::Index>{0});
  EXPECT_EQ(reduced.null_basis, matrix({{"1"}, {"-3/2"}}));
  EXPECT_EQ(flint_redundant_rows(a), std::vector<Eigen::Index>{0});
}

TEST_F(FlintElimination, LargeEntriesCancelExactly) {
  // det [10^30 1; 1 10^-30] = 1 - 1 = 0: rank 1. With 1 + 10^-30 in the corner the determinant
  // is 10^30 (10^-30 + 1) - 1 = 10^30: rank 2. Doubles see both as the same matrix.
  EXPECT_EQ(flint_rank(matrix({{"1000000000000000000000000000000", "1"}, {"1", "1/1000000000000000000000000000000"}})), 1);
  EXPECT_EQ(flint_rank(matrix({{"1000000000000000000000000000000", "1"},
                               {"1", "1000000000000000000000000000001/1000000000000000000000000000000"}})),
            2);
}

TEST_F(FlintElimination, InverseOrNothing) {
  // [2 1; 1 1]^-1 = [1 -1; -1 2] (determinant 1); [1 2; 2 4] is singular.
  EXPECT_EQ(flint_inverse(matrix({{"2", "1"}, {"1", "1"}})), matrix({{"1", "-1"}, {"-1", "2"}}));
  EXPECT_FALSE(flint_inverse(matrix({{"1", "2"}, {"2", "4"}})).has_value());
  EXPECT_THROW(flint_inverse(RationalMatrix(2, 3)), std::invalid_argument);
}

TEST_F(FlintElimination, EmptyMatrices) {
  // No rows: every variable is free (the identity); no columns: every row is zero, redundant.
  const RightPivotNullSpace no_rows = flint_right_pivot_null_space(RationalMatrix(0, 3));
  EXPECT_EQ(no_rows.rank, 0);
  EXPECT_EQ(no_rows.free_variables, (std::vector<Eigen::Index>{0, 1, 2}));
  EXPECT_EQ(no_rows.null_basis, matrix({{"1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}}));
  EXPECT_EQ(flint_redundant_rows(RationalMatrix(2, 0)), (std::vector<Eigen::Index>{0, 1}));
  EXPECT_EQ(flint_rank(RationalMatrix(0, 0)), 0);
}

// The exact path's entry points give the same hand-derived answers, with FLINT or without it.
TEST(ExactPath, HandDerivedAnswersWithEitherElimination) {
  EXPECT_EQ(exact_rank(dependent_rows()), 2);
  const HomogeneousSolution solution = solve_homogeneous(dependent_rows());
  EXPECT_TRUE(solution.rank.exact);
  EXPECT_EQ(solution.rank.rank, 2);
  EXPECT_EQ(solution.free_variables, std::vector<Eigen::Index>{0});
  EXPECT_EQ(*solution.exact_coefficients, matrix({{"1"}, {"1"}, {"-1"}}));
  EXPECT_EQ(solution.redundant_rows, std::vector<Eigen::Index>{0});
  // x3 chosen free instead: x1 = -x3, x2 = -x3 (the basis (1, 1, -1) divided by -1).
  const HomogeneousSolution chosen = with_free_variables(solution, {2});
  EXPECT_EQ(*chosen.exact_coefficients, matrix({{"-1"}, {"-1"}, {"1"}}));
  const HomogeneousSolution halves = solve_homogeneous(fractions());
  EXPECT_EQ(*halves.exact_coefficients, matrix({{"1"}, {"-3/2"}}));
  EXPECT_EQ(halves.redundant_rows, std::vector<Eigen::Index>{0});
}

}  // namespace
}  // namespace kinestat::linalg
