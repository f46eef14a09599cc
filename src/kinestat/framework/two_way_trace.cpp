// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/two_way_trace.hpp"

#include <algorithm>

#include "kinestat/framework/second_order.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

double TwoWayTrace::max_residual() const {
  double largest = 0.0;
  for (double r : forward.residual_along_path) largest = std::max(largest, r);
  for (double r : backward.residual_along_path) largest = std::max(largest, r);
  return largest;
}

TwoWayTrace trace_both_ways(const FrameworkModel& model, const FrameworkResult& analysis, const Eigen::VectorXd& direction,
                            const TraceOptions& options) {
  TwoWayTrace both;
  both.forward = trace_motion(model, analysis, direction, options);
  both.backward = trace_motion(model, analysis, -direction, options);
  return both;
}

std::vector<std::optional<TwoWayTrace>> animation_traces(const FrameworkModel& model, const FrameworkResult& analysis,
                                                         const AnalysisOptions& options) {
  std::vector<std::optional<TwoWayTrace>> traces(analysis.modes.size());
  if (analysis.orders.size() != analysis.modes.size()) return traces;
  TraceOptions tracing;
  tracing.amplitude_fraction = kAnimationAmplitude;
  tracing.steps = kAnimationSteps;
  tracing.tolerance = linalg::RankTolerance{options.tolerances.rank};
  // A side that loses closure on the long trace is traced again over the classification's
  // amplitude (finer steps); the side that reaches further is kept.
  TraceOptions narrow = tracing;
  narrow.amplitude_fraction = std::min(options.trace_amplitude_fraction, kAnimationAmplitude);
  const auto both_ways = [&](const Eigen::VectorXd& direction) {
    TwoWayTrace wide = trace_both_ways(model, analysis, direction, tracing);
    if (wide.forward.closed && wide.backward.closed) return wide;
    const TwoWayTrace fine = trace_both_ways(model, analysis, direction, narrow);
    if (fine.forward.amplitude > wide.forward.amplitude) wide.forward = fine.forward, wide.forward_retraced = true;
    if (fine.backward.amplitude > wide.backward.amplitude) wide.backward = fine.backward, wide.backward_retraced = true;
    return wide;
  };
  const Eigen::MatrixXd rigid = rigid_motions(model, analysis);
  for (std::size_t k = 0; k < analysis.modes.size(); ++k) {
    if (analysis.orders[k].order != MotionOrder::finite) continue;
    const Eigen::VectorXd& u = analysis.modes[k].velocities;
    if (analysis.orders[k].reason == OrderReason::rigid_motion || rigid.cols() == 0) {
      traces[k] = both_ways(u);
      continue;
    }
    // As classify_modes: the rigid part taken out; a mixture of a flex and a rigid motion is
    // harder to follow with the corrector than the flex alone.
    const Eigen::VectorXd own = u - rigid * (rigid.transpose() * u);
    traces[k] = both_ways(own);
    traces[k]->rigid_part_removed = (u - own).norm() > kRigidMotionZero * u.norm();
  }
  return traces;
}

}  // namespace kinestat::framework
