// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A fixed orthogonal matrix for tests whose hand-derived answer is invariant under an orthogonal
// change of the rows (singular values, spans, column norms, a pivoted QR's choices): it leaves
// that answer alone while filling every entry, so no zero structure helps the code under test.

#include <Eigen/Dense>

#include <cmath>

namespace kinestat::testing {

/// The m × m product of Givens rotations of adjacent rows (i, i + 1) by 0.3 + 0.11 i radians.
inline Eigen::MatrixXd givens_mixing(Eigen::Index m) {
  Eigen::MatrixXd p = Eigen::MatrixXd::Identity(m, m);
  for (Eigen::Index i = 0; i + 1 < m; ++i) {
    const double angle = 0.3 + 0.11 * static_cast<double>(i);
    Eigen::MatrixXd g = Eigen::MatrixXd::Identity(m, m);
    g(i, i) = g(i + 1, i + 1) = std::cos(angle);
    g(i, i + 1) = -std::sin(angle);
    g(i + 1, i) = std::sin(angle);
    p = g * p;
  }
  return p;
}

}  // namespace kinestat::testing
