// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/move_pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "kinestat/design/sweep_grid.hpp"
#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/finite_motion.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::pipeline {

report::FrameworkMove trace_framework_mode(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                           const std::string& path, const TraceRequest& request) {
  if (!analysis.vectors || analysis.method != framework::RankMethod::dense_svd)
    throw io::InputError({path, 1, 1}, "the framework is too large for the dense analysis that tracing needs");
  const auto modes = static_cast<long long>(analysis.modes.size());
  if (modes == 0) throw io::InputError({path, 1, 1}, "the framework has no kinematic mode: it cannot move (--mode has nothing to follow)");
  if (request.mode < 1 || request.mode > modes)
    throw io::InputError({path, 1, 1}, fmt::format("--mode {}: the framework has {} kinematic mode{}, numbered 1 to {}", request.mode,
                                                   modes, modes == 1 ? "" : "s", modes));
  report::FrameworkMove move;
  move.mode = static_cast<std::size_t>(request.mode - 1);
  move.amplitude_fraction = request.amplitude;
  move.steps = static_cast<int>(request.steps);
  framework::TraceOptions trace;
  trace.amplitude_fraction = request.amplitude;
  trace.steps = move.steps;
  trace.tolerance = linalg::RankTolerance{Tolerances::with_rank(request.tolerance).rank};
  trace.stop = request.stop;
  move.trace = framework::trace_motion(model, analysis, analysis.modes[move.mode].velocities, trace);
  return move;
}

FrameworkMotion trace_framework(const framework::FrameworkModel& model, const std::string& path, const TraceRequest& request) {
  framework::AnalysisOptions options;
  options.tolerances = Tolerances::with_rank(request.tolerance);
  options.stop = request.stop;
  FrameworkMotion motion;
  // The same basis of modes as `kinestat analyze` reports, so mode N means the same mode.
  motion.analysis = framework::analyse_framework_as_reported(model, options);
  motion.move = trace_framework_mode(model, motion.analysis, path, request);
  return motion;
}

NetworkMotion trace_network(const io::LoadedNetwork& loaded, const std::string& path, const TraceRequest& request) {
  if (static_cast<int>(loaded.model.couplings.size()) > network::kDenseNetworkLimit)
    throw io::InputError({path, 1, 1}, fmt::format("the network has more than {} couplings: too large for the dense analysis that tracing "
                                                   "needs",
                                                   network::kDenseNetworkLimit));
  network::AnalysisOptions options;
  options.tolerances = Tolerances::with_rank(request.tolerance);
  NetworkMotion motion;
  try {
    motion.result = network::analyse_network(loaded.model, options);
  } catch (const network::ModelError& error) {
    throw io::locate(error, loaded, path);
  }
  const network::NetworkResult& result = motion.result;
  const auto modes = static_cast<long long>(result.primary_motion.size());
  if (modes == 0) throw io::InputError({path, 1, 1}, "the network has no motion (FN = 0): it cannot move (--mode has nothing to follow)");
  if (request.mode < 1 || request.mode > modes)
    throw io::InputError({path, 1, 1}, fmt::format("--mode {}: the network has {} primary motion{} (FN), numbered 1 to {}", request.mode,
                                                   modes, modes == 1 ? "" : "s", modes));
  report::NetworkMove& move = motion.move;
  move.mode = static_cast<std::size_t>(request.mode - 1);
  move.amplitude_fraction = request.amplitude;
  move.steps = static_cast<int>(request.steps);
  network::NetworkSecondOrderOptions second_order_options;
  second_order_options.trace = false;
  const network::NetworkSecondOrder second_order = network::classify_network_motions(loaded.model, result, second_order_options);
  if (move.mode < second_order.motions.size()) move.second_order = second_order.motions[move.mode];
  network::NetworkTraceOptions trace;
  trace.amplitude_fraction = request.amplitude;
  trace.steps = move.steps;
  trace.tolerance = network::rank_rule_of(loaded.model, options.tolerances.rank);
  move.trace = network::trace_network_motion(loaded.model, result, result.motion_magnitudes.values.col(static_cast<Eigen::Index>(move.mode)),
                                             trace);
  return motion;
}

