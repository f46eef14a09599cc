// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/vibration.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

namespace {

Eigen::MatrixXd vibration_block(const Eigen::MatrixXd& a, const std::vector<Eigen::Index>& rows, const std::vector<Eigen::Index>& cols) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < cols.size(); ++j) out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = a(rows[i], cols[j]);
  return out;
}

// A sign for each shape, so that output repeats: largest-magnitude component positive.
void fix_signs(Eigen::MatrixXd& shapes) {
  for (Eigen::Index c = 0; c < shapes.cols(); ++c) {
    Eigen::Index at = 0;
    shapes.col(c).cwiseAbs().maxCoeff(&at);
    if (shapes(at, c) < 0) shapes.col(c) *= -1.0;
  }
}

// The eigenproblem of a diagonal mass matrix: the rows of M that are exactly zero are massless.
VibrationModes diagonal_mass_modes(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass) {
  const Eigen::Index n = stiffness.rows();
  VibrationModes modes;
  std::vector<Eigen::Index> massless;
  // Massless is a property of the data (no mass was given there), not of rounding: exact zero.
  for (Eigen::Index i = 0; i < n; ++i) (mass.row(i).isZero(0.0) ? massless : modes.massive).push_back(i);
  const auto m = static_cast<Eigen::Index>(modes.massive.size());
  if (m == 0) return modes;

  const Eigen::MatrixXd k_mm = vibration_block(stiffness, modes.massive, modes.massive);
  Eigen::MatrixXd condensed = k_mm;
  Eigen::MatrixXd recovery(static_cast<Eigen::Index>(massless.size()), m);  // φ_0 = recovery φ_m
  if (!massless.empty()) {
    const Eigen::MatrixXd k_00 = vibration_block(stiffness, massless, massless);
    const Eigen::MatrixXd k_0m = vibration_block(stiffness, massless, modes.massive);
    // K_00 is symmetric; LDLT copes with the indefinite tangent stiffness of a buckled prestress.
    const Eigen::LDLT<Eigen::MatrixXd> k_00_factor(k_00);
    // A massless mechanism (K_00 singular) leaves a pivot at rounding level of its own diagonal
    // entry (compared entry by entry, so that no unit enters); Eigen's solve would skip it.
    const Eigen::VectorXd diagonal = k_00_factor.transpositionsP() * k_00.diagonal();
    const Eigen::VectorXd& pivots = k_00_factor.vectorD();
    bool singular = k_00_factor.info() != Eigen::Success;
    for (Eigen::Index i = 0; i < pivots.size(); ++i) singular = singular || std::abs(pivots(i)) <= kZeroStiffness * std::abs(diagonal(i));
    if (singular)
      throw std::invalid_argument("vibration_modes: the massless coordinates are not held by the stiffness (a massless mechanism)");
    recovery = -k_00_factor.solve(k_0m);
    condensed = k_mm + k_0m.transpose() * recovery;
    condensed = (condensed + condensed.transpose()).eval() / 2;  // symmetric to rounding
  }
  const Eigen::MatrixXd m_mm = vibration_block(mass, modes.massive, modes.massive);
  const Eigen::LLT<Eigen::MatrixXd> mass_factor(m_mm);
  if (mass_factor.info() != Eigen::Success)
    throw std::invalid_argument("vibration_modes: the mass matrix of the coordinates with mass is not positive definite");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(condensed, m_mm, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success) throw std::invalid_argument("vibration_modes: the eigensolver did not converge");
  modes.eigenvalues = solver.eigenvalues();  // ascending
  modes.frequencies.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double lambda = modes.eigenvalues(i);
    modes.frequencies(i) = std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2 * std::numbers::pi);
  }
  modes.shapes = Eigen::MatrixXd::Zero(n, m);
  const Eigen::MatrixXd& phi = solver.eigenvectors();  // φᵀ M φ = I
  for (std::size_t i = 0; i < modes.massive.size(); ++i) modes.shapes.row(modes.massive[i]) = phi.row(static_cast<Eigen::Index>(i));
  if (!massless.empty()) {
    const Eigen::MatrixXd recovered = recovery * phi;
    for (std::size_t i = 0; i < massless.size(); ++i) modes.shapes.row(massless[i]) = recovered.row(static_cast<Eigen::Index>(i));
  }
  fix_signs(modes.shapes);
  return modes;
}

}  // namespace

VibrationModes vibration_modes(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass) {
  const Eigen::Index n = stiffness.rows();
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n)
    throw std::invalid_argument("vibration_modes: the stiffness and mass matrices must be square and of one size");
  if (mass.isDiagonal(0.0) || n == 0) return diagonal_mass_modes(stiffness, mass);
  // A full mass matrix (Nᵀ M N of a lumped M under rigid constraints): in its eigenvectors Q it is
  // diagonal; directions below kMasslessRelative × the largest eigenvalue have no mass.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> split(mass);
  if (split.info() != Eigen::Success) throw std::invalid_argument("vibration_modes: the mass matrix could not be decomposed");
  const Eigen::MatrixXd& q = split.eigenvectors();
  Eigen::VectorXd diagonal = split.eigenvalues();
  const double largest = diagonal.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < n; ++i)
    if (diagonal(i) <= kMasslessRelative * largest) diagonal(i) = 0.0;
  Eigen::MatrixXd k = q.transpose() * stiffness * q;
  k = (k + k.transpose()).eval() / 2;
  VibrationModes modes = diagonal_mass_modes(k, diagonal.asDiagonal().toDenseMatrix());
  modes.shapes = (q * modes.shapes).eval();
  fix_signs(modes.shapes);
  modes.massive.clear();  // the massive directions are combinations, not coordinates
  for (Eigen::Index i = 0; i < n; ++i)
    if (!mass.row(i).isZero(0.0)) modes.massive.push_back(i);
  return modes;
}

}  // namespace kinestat::framework
