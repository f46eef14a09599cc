// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The geometric stiffness of a prestress in the model's own units (issue 38, item 4): the
// second derivative of the work Σ_d s_d ε_d(x) of fixed stress resultants s on the deformation
// functions of seed 002 (eqs 2-4), K_G = Σ_d s_d ∂²ε_d/∂x∂x, over every nodal coordinate. For a
// truss of length L and axial force N this is N/L (I − e eᵀ) on the relative translation of its
// ends (e the unit vector from p to q): a tensioned bar stiffens transverse motion. The tangent
// stiffness of a prestressed framework is K + K_G (K = Dᵀ K_e D, the elastic part).
//
// second_order.hpp's geometric_stiffness gives the same form non-dimensionally on the columns of
// D(c) for the second-order classification; this one keeps units so that it adds to K.

#include <Eigen/Core>

#include "kinestat/framework/framework_jacobian.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::framework {

/// K_G = Σ_d s_d ∂²ε_d/∂x∂x at the model's configuration, n_x × n_x over indexing.coordinates
/// (translations in the model's length unit, rotations in rad about the global axes).
/// `resultants` holds one stress resultant per deformation of indexing.deformations, dual to it:
/// a force for a length-type deformation (the beam's l0-scaled angles included: moment / l0), a
/// moment for a rigid body's relative rotation; tension positive. Units of the entries: force
/// per length, force, or force × length, by the slots. Each element's block is exact by
/// polarisation of d²ε/dt² along motions at constant rates (deformation_functions.hpp), so the
/// matrix is symmetric.
Eigen::MatrixXd prestress_geometric_stiffness(const FrameworkModel& model, const FrameworkIndexing& indexing,
                                              const Eigen::VectorXd& resultants);

}  // namespace kinestat::framework
