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
  /// Largest closure residual (relative to the characteristic length) of the points of both.
  double max_residual() const;
};

/// Follows `direction` (a mode's rates, D̂'s units) from the configuration of `model` both
/// ways, `options.amplitude_fraction` of the characteristic length and `options.steps` steps
/// each. Bars only (as trace_motion): otherwise both traces are empty.
TwoWayTrace trace_both_ways(const FrameworkModel& model, const FrameworkResult& analysis, const Eigen::VectorXd& direction,
                            const TraceOptions& options = {});

/// Steps per side of the traces the HTML report animates: the animation shows traced
/// configurations only (no interpolation between them), so the motion advances by at most
/// 1/kAnimationSteps of the traced arc from one drawn configuration to the next.
inline constexpr int kAnimationSteps = 48;

/// The modes of `analysis` whose motion the report animates as traced: those of order `finite`
/// (a closed trace or a rigid motion of the whole model), each traced both ways along the mode
/// itself (the rates `kinestat move --mode N` follows) over `options.trace_amplitude_fraction`
/// of the characteristic length with kAnimationSteps steps per side, by the rank rule of
/// `options`. One entry per mode; empty for the other modes, and for every mode when
/// `analysis.orders` is empty (second order not computed).
std::vector<std::optional<TwoWayTrace>> animation_traces(const FrameworkModel& model, const FrameworkResult& analysis,
                                                         const AnalysisOptions& options);

}  // namespace kinestat::framework
