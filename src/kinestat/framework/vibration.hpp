// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Free vibration of a framework about its configuration (issue 38, item 4): the generalized
// symmetric eigenproblem K φ = ω² M φ over the free coordinates, with K the (tangent) stiffness
// and M the lumped mass matrix. Coordinates without mass (the nodes of massless leaves, rotations
// without inertia) carry no inertia force, so they are condensed out first (static condensation:
// K* = K_mm − K_m0 K_00⁻¹ K_0m) and follow the massive ones quasi-statically.

#include <Eigen/Core>

#include <vector>

namespace kinestat::framework {

/// The eigenpairs of K φ = ω² M φ, lowest first.
struct VibrationModes {
  /// ω² per mode (rad²/s² in consistent units), ascending. A negative value is a mode the
  /// stiffness does not hold (K + K_G not positive definite: buckled by a prestress).
  Eigen::VectorXd eigenvalues;
  /// ω / 2π in Hz, ascending; a mode with negative ω² gets −√|ω²| / 2π (marked, not hidden).
  Eigen::VectorXd frequencies;
  /// One column per mode over all coordinates of K (the massless ones recovered by the
  /// condensation), mass-normalised: φᵀ M φ = 1.
  Eigen::MatrixXd shapes;
  /// The coordinates whose row of M is not zero (with a diagonal M: the rows of K kept in the
  /// eigenproblem), increasing.
  std::vector<Eigen::Index> massive;
};

/// Solves K φ = ω² M φ for symmetric K (n × n, force per length in consistent units) and
/// symmetric positive semidefinite M (n × n, mass; lumped: diagonal). A coordinate whose row of
/// M is exactly zero is massless and condensed out; the massless block of K must then be
/// non-singular (a massless mechanism has no frequency) and the massive block of M positive
/// definite, otherwise std::invalid_argument says which. Returns every mode of the massive
/// coordinates (empty when no coordinate has mass).
VibrationModes vibration_modes(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass);

}  // namespace kinestat::framework
