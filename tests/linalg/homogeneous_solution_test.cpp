// SPDX-License-Identifier: BSD-3-Clause
// Homogeneous solutions on the seed's single-circuit example (seed 000, section 2.1) and on
// small hand-checked systems.
#include <gtest/gtest.h>

#include "kinestat/linalg/homogeneous_solution.hpp"

namespace kinestat::linalg {
namespace {

// [M^D]6,6 of two spheric couplings at (0,0,0) and (0,0,1), seed 000 section 2.1.
RationalMatrix two_spheres_motion_matrix() {
  const int values[6][6] = {{1, 0, 0, 1, 0, 0},  {0, 1, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1},
                            {0, 0, 0, 0, -1, 0}, {0, 0, 0, 1, 0, 0}, {0, 0, 0, 0, 0, 0}};
  RationalMatrix m(6, 6);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) m(r, c) = values[r][c];
  return m;
}

TEST(HomogeneousSolution, SingleCircuitOfTwoSpheresExact) {
  const auto solution = solve_homogeneous(two_spheres_motion_matrix());
  EXPECT_TRUE(solution.rank.exact);
  EXPECT_EQ(solution.rank.rank, 5);
  ASSERT_EQ(solution.free_variables, std::vector<Eigen::Index>{2});  // ta, the earliest that can be free
  // Only ta and tb move, with ta + tb = 0.
  const RationalMatrix& k = *solution.exact_coefficients;
  for (int i = 0; i < 6; ++i) {
    const Rational expected = i == 2 ? 1 : (i == 5 ? -1 : 0);
    EXPECT_EQ(k(i, 0), expected) << "variable " << i;
  }
  EXPECT_EQ(solution.redundant_rows, std::vector<Eigen::Index>{5});  // the empty sixth row
}

TEST(HomogeneousSolution, FloatingPointAgreesWithExact) {
  const auto exact = solve_homogeneous(two_spheres_motion_matrix());
  const auto approx = solve_homogeneous(two_spheres_motion_matrix().to_double(), {});
  EXPECT_FALSE(approx.rank.exact);
  EXPECT_EQ(approx.rank.rank, exact.rank.rank);
  EXPECT_EQ(approx.free_variables, exact.free_variables);
  EXPECT_TRUE(approx.coefficients.isApprox(exact.coefficients, 1e-12));
  EXPECT_EQ(approx.redundant_rows, exact.redundant_rows);
  EXPECT_GT(approx.rank.smallest_kept, 0.5);
  EXPECT_LT(approx.rank.largest_dropped, 1e-14);
}

TEST(HomogeneousSolution, ChosenFreeVariables) {
  const auto solution = with_free_variables(solve_homogeneous(two_spheres_motion_matrix()), {5});
  EXPECT_EQ((*solution.exact_coefficients)(2, 0), Rational(-1));
  EXPECT_THROW(with_free_variables(solve_homogeneous(two_spheres_motion_matrix()), {0}), DependentFreeVariable);
}

TEST(HomogeneousSolution, TheUsersToleranceDecidesWhichVariableCanBeFree) {
  // A = [1, 1e-8]: x = t (-1e-8, 1). x0 can be free only through a coefficient of 1e8 on x1; its
  // row of the unit null vector has norm 1e-8. Below the default threshold (2^22 eps = 9.3e-10)
  // that is still independent, so x0 (the earliest) is free; with a user tolerance of 1e-7
  // (Tolerances::with_rank, as --tolerance) it is not, and x1 is free with x0 = -1e-8 x1.
  Eigen::MatrixXd a(1, 2);
  a << 1, 1e-8;
  const auto by_default = solve_homogeneous(a, {});
  EXPECT_EQ(by_default.free_variables, std::vector<Eigen::Index>{0});
  EXPECT_NEAR(by_default.coefficients(1, 0), -1e8, 1e-8 * 1e8);

  const Tolerances loose = Tolerances::with_rank(1e-7);
  const auto tolerant = solve_homogeneous(a, {loose.rank}, loose.free_variable);
  EXPECT_EQ(tolerant.rank.rank, 1);  // sigma = sqrt(1 + 1e-16) is far above 1e-7
  EXPECT_EQ(tolerant.free_variables, std::vector<Eigen::Index>{1});
  EXPECT_NEAR(tolerant.coefficients(0, 0), -1e-8, 1e-20);
  // The same tolerance refuses x0 as a chosen free variable.
  EXPECT_THROW(with_free_variables(tolerant, {0}, loose.free_variable), DependentFreeVariable);
  EXPECT_NO_THROW(with_free_variables(by_default, {1}));
}

TEST(Tolerances, TheUsersToleranceReachesEveryRankDecision) {
  const Tolerances defaults;
  EXPECT_FALSE(defaults.rank.has_value());
  EXPECT_EQ(defaults.pair_rank, 0x1p19 * kEpsilon);
  EXPECT_EQ(defaults.free_variable, 0x1p22 * kEpsilon);
  const Tolerances user = Tolerances::with_rank(1e-6);
  EXPECT_EQ(user.rank, 1e-6);
  EXPECT_EQ(user.pair_rank, 1e-6);
  EXPECT_EQ(user.free_variable, 1e-6);
  EXPECT_EQ(Tolerances::with_rank(std::nullopt).free_variable, defaults.free_variable);
}

TEST(HomogeneousSolution, RedundantRowsDependOnLaterRows) {
  RationalMatrix a(3, 2);
  a(0, 0) = 2;  // row 0 = 2 * row 2
  a(1, 1) = 1;
  a(2, 0) = 1;
  EXPECT_EQ(redundant_rows(a), std::vector<Eigen::Index>{0});
}

// A matrix with rows and no column (a network whose every coupling is rigid has no motion
// unknown): rank 0, so every row is redundant. Found by fuzz_valid_models as undefined behaviour.
TEST(HomogeneousSolution, RowsWithoutColumnsAreAllRedundant) {
  EXPECT_EQ(redundant_rows(Eigen::MatrixXd(3, 0), 0), (std::vector<Eigen::Index>{0, 1, 2}));
  EXPECT_TRUE(redundant_rows(Eigen::MatrixXd(0, 0), 0).empty());
}

}  // namespace
}  // namespace kinestat::linalg
