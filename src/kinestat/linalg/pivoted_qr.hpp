// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The column order of a Householder QR factorisation with column pivoting, with a tie rule
// that rounding cannot change: columns whose remaining norms are within kPivotTie of the
// largest are equally good, and the one earliest in the original order is taken. A plain
// pivoted QR takes the largest by the last bit, so a symmetric model moved away from the
// origin proposed another (equivalent) bar to release.

#include <Eigen/Core>

#include <vector>

namespace kinestat::linalg {

/// Indices of the columns of `a` in the order the pivoted QR takes them: at each step the
/// largest remaining norm, ties (within kPivotTie, relative) to the lowest original index.
/// Dimensionless: scale `a` first when its columns carry different units.
std::vector<Eigen::Index> pivoted_column_order(const Eigen::MatrixXd& a);

}  // namespace kinestat::linalg
