#pragma once
// Reports of `kinestat move` (issue 13): the path a framework mode is traced along, and the
// positions a planar mechanism reaches at given inputs, group by group. Deterministic: numbers
// rounded to ten significant digits, fixed key order.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/mode_order.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/network/model.hpp"

namespace kinestat::report {

/// One mode of a framework followed by the predictor–corrector.
struct FrameworkMove {
  std::size_t mode = 0;             ///< 0-based index into analysis.modes
  double amplitude_fraction = 0.1;  ///< arc length asked for / characteristic length
  int steps = 20;
  framework::FiniteTrace trace;     ///< framework::trace_motion's result
};

/// The traced path as JSON: the mode's second-order order, the outcome and `path`, one entry
/// per point with `parameter` (arc length / characteristic length), `arc_length` (length
/// units), `residual` (relative), `rank` and `positions` (node name → coordinates).
nlohmann::ordered_json framework_move_json(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                           const FrameworkMove& move);
/// The same as readable text: one line per point with the nodes that move.
std::string framework_move_text(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                const FrameworkMove& move);

/// Positions of a planar mechanism at a list of input values (one `--input` set, or a sweep).
struct PositionSweep {
  kinematics::PositionPlan plan;
  std::vector<std::vector<double>> values;           ///< per step: one value per plan.drivers
  std::vector<kinematics::PositionResult> results;   ///< per step
};

/// The positions as JSON: `groups` (order of formation, type, method, branch) and `steps`, each
/// with the inputs, `assembled`, the failing group, `max_residual`, per-body poses and per-coupling
/// points and values; `not_assembled` lists the steps where a group could not be placed.
nlohmann::ordered_json positions_json(const network::Model& model, const PositionSweep& sweep);
/// The same as readable text: the groups, then one line per step.
std::string positions_text(const network::Model& model, const PositionSweep& sweep);

}  // namespace kinestat::report
