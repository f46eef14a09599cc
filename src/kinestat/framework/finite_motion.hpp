// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Finite-motion tracing of a framework (issue 13, item 2): a predictor–corrector that follows
// a direction of the mechanism space on the full nonlinear constraints (every fixed and
// independent deformation held at its value in the model), reporting the closure residual, the
// rank of D(c) at every point and the configurations reached.

#include <Eigen/Core>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/mode_order.hpp"
#include "kinestat/stop_request.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::framework {

struct TraceOptions {
  /// Arc length to follow, as a fraction of the characteristic length (the 0.1).
  double amplitude_fraction = 0.1;
  int steps = 20;
  linalg::RankTolerance tolerance;  ///< the rank rule of the analysis
  StopRequest stop;                 ///< the caller's request to stop, polled every step (throws Stopped)
};

/// Current length of a truss element of `model` (length units).
double truss_length(const FrameworkModel& model, const Element& element);

/// Follows `direction` (rates of the columns of D(c) in D̂'s units, the units of a
/// KinematicMode) from the configuration of `model`, on which `analysis` was made. The
/// constraints are the held deformations at their analysed values: bar lengths, beams' eq (3)
/// with its second-order terms between the turned node triads, rigid bodies' relative
/// coordinates. Node triads turn by the rotation vectors of the steps (rotations compose).
FiniteTrace trace_motion(const FrameworkModel& model, const FrameworkResult& analysis,
                         const Eigen::VectorXd& direction, const TraceOptions& options = {});

}  // namespace kinestat::framework
