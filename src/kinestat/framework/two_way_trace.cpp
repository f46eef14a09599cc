#include "kinestat/framework/two_way_trace.hpp"

#include <algorithm>

namespace kinestat::framework {

double TwoWayTrace::max_residual() const { return std::max(forward.max_residual, backward.max_residual); }

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
  if (analysis.orders.size() != analysis.modes.size() || !bars_only(model)) return traces;
  TraceOptions tracing;
  tracing.amplitude_fraction = options.trace_amplitude_fraction;
  tracing.steps = kAnimationSteps;
  tracing.tolerance = linalg::RankTolerance{options.tolerances.rank};
  for (std::size_t k = 0; k < analysis.modes.size(); ++k)
    if (analysis.orders[k].order == MotionOrder::finite) traces[k] = trace_both_ways(model, analysis, analysis.modes[k].velocities, tracing);
  return traces;
}

}  // namespace kinestat::framework
