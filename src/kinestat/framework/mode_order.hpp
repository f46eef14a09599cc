// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Plain results of the second-order classification of kinematic modes and of finite-motion
// tracing (issue 13): is a first-order mechanism blocked at second order by a self-stress
// (Connelly & Whiteley's prestress stability, Pellegrino & Calladine's product forces), or does
// it extend to a finite motion that Newton's method can follow with closure at rounding level?

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace kinestat::framework {

/// `infinitesimal`: blocked at second order; `finite`: traced (or a rigid motion);
/// `undetermined`: passes the second-order test but was not traced (or the trace failed).
enum class MotionOrder { infinitesimal, finite, undetermined };

/// The JSON spelling: "infinitesimal", "finite", "undetermined".
const char* motion_order_name(MotionOrder order);

/// Why a mode got its order.
enum class OrderReason {
  prestress_stable,      ///< a self-stress makes the geometric stiffness positive definite on every non-rigid mode
  blocked_by_stress,     ///< this mode (not every combination) does work against a self-stress at second order
  rigid_motion,          ///< the mode is a rigid motion of the whole model
  traced,                ///< passes second order and was followed with closure at rounding level
  trace_failed,          ///< passes second order, but the corrector lost closure on the way
  no_second_order_model, ///< no second-order model of some element (not used by frameworks since beams have one)
  not_computed,          ///< modes too many or the model too large (see SecondOrderOptions)
};

/// A path followed by the predictor–corrector from the model's configuration.
struct FiniteTrace {
  double amplitude = 0.0;     ///< arc length reached, length units (translations; rotations times the characteristic length)
  double max_residual = 0.0;  ///< largest |constraint| / characteristic length over the points
  std::vector<Eigen::Index> rank_along_path;  ///< rank of D(c) at every point, the start first
  /// max |constraint| / characteristic length at every point, the start first.
  std::vector<double> residual_along_path;
  /// Arc length reached at every point (length units, chords summed as for `amplitude`), 0 first.
  std::vector<double> arc_length_along_path;
  /// Node positions (3 × nodes, global frame, length units) at every point, the start first.
  std::vector<Eigen::MatrixXd> positions;
  bool closed = false;        ///< every point reached with max_residual ≤ kTraceResidual
  std::size_t failed_step = 0;  ///< first step whose corrector failed (when !closed)
  /// Points whose rank is below the largest rank along the path: singular configurations,
  /// where branches meet or the mobility changes.
  std::vector<std::size_t> rank_drops;
};

/// The second-order verdict on one mode.
struct ModeOrder {
  MotionOrder order = MotionOrder::undetermined;
  OrderReason reason = OrderReason::not_computed;
  /// The self-stress that blocks the mode (resultants dual to the rows of D(c), unit 2-norm),
  /// when infinitesimal.
  Eigen::VectorXd blocking_stress;
  /// σᵀ ε''(u, u) of the blocking stress on the mode, relative to ‖ε''(u, u)‖ (0 < · ≤ 1), or
  /// the largest relative value over the stresses when the mode passes (then below tolerance).
  double second_order_work = 0.0;
  bool traced = false;
  FiniteTrace trace;
};

/// Prestress stability of the whole mechanism space (modulo rigid motions).
struct PrestressStability {
  bool tested = false;               ///< trusses only, at least one non-rigid mode and one self-stress
  bool stable = false;               ///< some self-stress makes the form positive definite
  Eigen::Index nonrigid_modes = 0;   ///< dimension of the mechanism space modulo rigid motions
  Eigen::Index rigid_motions = 0;    ///< rigid motions of the whole model among the mechanisms
  /// The best self-stress found (resultants dual to the rows of D(c), unit 2-norm).
  Eigen::VectorXd stress;
  /// Smallest eigenvalue of its geometric stiffness on the non-rigid modes, relative to the
  /// largest Frobenius norm of the stiffnesses (on all columns of D(c)) of the orthonormal
  /// stress basis: > kPrestressMargin means stable.
  double smallest_eigenvalue = 0.0;
  /// The search over combinations of self-stresses was exhaustive up to its grid: exact for one
  /// stress, a dense scan plus ascent for two or three, sampled plus ascent for more.
  bool exhaustive = false;
};

}  // namespace kinestat::framework
