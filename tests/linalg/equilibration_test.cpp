// SPDX-License-Identifier: BSD-3-Clause
// Ruiz equilibration of a magnitude pattern: the scaled maxima of every row and column are 1,
// and rank-relevant structure is left to the values (the pattern carries no values).
#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/linalg/equilibration.hpp"

namespace kinestat::linalg {
namespace {

double scaled_max_deviation(const std::vector<EntryMagnitude>& pattern, const Equilibration& e, Eigen::Index rows, Eigen::Index cols) {
  Eigen::VectorXd row_max = Eigen::VectorXd::Zero(rows), col_max = Eigen::VectorXd::Zero(cols);
  for (const auto& p : pattern) {
    const double v = e.rows(p.row) * p.magnitude * e.cols(p.col);
    row_max(p.row) = std::max(row_max(p.row), v);
    col_max(p.col) = std::max(col_max(p.col), v);
  }
  double worst = 0.0;
  for (Eigen::Index i = 0; i < rows; ++i) worst = std::max(worst, std::abs(std::log2(row_max(i))));
  for (Eigen::Index j = 0; j < cols; ++j) worst = std::max(worst, std::abs(std::log2(col_max(j))));
  return worst;
}

TEST(Equilibration, ColumnOfTinyNaturalScaleIsScaledUp) {
  // [1 1e-9; 0 1e-9]: the second column is measured in a unit 1e9 too large. Scaling it by 1e9
  // gives [1 1; 0 1], all maxima 1; the rows need no scaling.
  const std::vector<EntryMagnitude> pattern{{0, 0, 1.0}, {0, 1, 1e-9}, {1, 1, 1e-9}};
  const Equilibration e = equilibrate(pattern, 2, 2);
  EXPECT_LE(scaled_max_deviation(pattern, e, 2, 2), kEquilibrationTolerance);
  EXPECT_NEAR(e.cols(1) * e.rows(1) / (e.cols(0) * e.rows(0)), 1e9, 1e9 * 1e-2);
}

TEST(Equilibration, ScalingAllMagnitudesTogetherChangesNoRatio) {
  // A unit change multiplies whole rows or columns: the equilibrated matrix is the same.
  std::vector<EntryMagnitude> pattern{{0, 0, 1.0}, {0, 1, 1e3}, {1, 0, 1e-6}, {1, 2, 5.0}, {2, 1, 2.0}, {2, 2, 1e-4}};
  const Equilibration e = equilibrate(pattern, 3, 3);
  EXPECT_LE(scaled_max_deviation(pattern, e, 3, 3), kEquilibrationTolerance);
  auto scaled = pattern;
  for (auto& p : scaled) p.magnitude *= p.col == 1 ? 1e3 : 1.0;  // column 1 in other units
  const Equilibration f = equilibrate(scaled, 3, 3);
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    const auto& p = pattern[k];
    EXPECT_NEAR(e.rows(p.row) * p.magnitude * e.cols(p.col), f.rows(p.row) * scaled[k].magnitude * f.cols(p.col), 2e-3);
  }
}

TEST(Equilibration, EmptyRowsAndColumnsKeepFactorOne) {
  const std::vector<EntryMagnitude> pattern{{0, 0, 4.0}};
  const Equilibration e = equilibrate(pattern, 2, 2);
  EXPECT_DOUBLE_EQ(e.rows(1), 1.0);
  EXPECT_DOUBLE_EQ(e.cols(1), 1.0);
  EXPECT_NEAR(e.rows(0) * 4.0 * e.cols(0), 1.0, 1e-3);
}

}  // namespace
}  // namespace kinestat::linalg
