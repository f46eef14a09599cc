// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/equilibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinestat::linalg {

Equilibration equilibrate(const std::vector<EntryMagnitude>& pattern, Eigen::Index rows, Eigen::Index cols) {
  // In log2: scaled entry = a_ij + r_i + c_j; each step subtracts half of every row's and
  // column's maximum, which is Ruiz's r_i /= sqrt(max_j |a_ij|) in the max norm.
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  std::vector<double> log_entry(pattern.size());
  for (std::size_t k = 0; k < pattern.size(); ++k) log_entry[k] = std::log2(pattern[k].magnitude);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(rows), c = Eigen::VectorXd::Zero(cols);
  Eigen::VectorXd row_max(rows), col_max(cols);
  Equilibration out;
  for (; out.iterations < kMaxEquilibrationIterations; ++out.iterations) {
    row_max.setConstant(kNone);
    col_max.setConstant(kNone);
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      const double v = log_entry[k] + r(pattern[k].row) + c(pattern[k].col);
      row_max(pattern[k].row) = std::max(row_max(pattern[k].row), v);
      col_max(pattern[k].col) = std::max(col_max(pattern[k].col), v);
    }
    double spread = 0.0;
    for (Eigen::Index i = 0; i < rows; ++i)
      if (row_max(i) != kNone) spread = std::max(spread, std::abs(row_max(i)));
    for (Eigen::Index j = 0; j < cols; ++j)
      if (col_max(j) != kNone) spread = std::max(spread, std::abs(col_max(j)));
    if (spread <= kEquilibrationTolerance) break;
    for (Eigen::Index i = 0; i < rows; ++i)
      if (row_max(i) != kNone) r(i) -= row_max(i) / 2;
    for (Eigen::Index j = 0; j < cols; ++j)
      if (col_max(j) != kNone) c(j) -= col_max(j) / 2;
  }
  out.rows = r.unaryExpr([](double x) { return std::exp2(x); });
  out.cols = c.unaryExpr([](double x) { return std::exp2(x); });
  return out;
}

}  // namespace kinestat::linalg
