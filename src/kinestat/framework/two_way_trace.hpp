// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A kinematic mode followed both ways from the model's configuration (issue 13, item 2): what
// the HTML report animates instead of the first-order velocities. Two runs of trace_motion,
// along +u and along −u; each keeps the configurations it reached with closure (a side that
// lost closure stops short, and says where).

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/mode_order.hpp"

namespace kinestat::framework {

/// A mode traced both ways: `forward` along +direction, `backward` along −direction. Both start
/// at the model's configuration (their first point is the same).
struct TwoWayTrace {
  FiniteTrace forward;
  FiniteTrace backward;
  /// The direction followed is the mode without its rigid motion of the whole model (the part
  /// the second-order classification traced), not the mode itself.
  bool rigid_part_removed = false;
  /// A side lost closure before kAnimationAmplitude and was traced again, shorter
  /// (animation_traces): its amplitude is the classification's.
  bool forward_retraced = false, backward_retraced = false;
  /// Largest closure residual (relative to the characteristic length) of the points reached by
  /// both (a point where the corrector lost closure is not among them).
  double max_residual() const;
};

/// Follows `direction` (a mode's rates, D̂'s units) from the configuration of `model` both
/// ways, `options.amplitude_fraction` of the characteristic length and `options.steps` steps
/// each.
TwoWayTrace trace_both_ways(const FrameworkModel& model, const FrameworkResult& analysis, const Eigen::VectorXd& direction,
                            const TraceOptions& options = {});

/// Steps per side of the traces the HTML report animates: the animation shows traced
/// configurations only (no interpolation between them), so the motion advances by at most
/// 1/kAnimationSteps of the traced arc from one drawn configuration to the next.
inline constexpr int kAnimationSteps = 48;

/// Arc length of each side of the traces the HTML report animates, as a fraction of the
/// characteristic length: five times the classification's 0.1, so that the motion is visible
/// next to the first-order animation (whose largest displacement reaches 25 % of the model's
/// size); a side that loses closure before it stops where it did.
inline constexpr double kAnimationAmplitude = 0.5;

/// The modes of `analysis` whose motion the report animates as traced: those of order `finite`
/// (a closed trace or a rigid motion of the whole model), each traced both ways over
/// kAnimationAmplitude of the characteristic length with kAnimationSteps steps per side, by the
/// rank rule of `options` (a side that loses closure before is traced again over
/// `options.trace_amplitude_fraction` with the same number of steps, and the side that reaches
/// further is kept): a rigid motion along itself, any other mode along
/// its part without rigid motions of the whole model (second_order.hpp's rigid_motions), the
/// direction the classification traced and closed. One entry per mode; empty for the other
/// modes, and for every mode when `analysis.orders` is empty (second order not computed).
std::vector<std::optional<TwoWayTrace>> animation_traces(const FrameworkModel& model, const FrameworkResult& analysis,
                                                         const AnalysisOptions& options);

}  // namespace kinestat::framework
