// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Finite-motion tracing of a coupling network (issue 13, item 2): a predictor–corrector that
// follows a first-order motion of the network on the full nonlinear loop-closure equations,
// reporting the closure residual, the rank of the closure Jacobian at every point (a drop marks
// a branch point or a change of mobility) and the joint coordinates reached.
//
// The equations. Every magnitude i (a column of M^D: one unit motion of one coupling) gets a
// joint coordinate x_i, 0 in the model's configuration: an angle in rad for a rotation (a
// helical coupling's rotation included; the axis as written need not be unit, the angle is
// about the unit axis), a length in file units for a translation. Around every circuit (a row of
// B, walked as network/circuit_walk.hpp says) the product of exponentials of the unit twists
// ξ_i in the model's configuration must be the identity:
//     Π_k exp(sign_k · ξ_k · x_k) = I  in SE(3)
// (planar networks: rotations about z and translations in xy; spherical screw spaces:
// rotations about the origin, SO(3)). The closure Jacobian of a circuit has the column
// sign_k · Ad(Π_{j<k} exp(sign_j ξ_j x_j)) ξ_k for magnitude k: the coupling twists transported
// by the current poses, i.e. the network's M^N at the current configuration (each circuit's
// rows in the frame of the body its walk starts from, an invertible change per block).
//
// The frame and the units. All of it is evaluated in the analysis frame of the network
// (AnalysisFrame::of: origin at the centroid of the coupling points, lengths over the
// characteristic length L = the largest coordinate distance of a coupling point from that
// centroid, 1 when they coincide; spherical screw spaces: origin and L = 1 of the user frame).
// The scaled coordinates are s_i = x_i for rotations and s_i = x_i / L for translations; arc
// length is the Euclidean length of the path in s (chords summed), and the amplitude reached is
// that arc length × L (length units, as for frameworks: rotations count times L).
// The closure residual of a circuit is θ_err + |t_err| / L (θ_err the rotation angle of the
// circuit's product in rad, t_err its translation), i.e. (rotation × L + translation) / L; the
// residual of a point is the largest over the circuits.

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"

namespace kinestat::network {

/// Largest number of magnitudes (F) or closure rows (d·l) a network is traced with: every point
/// costs a dense SVD of the closure Jacobian and a few least-squares solves.
inline constexpr Eigen::Index kNetworkTraceSizeLimit = 300;

struct NetworkTraceOptions {
  /// Arc length to follow in the scaled coordinates s (see above): a fraction of L (the 0.1).
  double amplitude_fraction = 0.1;
  int steps = 20;  ///< predictor–corrector steps of equal predicted arc length
  /// The rank rule (linalg::numerical_rank): a user's relative tolerance, and the input rounding
  /// level of the model (AnalysisFrame::input_rounding). At every point the rounding level is
  /// raised to that point's closure residual: the configuration is known no better.
  linalg::RankTolerance tolerance;
};

/// Why a motion was not traced (no points then).
enum class TraceRefusal {
  none,                  ///< traced (the path may still have failed: see closed)
  unmodelled_coupling,   ///< a coupling in a circuit is point_on_plane, point_on_line or custom
  space_not_modelled,    ///< a screw space other than spatial, planar or spherical
  too_large,             ///< more than kNetworkTraceSizeLimit magnitudes or closure rows
  open_circuit,          ///< a row of B is not a closed walk (the analysis and the model disagree)
  not_a_motion,          ///< the direction is zero, of the wrong size, or not a first-order motion
};

/// The reason in words, for reports ("" for none).
const char* trace_refusal_text(TraceRefusal refusal);

/// A path followed from the model's configuration, with the keys of framework::FiniteTrace.
struct NetworkTrace {
  TraceRefusal refusal = TraceRefusal::none;
  std::vector<std::string> unmodelled_couplings;  ///< names, when refusal is unmodelled_coupling
  double characteristic_length = 1.0;  ///< L above, file units
  double amplitude = 0.0;     ///< arc length reached × L (length units)
  double max_residual = 0.0;  ///< largest point residual (relative, see above)
  std::vector<Eigen::Index> rank_along_path;  ///< rank of the closure Jacobian at every point, the start first
  std::vector<double> residual_along_path;    ///< residual of every point, the start first
  std::vector<double> arc_length_along_path;  ///< arc length reached × L at every point, 0 first
  /// Joint coordinates x at every point, the start (all 0) first: one per magnitude (column
  /// order of NetworkResult::motions), rad for rotations, file length units for translations,
  /// relative to the model's configuration.
  std::vector<Eigen::VectorXd> coordinates;
  bool closed = false;          ///< every point reached with residual ≤ kTraceResidual
  std::size_t failed_step = 0;  ///< first step whose corrector failed (when traced and !closed)
  /// Points whose rank is below the largest rank along the path: singular configurations,
  /// where branches meet or the mobility changes.
  std::vector<std::size_t> rank_drops;

  bool traced() const { return refusal == TraceRefusal::none; }
};

/// Follows `direction` (magnitude rates, one per NetworkResult::motions, in the units of the
/// motion magnitudes: a column of result.motion_magnitudes.values is one) from the
/// configuration of `model`, on which `result` (the dense analysis) was made. The predictor
/// steps along the tangent (the previous tangent projected on the null space of the closure
/// Jacobian at the current point, so the branch and its sense are kept); the Newton corrector
/// takes minimum-norm least-squares steps on the hyperplane through the predicted point normal
/// to the tangent. Not traced (refusal set, no points) in the cases TraceRefusal lists.
NetworkTrace trace_network_motion(const Model& model, const NetworkResult& result, const Eigen::VectorXd& direction,
                                  const NetworkTraceOptions& options = {});

}  // namespace kinestat::network
