// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Second-order classification of the motions of a coupling network (issue 13, item 1).
//
// Around each circuit the couplings' relative motions compose to the identity. With the motion
// of coupling k written as the product of exponentials of its unit twists (its own serial chain,
// the `from` side first), the closure to second order in a path θ(t) = tθ′ + ½t²θ″ is (Baker–
// Campbell–Hausdorff)
//     Σ_k S_k θ″_k + Σ_{j<k} [S_j θ′_j, S_k θ′_k] = 0          (per circuit, in circuit order)
// where [·,·] is the Lie bracket of twists: [(ω₁, v₁), (ω₂, v₂)] = (ω₁ × ω₂, ω₁ × v₂ − ω₂ × v₁).
// Stacked over the circuits, a first-order motion θ′ (M^N θ′ = 0) extends to second order exactly
// when the bracket vector b(θ′) lies in the range of M^N, i.e. when every left null vector w of
// M^N — one per self-stress, CN of them — gives wᵀ b(θ′) = 0. Each self-stress is thus a quadratic
// form on the motions, the network's analogue of a framework's stress matrix (Connelly &
// Whiteley's prestress stability), and the second-order mobility condition of the screw-theory
// literature on higher-order loop closure.
//
// The result does not depend on where each circuit starts (the bracket sum is invariant under a
// cyclic shift once first-order closure holds), on the spanning tree, the frame or the unit.
//
// Motions that pass (or that nothing can block, CN = 0) are traced on the full loop-closure
// equations (finite_motion.hpp); a trace that closes at every point makes them `finite`.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "kinestat/network/finite_motion.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"

namespace kinestat::network {

/// `infinitesimal`: blocked at second order by a self-stress; `finite`: passes second order and
/// was traced with closure at every point; `undetermined`: passes second order but was not
/// traced or the trace failed, or no second-order model (see reason).
enum class NetworkMotionOrder { infinitesimal, finite, undetermined };

/// The JSON spelling, as for frameworks: "infinitesimal", "finite" or "undetermined".
const char* network_motion_order_name(NetworkMotionOrder order);

/// Why a motion got its order.
enum class NetworkOrderReason {
  blocked_by_stress,      ///< some self-stress does work on it at second order
  prestress_stable,       ///< a combination of the self-stresses blocks every motion at once
  passes_second_order,    ///< no self-stress does work on it: a second-order extension exists (not traced)
  no_self_stress,         ///< CN = 0: nothing can block it at second order (not traced)
  traced,                 ///< passes second order (or CN = 0) and was followed with closure at every point
  trace_failed,           ///< passes second order (or CN = 0), but the corrector lost closure on the way
  no_second_order_model,  ///< a coupling whose finite motion is not the product of its unit twists
};

/// The JSON spelling of a reason, e.g. "blocked_by_stress".
const char* network_order_reason_name(NetworkOrderReason reason);

/// The second-order verdict on one primary motion (one column of the motion magnitudes).
struct NetworkMotionVerdict {
  NetworkMotionOrder order = NetworkMotionOrder::undetermined;
  NetworkOrderReason reason = NetworkOrderReason::no_second_order_model;
  /// |wᵀ b(θ′)| of the blocking combination of self-stresses, relative to the size of the
  /// bracket terms Σ_{j<k} |X_j| |X_k| (lengths over the model's extent): 0 ≤ · ≤ 1, above
  /// kSecondOrderWorkZero when blocked.
  double second_order_work = 0.0;
  /// The closure defect the blocking self-stress sees, when blocked: a circuit wrench per circuit
  /// (d coordinates each, user frame, ray formation; unit 2-norm over all d·l).
  Eigen::VectorXd blocking_stress;
  bool traced = false;  ///< a trace was made (reason traced or trace_failed)
  NetworkTrace trace;   ///< the path, when traced
};

/// The classification of every primary motion, plus prestress stability of the whole motion space.
struct NetworkSecondOrder {
  std::vector<NetworkMotionVerdict> motions;  ///< one per primary motion (FN)
  bool prestress_tested = false;  ///< at least one motion and one self-stress, every coupling modelled
  bool prestress_stable = false;  ///< a combination of self-stresses blocks every motion at once
  /// λ_min of the best combination (unit vector of self-stresses) on the orthonormalised motion
  /// space, relative to the largest bracket size Σ_{j<k} |X_j| |X_k| of a unit motion of that
  /// basis: > kPrestressMargin means stable.
  double smallest_eigenvalue = 0.0;
  /// Couplings (names) in a circuit whose finite motion is not modelled (higher pairs, custom).
  std::vector<std::string> unmodelled_couplings;
};

struct NetworkSecondOrderOptions {
  bool trace = true;             ///< trace the motions that pass second order (or that nothing can block)
  NetworkTraceOptions tracing;   ///< amplitude, steps and the rank rule of the traces
};

/// Classifies the FN primary motions of `result`, the (dense) analysis of `model`, at second
/// order. Couplings of type point_on_plane, point_on_line and custom have no second-order model
/// here (their finite motion depends on curvatures the model does not give); a network with one
/// of them in a circuit gets `undetermined`, reason no_second_order_model. Screw spaces other
/// than spatial, planar and spherical, and networks of more than 1,200 magnitudes or closure
/// rows, likewise. With options.trace, every motion that passes (or CN = 0) is traced from the
/// model's configuration along its column of the motion magnitudes (trace_network_motion):
/// `finite` (traced) when the trace closes, `undetermined` (trace_failed) when it does not; a
/// motion the tracer refuses (TraceRefusal, e.g. above kNetworkTraceSizeLimit) keeps its
/// second-order reason.
NetworkSecondOrder classify_network_motions(const Model& model, const NetworkResult& result,
                                            const NetworkSecondOrderOptions& options = {});

}  // namespace kinestat::network
