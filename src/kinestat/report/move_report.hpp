// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reports of `kinestat move` (issue 13): the path a framework mode or a network's primary motion
// is traced along, and the positions a planar mechanism reaches at given inputs, group by group. Deterministic: numbers
// rounded to ten significant digits, fixed key order.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/mode_order.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/network/finite_motion.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/network/second_order.hpp"

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

/// One primary motion of a network followed by the predictor–corrector.
struct NetworkMove {
  std::size_t mode = 0;             ///< 0-based index into result.primary_motion
  double amplitude_fraction = 0.1;  ///< arc length asked for / characteristic length
  int steps = 20;
  /// The second-order verdict without a trace (network::classify_network_motions, trace off):
  /// the order printed is `infinitesimal` when blocked, else `finite` when this trace closed and
  /// `undetermined` when it did not (or was refused).
  network::NetworkMotionVerdict second_order;
  network::NetworkTrace trace;      ///< network::trace_network_motion's result
};

/// The order of a network motion given its second-order verdict and the trace of `move`.
network::NetworkMotionOrder network_move_order(const NetworkMove& move);

/// The traced path as JSON, with the keys of framework_move_json (`kind` network, `mode`,
/// `modes` = FN, `primary`, `order`, `characteristic_length`, `amplitude_fraction`, `steps`,
/// `closed`, `failed_step`, `amplitude`, `max_residual`, `rank_drops`, `not_traced` (the reason,
/// null when traced) and `path`), each point with `step`, `parameter`, `arc_length`,
/// `residual`, `rank` and `coordinates` (magnitude name → joint coordinate: rad for rotations,
/// file length units for translations, relative to the file's configuration).
nlohmann::ordered_json network_move_json(const network::Model& model, const network::NetworkResult& result, const NetworkMove& move);
/// The same as readable text: one line per point with the joint coordinates.
std::string network_move_text(const network::Model& model, const network::NetworkResult& result, const NetworkMove& move);

/// Positions of a planar mechanism at a list of input values (one `--input` set, or a sweep).
struct PositionSweep {
  kinematics::PositionPlan plan;
  std::vector<std::vector<double>> values;           ///< per step: one value per plan.drivers
  std::vector<kinematics::PositionResult> results;   ///< per step
};

/// The positions as JSON text (indented as report::json_text prints, with its final newline):
/// `groups` (order of formation, type, method, branch) and `steps`, each with the inputs,
/// `assembled`, the failing group, `max_residual`, per-body poses and per-coupling points and
/// values; `not_assembled` lists the steps where a group could not be placed. Built step by
/// step, so a sweep too long for memory ends in std::bad_alloc, not in an abort.
std::string positions_json_text(const network::Model& model, const PositionSweep& sweep);
/// The same as readable text: the groups, then one line per step.
std::string positions_text(const network::Model& model, const PositionSweep& sweep);

}  // namespace kinestat::report