NetworkPositions solve_positions(io::LoadedNetwork loaded, const std::string& path, const PositionRequest& request) {
  const std::optional<SweptInput>& sweep = request.sweep;
  std::vector<std::string> names;
  for (const auto& input : request.inputs) names.push_back(input.first);
  if (sweep) names.push_back(sweep->name);
  if (names.empty())
    throw io::InputError({path, 1, 1}, "a mechanism is moved by its inputs: give --input NAME=VALUE (or --sweep NAME=FROM:TO:STEPS) for "
                                       "each driving coupling" + request.no_inputs_hint);
  const auto& couplings = loaded.model.couplings;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::none_of(couplings.begin(), couplings.end(), [&](const auto& c) { return c.name == names[i]; }))
      throw io::InputError({path, 1, 1}, fmt::format("the input '{}' names no coupling of this model", names[i]));
    for (std::size_t k = 0; k < i; ++k)
      if (names[k] == names[i]) throw io::InputError({path, 1, 1}, fmt::format("the input '{}' is given twice", names[i]));
  }
  // The inputs given are the drivers (they replace the file's `inputs:`).
  loaded.model.inputs = names;
  kinematics::PositionPlan plan;
  try {
    const structure::StructureModel structure = io::structure_of_network(loaded, path);
    plan = kinematics::plan_positions(loaded.model, structure, structure::analyse_structure(structure));
  } catch (const kinematics::PositionModelError& error) {
    SourceLocation where{path, 1, 1};
    const auto it = loaded.item_locations.find("couplings");
    if (error.coupling() >= 0 && it != loaded.item_locations.end() && static_cast<std::size_t>(error.coupling()) < it->second.size())
      where = it->second[static_cast<std::size_t>(error.coupling())];
    throw io::InputError(where, error.what());
  }
  NetworkPositions positions;
  report::PositionSweep& result = positions.sweep;
  const std::size_t count = sweep ? static_cast<std::size_t>(sweep->steps) + 1 : 1;
  std::vector<kinematics::Pose> start;
  for (std::size_t s = 0; s < count; ++s) {
    std::vector<double> values;
    for (const auto& input : request.inputs) values.push_back(input.second);
    if (sweep) values.push_back(design::range_value(sweep->from, sweep->to, static_cast<long long>(s), sweep->steps));
    kinematics::PositionResult r = kinematics::solve_positions(loaded.model, plan, values, start);
    if (r.assembled) start = r.poses;  // Newton groups continue from the last configuration reached
    result.values.push_back(std::move(values));
    result.results.push_back(std::move(r));
  }
  result.plan = std::move(plan);
  positions.model = std::move(loaded.model);
  return positions;
}

ModelMotion move_model(const io::ModelFile& file, const MoveRequest& request) {
  ModelMotion motion;
  if (file.framework) {
    if (!request.trace)
      throw io::InputError({file.path, 1, 1},
                           "a framework moves along one of its kinematic modes: give --mode N (modes as 'kinestat analyze' numbers them)");
    motion.framework = trace_framework(*file.framework, file.path, *request.trace);
  } else if (file.network) {
    if (request.trace) motion.network = trace_network(*file.network, file.path, *request.trace);
    else motion.positions = solve_positions(*file.network, file.path, request.positions);
  } else {
    throw io::InputError({file.path, 1, 1}, "a model of kind 'structure' has no geometry to move; write the mechanism as a network "
                                            "model (kind: network) with the points and axes of its couplings");
  }
  return motion;
}

std::string move_json_text(const io::ModelFile& file, const ModelMotion& motion) {
  if (motion.framework) return report::json_text(report::framework_move_json(*file.framework, motion.framework->analysis, motion.framework->move));
  if (motion.network) return report::json_text(report::network_move_json(file.network->model, motion.network->result, motion.network->move));
  return report::positions_json_text(motion.positions->model, motion.positions->sweep);
}

std::string move_text(const io::ModelFile& file, const ModelMotion& motion) {
  if (motion.framework) return report::framework_move_text(*file.framework, motion.framework->analysis, motion.framework->move);
  if (motion.network) return report::network_move_text(file.network->model, motion.network->result, motion.network->move);
  return report::positions_text(motion.positions->model, motion.positions->sweep);
}

}  // namespace kinestat::pipeline
