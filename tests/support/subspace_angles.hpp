#pragma once
// Comparing two bases of one space (modes, self-stresses) without comparing entries: a basis is
// only defined up to an invertible change of coordinates.

#include <Eigen/Dense>

namespace kinestat::testing {

/// Cosines of the principal angles between the column spans of `a` and `b` (both of full column
/// rank, same number of rows): the singular values of Qaᵀ Qb. Equal spaces give cosines 1.
inline Eigen::VectorXd principal_cosines(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const Eigen::MatrixXd qa = Eigen::HouseholderQR<Eigen::MatrixXd>(a).householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.cols());
  const Eigen::MatrixXd qb = Eigen::HouseholderQR<Eigen::MatrixXd>(b).householderQ() * Eigen::MatrixXd::Identity(b.rows(), b.cols());
  return Eigen::JacobiSVD<Eigen::MatrixXd>(qa.transpose() * qb).singularValues();
}

}  // namespace kinestat::testing
