// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Diagonal equilibration of a matrix from the natural magnitudes of its entries. A rank
// decision relative to sigma_max is only meaningful when rows and columns are measured in
// comparable units; multiplying rows and columns by positive factors changes no rank, only
// how far the singular values spread.

#include <Eigen/Core>

#include <vector>
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

/// One entry of the magnitude pattern: where an entry can be non-zero and how large it is in
/// the natural units of its row and column (a positive number).
struct EntryMagnitude {
  Eigen::Index row = 0;
  Eigen::Index col = 0;
  double magnitude = 1.0;
};

/// Row and column factors r, c such that max_j r_i m_ij c_j = 1 for every row and column the
/// pattern touches (1 elsewhere).
struct Equilibration {
  Eigen::VectorXd rows;
  Eigen::VectorXd cols;
  int iterations = 0;  ///< Ruiz iterations run
};

/// Ruiz's iteration in the max norm (D. Ruiz, "A scaling algorithm to equilibrate both rows
/// and columns norms in matrices", RAL-TR-2001-034) on the magnitude pattern, not on the
/// values: an entry that is small because of cancellation (exactly or nearly singular geometry)
/// stays small, only a spread of natural scales (element lengths of 1e-6 and 1e3) is removed.
/// Stops when every scaled row and column maximum is within kEquilibrationTolerance of 1 (in
/// log2) or after kMaxEquilibrationIterations.
Equilibration equilibrate(const std::vector<EntryMagnitude>& pattern, Eigen::Index rows, Eigen::Index cols);

/// Iteration cap of `equilibrate` (each iteration roughly halves the spread left in log2).
inline constexpr int kMaxEquilibrationIterations = 100;

}  // namespace kinestat::linalg
