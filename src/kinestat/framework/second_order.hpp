// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Second-order classification of the kinematic modes of a framework (issue 13, item 1).
//
// A first-order mode u (D u = 0) extends to a second-order flex (u, u″) with D u″ + ε″(u, u) = 0
// exactly when every self-stress σ (σᵀD = 0) does no work on it: σᵀ ε″(u, u) = 0 (Connelly &
// Servatius, "Higher-order rigidity", 1994). For a bar, ε″(u, u) = |Δu|²/l − (e·Δu)²/l, and on
// first-order modes the second term vanishes, so σᵀε″(u, u) = Σ (σ_e / l_e) |Δu_e|²: the stress
// matrix of Connelly, the product forces of Pellegrino & Calladine (1986). If some combination
// of the self-stresses makes that form positive definite on all modes modulo rigid motions, the
// framework is prestress stable (Connelly & Whiteley 1996) and every mode is infinitesimal.
// Beams use seed 002's eq (3) with its second-order terms and rigid bodies their relative
// coordinates (deformation_functions.hpp gives ε″ of each along a motion of its nodes).
// Modes that pass are traced (finite_motion.hpp); a closed trace makes them finite.

#include <Eigen/Core>

#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/mode_order.hpp"

namespace kinestat::framework {


/// Largest number of columns or rows of D(c) classified (each traced point costs an SVD).
inline constexpr Eigen::Index kSecondOrderSizeLimit = 300;

struct SecondOrderOptions {
  bool trace = true;     ///< trace the modes that pass second order
  TraceOptions tracing;  ///< amplitude, steps and the rank rule of the traces
};

/// The classification of all modes of `analysis` plus the prestress-stability test.
struct SecondOrderResult {
  PrestressStability prestress;
  std::vector<ModeOrder> orders;  ///< one per analysis.modes
};

/// Classifies every mode of `analysis` (made on `model`, dense path with vectors): bars, beams
/// and rigid bodies. Above kSecondOrderSizeLimit, reason not_computed.
SecondOrderResult classify_modes(const FrameworkModel& model, const FrameworkResult& analysis,
                                 const SecondOrderOptions& options = {});

/// The geometric stiffness (stress matrix) of the resultants `stress` (dual to the rows of D(c),
/// in D̂'s units) on the columns of D(c): the n × n matrix of Σ_r σ_r ε̂_r″, non-dimensional, with
/// ε̂_r″ the second derivative along motions at constant rates (deformation_functions.hpp).
Eigen::MatrixXd geometric_stiffness(const FrameworkModel& model, const FrameworkResult& analysis,
                                    const Eigen::VectorXd& stress);

/// An orthonormal basis (columns of D(c), D̂'s units) of the rigid motions of the whole model
/// that leave every fixed and independent coordinate at rest.
Eigen::MatrixXd rigid_motions(const FrameworkModel& model, const FrameworkResult& analysis);

}  // namespace kinestat::framework
