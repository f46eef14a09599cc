// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Deformation functions of seed 002, eqs (2)-(4), and their analytic derivatives with respect
// to the nodal coordinates. Velocities of a node are (ẋ, ω): the translation rate (length/s)
// and the angular velocity (rad/s), both in global axes; a triad vector e rotates as ė = ω × e.

#include <Eigen/Core>

namespace kinestat::framework {

using Vector6 = Eigen::Matrix<double, 6, 1>;
/// Derivative of six deformations; columns are (ẋ_p, ω_p, ẋ_q, ω_q), three each.
using Derivative6x12 = Eigen::Matrix<double, 6, 12>;
/// Rates of the two nodes of an element: (ẋ_p, ω_p, ẋ_q, ω_q), length/s and rad/s, global axes.
using NodeRates12 = Eigen::Matrix<double, 12, 1>;

/// Configuration of one spatial beam: end positions (global, length) and the element triads
/// at p and q (columns e_x, e_y, e_z in global axes, orthonormal), reference length l0 and the
/// torsion–elongation constant c_r (length²) of eq (3).
struct BeamConfiguration {
  Eigen::Vector3d xp = Eigen::Vector3d::Zero();
  Eigen::Vector3d xq = Eigen::Vector3d::UnitX();
  Eigen::Matrix3d triad_p = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d triad_q = Eigen::Matrix3d::Identity();
  double l0 = 1.0;
  double torsion_coupling = 0.0;
};

/// Truss elongation ε1 = l − l0 (eq 2), length.
double truss_elongation(const Eigen::Vector3d& xp, const Eigen::Vector3d& xq, double l0);
/// dε1/d(ẋ_p, ẋ_q): (−e_l, e_l), with e_l the unit vector from p to q.
Eigen::Matrix<double, 1, 6> truss_elongation_derivative(const Eigen::Vector3d& xp, const Eigen::Vector3d& xq);

/// The basic deformations ε̄1..ε̄6 of eq (4): elongation, torsion and four bending angles, the
/// last five multiplied by l0 so that all six are lengths.
Vector6 beam_basic_deformations(const BeamConfiguration& beam);
/// The deformations ε1..ε6 of eq (3), including the second-order terms, lengths.
Vector6 beam_deformations(const BeamConfiguration& beam);
/// dε̄/d(ẋ_p, ω_p, ẋ_q, ω_q) of eq (4).
Derivative6x12 beam_basic_derivative(const BeamConfiguration& beam);
/// dε/dε̄ of eq (3) (identity when all ε̄2..ε̄6 vanish).
Eigen::Matrix<double, 6, 6> beam_second_order_jacobian(const Vector6& basic, double l0, double torsion_coupling);
/// dε/d(ẋ_p, ω_p, ẋ_q, ω_q): the chain rule through eqs (3) and (4).
Derivative6x12 beam_deformation_derivative(const BeamConfiguration& beam);

/// The second-order terms of eq (3): ε − ε̄ as a function of the basic deformations ε̄
/// (lengths), a homogeneous quadratic.
Vector6 beam_second_order_terms(const Vector6& basic, double l0, double torsion_coupling);

// Second derivatives along a motion (issue 13: second-order rigidity of beams and rigid bodies).
// The motion is the one in which every node translates at its constant rate ẋ and turns at its
// constant angular velocity ω about the global axes: x(t) = x + t ẋ, triad(t) = exp(t [ω]×) triad.
// On a first-order mode, σᵀ d²ε/dt² does not depend on which motion with these first
// derivatives is taken (they differ by a tangent vector, on which every self-stress does no
// work), so this one is as good as any and gives closed forms.

/// d²ε1/dt² of a truss (eq 2) along that motion, `rates` = (ẋ_p, ẋ_q): (|Δẋ|² − (e·Δẋ)²)/l,
/// length/s².
double truss_elongation_second_derivative(const Eigen::Vector3d& xp, const Eigen::Vector3d& xq,
                                          const Eigen::Vector3d& rate_p, const Eigen::Vector3d& rate_q);
/// d²ε̄/dt² of eq (4) along that motion, lengths/s².
Vector6 beam_basic_second_derivative(const BeamConfiguration& beam, const NodeRates12& rates);
/// d²ε/dt² of eq (3) along that motion: (dε/dε̄) d²ε̄/dt² + 2 q(dε̄/dt), with q the second-order
/// terms (beam_second_order_terms), lengths/s².
Vector6 beam_deformation_second_derivative(const BeamConfiguration& beam, const NodeRates12& rates);
/// d²/dt² of the six relative coordinates of rigid_link_derivative along that motion: the
/// relative translation exp(−t[ω_r]×)(x_j − x_r) and the relative rotation
/// log(exp(−t[ω_r]×) exp(t[ω_j]×)), giving ω_r × (ω_r × r) − 2 ω_r × ṙ (length/s²) and
/// −ω_r × ω_j (rad/s²), with r = x_j − x_r. `rates` = (ẋ_r, ω_r, ẋ_j, ω_j).
Vector6 rigid_link_second_derivative(const Eigen::Vector3d& x_reference, const Eigen::Vector3d& x_node,
                                     const NodeRates12& rates);

/// Rates of the six relative coordinates that a rigid body keeps fixed between its reference
/// node r and another node j, linearised at the configuration: relative translation
/// ẋ_j − ẋ_r − ω_r × (x_j − x_r) (length/s) and relative rotation ω_j − ω_r (rad/s), global
/// axes. Columns (ẋ_r, ω_r, ẋ_j, ω_j).
Derivative6x12 rigid_link_derivative(const Eigen::Vector3d& x_reference, const Eigen::Vector3d& x_node);

}  // namespace kinestat::framework
