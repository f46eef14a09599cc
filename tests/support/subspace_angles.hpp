// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Comparing two bases of one space (modes, self-stresses) without comparing entries: a basis is
// only defined up to an invertible change of coordinates.

#include <Eigen/Dense>

namespace kinestat::testing {

/// An orthonormal basis of the column span of `a` (full column rank): the thin Q of its
/// Householder QR.
inline Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& a) {
  return Eigen::HouseholderQR<Eigen::MatrixXd>(a).householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.cols());
}

/// Cosines of the principal angles between the column spans of `a` and `b` (both of full column
/// rank, same number of rows): the singular values of Qaᵀ Qb. Equal spaces give cosines 1.
inline Eigen::VectorXd principal_cosines(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return Eigen::JacobiSVD<Eigen::MatrixXd>(orthonormal_columns(a).transpose() * orthonormal_columns(b)).singularValues();
}

/// ‖X − Q Qᵀ X‖_F for orthonormal bases X of span(`x`) and Q of span(`subspace`) (both of full
/// column rank, same number of rows): at least the sine of the largest principal angle between
/// span(x) and the subspace, 0 when span(x) lies in it. Cheaper than principal_cosines for a
/// few vectors against a large space, and one-sided (span(x) may be smaller).
inline double distance_to_span(const Eigen::MatrixXd& x, const Eigen::MatrixXd& subspace) {
  const Eigen::MatrixXd qx = orthonormal_columns(x), q = orthonormal_columns(subspace);
  return (qx - q * (q.transpose() * qx)).norm();
}

}  // namespace kinestat::testing
