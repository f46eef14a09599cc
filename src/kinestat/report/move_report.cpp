// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/move_report.hpp"
#include "kinestat/report/json_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::report {

namespace {

// Residuals keep tiny values: three significant digits.
double three_significant(double value) {
  if (!std::isfinite(value) || value == 0.0) return value;
  return std::strtod(fmt::format("{:.3g}", value).c_str(), nullptr);
}
std::string printed_number(double value) { return fmt::format("{:.6g}", rounded_for_report(value)); }

// Positions are printed relative to the model's size: entries below kPrintedZero × length are 0.
double coordinate(double value, double length) { return std::abs(value) < kPrintedZero * length ? 0.0 : rounded_for_report(value); }

}  // namespace

// ---- Framework path --------------------------------------------------------------------------

namespace {

// Nodes whose position changes along the path by more than kCoincident × the length.
std::vector<std::size_t> moving_nodes(const framework::FrameworkModel& model, const framework::FiniteTrace& trace, double length) {
  std::vector<std::size_t> moving;
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    double largest = 0.0;
    for (const auto& p : trace.positions) largest = std::max(largest, (p.col(static_cast<Eigen::Index>(k)) - trace.positions.front().col(static_cast<Eigen::Index>(k))).norm());
    if (largest > kCoincident * length) moving.push_back(k);
  }
  return moving;
}

const framework::ModeOrder* order_of(const framework::FrameworkResult& analysis, std::size_t mode) {
  return mode < analysis.orders.size() ? &analysis.orders[mode] : nullptr;
}

// The outcome line of a traced path, framework or network; `followed` names what was followed.
std::string path_outcome_text(bool closed, double amplitude, double length, double max_residual, std::size_t failed_step, int steps,
                              const char* followed) {
  if (closed)
    return fmt::format("traced to arc length {} ({} of the characteristic length {}) with closure residual at most {} (relative)",
                       printed_number(amplitude), printed_number(amplitude / length), printed_number(length), fmt::format("{:.3g}", three_significant(max_residual)));
  return fmt::format("the corrector lost closure at step {} of {} (residual {:.3g}, relative): no finite motion along this {} "
                     "beyond arc length {}",
                     failed_step, steps, three_significant(max_residual), followed, printed_number(amplitude));
}

std::string outcome_text(const FrameworkMove& move, double length) {
  const auto& t = move.trace;
  if (t.positions.empty()) return "not traced";
  return path_outcome_text(t.closed, t.amplitude, length, t.max_residual, t.failed_step, move.steps, "mode");
}

// The keys every traced path carries, framework or network: the outcome, then one point per
// configuration with its step, arc length, residual and rank (`failed` null when closed or not
// traced). Each point is returned for the caller to add where it moved.
struct PathSummary {
  bool closed = false;
  std::optional<std::size_t> failed_step;
  double amplitude = 0.0, max_residual = 0.0, length = 1.0;
  const std::vector<std::size_t>* rank_drops = nullptr;
  const std::vector<double>* arcs = nullptr;
  const std::vector<double>* residuals = nullptr;
  const std::vector<Eigen::Index>* ranks = nullptr;
};

void add_path_summary(nlohmann::ordered_json& j, const PathSummary& s) {
  j["closed"] = s.closed;
  if (s.failed_step) j["failed_step"] = *s.failed_step;
  else j["failed_step"] = nullptr;
  j["amplitude"] = rounded_for_report(s.amplitude);
  j["max_residual"] = three_significant(s.max_residual);
  j["rank_drops"] = *s.rank_drops;
  j["path"] = nlohmann::ordered_json::array();
}

nlohmann::ordered_json path_point(const PathSummary& s, std::size_t k) {
  nlohmann::ordered_json point;
  const double arc = k < s.arcs->size() ? (*s.arcs)[k] : 0.0;
  point["step"] = k;
  point["parameter"] = rounded_for_report(arc / s.length);
  point["arc_length"] = rounded_for_report(arc);
  point["residual"] = three_significant(k < s.residuals->size() ? (*s.residuals)[k] : 0.0);
  point["rank"] = k < s.ranks->size() ? (*s.ranks)[k] : 0;
  return point;
}

}  // namespace

nlohmann::ordered_json framework_move_json(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                           const FrameworkMove& move) {
  nlohmann::ordered_json j;
  j["kind"] = "framework";
  j["command"] = "move";
  if (!model.name.empty()) j["name"] = model.name;
  j["mode"] = move.mode + 1;
  j["modes"] = analysis.modes.size();
  if (const auto* o = order_of(analysis, move.mode)) {
    j["order"] = framework::motion_order_name(o->order);
  } else {
    j["order"] = nullptr;
  }
  j["characteristic_length"] = rounded_for_report(analysis.length);
  j["amplitude_fraction"] = rounded_for_report(move.amplitude_fraction);
  j["steps"] = move.steps;
  const auto& t = move.trace;
  const PathSummary summary{t.closed, t.closed ? std::nullopt : std::optional<std::size_t>(t.failed_step), t.amplitude,
                            t.max_residual, analysis.length, &t.rank_drops, &t.arc_length_along_path,
                            &t.residual_along_path, &t.rank_along_path};
  add_path_summary(j, summary);
  const int dimension = model.dimension == 2 ? 2 : 3;
  for (std::size_t k = 0; k < t.positions.size(); ++k) {
    nlohmann::ordered_json point = path_point(summary, k);
    nlohmann::ordered_json positions;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
      nlohmann::ordered_json xyz = nlohmann::ordered_json::array();
      for (int c = 0; c < dimension; ++c) xyz.push_back(coordinate(t.positions[k](c, static_cast<Eigen::Index>(n)), analysis.length));
      positions[model.nodes[n].name] = std::move(xyz);
    }
    point["positions"] = std::move(positions);
    j["path"].push_back(std::move(point));
  }
  add_versions(j);
  return j;
}

std::string framework_move_text(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                                const FrameworkMove& move) {
  std::string out = fmt::format("Finite motion of {}, mode {} of {}\n", model.name.empty() ? "the framework" : model.name, move.mode + 1,
                                analysis.modes.size());
  if (const auto* o = order_of(analysis, move.mode)) {
    out += fmt::format("  order: {}", framework::motion_order_name(o->order));
    if (o->order == framework::MotionOrder::infinitesimal)
      out += " (a self-stress blocks it at second order: the mode is a first-order motion only)";
    out += "\n";
  }
  out += "  " + outcome_text(move, analysis.length) + "\n";
  const auto& t = move.trace;
  if (!t.rank_drops.empty()) {
    out += "  the rank of D(c) drops at step";
    for (std::size_t k : t.rank_drops) out += fmt::format(" {}", k);
    out += " (a singular configuration: branches may meet there)\n";
  } else if (t.positions.size() > 1) {  // one point is no path
    out += "  the rank of D(c) stays constant along the path\n";
  }
  const std::vector<std::size_t> moving = moving_nodes(model, t, analysis.length);
  const int dimension = model.dimension == 2 ? 2 : 3;
  out += "\n  step  parameter   residual   rank  positions of the nodes that move\n";
  for (std::size_t k = 0; k < t.positions.size(); ++k) {
    const double arc = k < t.arc_length_along_path.size() ? t.arc_length_along_path[k] : 0.0;
    out += fmt::format("  {:>4}  {:<10}  {:<9}  {:>4} ", k, printed_number(arc / analysis.length),
                       fmt::format("{:.3g}", three_significant(k < t.residual_along_path.size() ? t.residual_along_path[k] : 0.0)),
                       k < t.rank_along_path.size() ? t.rank_along_path[k] : 0);
    for (std::size_t n : moving) {
      out += fmt::format(" {} (", model.nodes[n].name);
      for (int c = 0; c < dimension; ++c)
        out += (c ? ", " : "") + printed_number(coordinate(t.positions[k](c, static_cast<Eigen::Index>(n)), analysis.length));
      out += ")";
    }
    out += "\n";
  }
  return out;
}

// ---- Network path ----------------------------------------------------------------------------

namespace {

std::string network_outcome_text(const NetworkMove& move) {
  const auto& t = move.trace;
  if (!t.traced()) return fmt::format("not traced: {}", network::trace_refusal_text(t.refusal));
  return path_outcome_text(t.closed, t.amplitude, t.characteristic_length, t.max_residual, t.failed_step, move.steps, "motion");
}

// The name of primary motion `mode` (its magnitude's name).
std::string primary_name(const network::NetworkResult& result, std::size_t mode) {
  if (mode >= result.primary_motion.size()) return {};
  const auto index = static_cast<std::size_t>(result.primary_motion[mode]);
  return index < result.motions.size() ? result.motions[index].name : std::string{};
}

// Joint coordinates: rad or file length; below kPrintedZero (× L for lengths) printed as 0.
double joint_coordinate(const network::NetworkResult& result, const network::NetworkTrace& t, std::size_t point, std::size_t i) {
  const double value = t.coordinates[point](static_cast<Eigen::Index>(i));
  const bool translation = result.motions[i].unit_screw.kind == screw::UnitScrewKind::translation;
  return coordinate(value, translation ? t.characteristic_length : 1.0);
}

}  // namespace

network::NetworkMotionOrder network_move_order(const NetworkMove& move) {
  if (move.second_order.order == network::NetworkMotionOrder::infinitesimal) return network::NetworkMotionOrder::infinitesimal;
  if (move.second_order.reason == network::NetworkOrderReason::no_second_order_model) return network::NetworkMotionOrder::undetermined;
  return move.trace.traced() && move.trace.closed ? network::NetworkMotionOrder::finite : network::NetworkMotionOrder::undetermined;
}

nlohmann::ordered_json network_move_json(const network::Model& model, const network::NetworkResult& result, const NetworkMove& move) {
  nlohmann::ordered_json j;
  j["kind"] = "network";
  j["command"] = "move";
  if (!model.name.empty()) j["name"] = model.name;
  j["mode"] = move.mode + 1;
  j["modes"] = result.primary_motion.size();
  j["primary"] = primary_name(result, move.mode);
  j["order"] = network::network_motion_order_name(network_move_order(move));
  const auto& t = move.trace;
  j["characteristic_length"] = rounded_for_report(t.characteristic_length);
  j["amplitude_fraction"] = rounded_for_report(move.amplitude_fraction);
  j["steps"] = move.steps;
  if (t.traced()) j["not_traced"] = nullptr;
  else j["not_traced"] = network::trace_refusal_text(t.refusal);
  const PathSummary summary{t.closed,
                            t.closed || !t.traced() ? std::nullopt : std::optional<std::size_t>(t.failed_step),
                            t.amplitude, t.max_residual, t.characteristic_length, &t.rank_drops,
                            &t.arc_length_along_path, &t.residual_along_path, &t.rank_along_path};
  add_path_summary(j, summary);
  for (std::size_t k = 0; k < t.coordinates.size(); ++k) {
    nlohmann::ordered_json point = path_point(summary, k);
    nlohmann::ordered_json coordinates;
    for (std::size_t i = 0; i < result.motions.size(); ++i) coordinates[result.motions[i].name] = joint_coordinate(result, t, k, i);
    point["coordinates"] = std::move(coordinates);
    j["path"].push_back(std::move(point));
  }
  add_versions(j);
  return j;
}

std::string network_move_text(const network::Model& model, const network::NetworkResult& result, const NetworkMove& move) {
  std::string out = fmt::format("Finite motion of {}, primary motion {} of {} ({})\n", model.name.empty() ? "the network" : io::printable_text(model.name),
                                move.mode + 1, result.primary_motion.size(), io::printable_text(primary_name(result, move.mode)));
  out += fmt::format("  order: {}", network::network_motion_order_name(network_move_order(move)));
  if (move.second_order.order == network::NetworkMotionOrder::infinitesimal)
    out += move.trace.closed ? " (a self-stress blocks this direction at second order; the closed path below leaves the start along "
                               "another direction: the start is a branch point)"
                             : " (a self-stress blocks it at second order: the motion is a first-order motion only)";
  out += "\n";
  out += "  " + network_outcome_text(move) + "\n";
  const auto& t = move.trace;
  if (!t.rank_drops.empty()) {
    out += "  the rank of the closure Jacobian drops at step";
    for (std::size_t k : t.rank_drops) out += fmt::format(" {}", k);
    out += " (a singular configuration: branches may meet there)\n";
  } else if (t.coordinates.size() > 1) {
    out += "  the rank of the closure Jacobian stays constant along the path\n";
  }
  if (t.coordinates.empty()) return out;
  // Joint coordinates that change along the path (rad; lengths in file units).
  std::vector<std::size_t> moving;
  for (std::size_t i = 0; i < result.motions.size(); ++i) {
    double largest = 0.0;
    for (std::size_t k = 0; k < t.coordinates.size(); ++k) largest = std::max(largest, std::abs(joint_coordinate(result, t, k, i)));
    if (largest > 0.0) moving.push_back(i);
  }
  out += "\n  step  parameter   residual   rank  joint coordinates that change (rad; translations in length units)\n";
  for (std::size_t k = 0; k < t.coordinates.size(); ++k) {
    const double arc = k < t.arc_length_along_path.size() ? t.arc_length_along_path[k] : 0.0;
    out += fmt::format("  {:>4}  {:<10}  {:<9}  {:>4} ", k, printed_number(arc / t.characteristic_length),
                       fmt::format("{:.3g}", three_significant(k < t.residual_along_path.size() ? t.residual_along_path[k] : 0.0)),
                       k < t.rank_along_path.size() ? t.rank_along_path[k] : 0);
    for (std::size_t i : moving) out += fmt::format(" {} {}", io::printable_text(result.motions[i].name), printed_number(joint_coordinate(result, t, k, i)));
    out += "\n";
  }
  return out;
}

// ---- Positions of a planar mechanism ---------------------------------------------------------

namespace {

std::vector<std::string> names_of(const network::Model& model, const std::vector<int>& indices, bool bodies) {
  std::vector<std::string> names;
  for (int i : indices) names.push_back(bodies ? model.bodies[static_cast<std::size_t>(i)] : model.couplings[static_cast<std::size_t>(i)].name);
  return names;
}

// Bodies placed at a step: the frame and the bodies of assembled (or singular) groups.
std::vector<bool> placed_bodies(const network::Model& model, const PositionSweep& sweep, const kinematics::PositionResult& r) {
  std::vector<bool> placed(model.bodies.size(), false);
  placed[static_cast<std::size_t>(sweep.plan.frame)] = true;
  for (std::size_t g = 0; g < r.groups.size(); ++g) {
    const auto s = r.groups[g].status;
    if (s == kinematics::AssemblyStatus::assembled || s == kinematics::AssemblyStatus::singular)
      for (int b : sweep.plan.groups[g].bodies) placed[static_cast<std::size_t>(b)] = true;
  }
  return placed;
}

std::string group_label(const network::Model& model, const kinematics::GroupPlan& g) {
  return fmt::format("group {} {{{}}} ({})", g.number, fmt::join(names_of(model, g.bodies, true), ", "), g.type);
}

std::string inputs_text(const network::Model& model, const PositionSweep& sweep, std::size_t step) {
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < sweep.plan.drivers.size(); ++i)
    parts.push_back(fmt::format("{} = {}", model.couplings[static_cast<std::size_t>(sweep.plan.drivers[i])].name, printed_number(sweep.values[step][i])));
  return fmt::format("{}", fmt::join(parts, ", "));
}

}  // namespace

namespace {

// One step of positions_json_text as JSON; a step whose group could not be placed also adds
// its entry to `not_assembled`.
nlohmann::ordered_json position_step_json(const network::Model& model, const PositionSweep& sweep, std::size_t s,
                                          std::vector<nlohmann::ordered_json>& not_assembled) {
  const double length = sweep.plan.length;
  const kinematics::PositionResult& r = sweep.results[s];
  nlohmann::ordered_json step;
  nlohmann::ordered_json inputs;
  for (std::size_t i = 0; i < sweep.plan.drivers.size(); ++i)
    inputs[model.couplings[static_cast<std::size_t>(sweep.plan.drivers[i])].name] = rounded_for_report(sweep.values[s][i]);
  step["inputs"] = inputs;
  step["assembled"] = r.assembled;
  if (r.failed_group) {
    const auto& g = sweep.plan.groups[*r.failed_group];
    step["failed_group"] = g.number;
    step["reason"] = r.groups[*r.failed_group].reason;
    nlohmann::ordered_json failure;
    failure["step"] = s;
    failure["inputs"] = inputs;
    failure["group"] = g.number;
    failure["bodies"] = names_of(model, g.bodies, true);
    failure["reason"] = r.groups[*r.failed_group].reason;
    not_assembled.push_back(std::move(failure));
  } else {
    step["failed_group"] = nullptr;
  }
  if (r.assembled) step["max_residual"] = three_significant(r.max_residual);
  else step["max_residual"] = nullptr;
  step["groups"] = nlohmann::ordered_json::array();
  for (std::size_t g = 0; g < r.groups.size(); ++g) {
    nlohmann::ordered_json group;
    group["number"] = sweep.plan.groups[g].number;
    group["status"] = kinematics::assembly_status_name(r.groups[g].status);
    if (sweep.plan.groups[g].method == kinematics::GroupMethod::newton) {
      group["iterations"] = r.groups[g].iterations;
      group["residual"] = three_significant(r.groups[g].discriminant);
    } else if (sweep.plan.groups[g].method == kinematics::GroupMethod::closed_form) {
      group["discriminant"] = three_significant(r.groups[g].discriminant);
    }
    if (!r.groups[g].reason.empty()) group["reason"] = r.groups[g].reason;
    step["groups"].push_back(std::move(group));
  }
  const std::vector<bool> placed = placed_bodies(model, sweep, r);
  nlohmann::ordered_json bodies;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!placed[b]) {
      bodies[model.bodies[b]] = nullptr;
      continue;
    }
    const auto& p = r.poses[b];
    bodies[model.bodies[b]] = {{"x", coordinate(p.x, length)}, {"y", coordinate(p.y, length)}, {"angle", rounded_for_report(p.angle)}};
  }
  step["bodies"] = std::move(bodies);
  nlohmann::ordered_json couplings;
  for (std::size_t c = 0; c < model.couplings.size(); ++c) {
    const auto& coupling = model.couplings[c];
    if (!placed[static_cast<std::size_t>(coupling.from)] || !placed[static_cast<std::size_t>(coupling.to)]) {
      couplings[coupling.name] = nullptr;
      continue;
    }
    const auto point = kinematics::coupling_point(model, r.poses, static_cast<int>(c));
    const double value = kinematics::coupling_value(model, r.poses, static_cast<int>(c));
    couplings[coupling.name] = {{"point", {coordinate(point[0], length), coordinate(point[1], length)}},
                                {"value", coupling.type == screw::CouplingType::revolute ? rounded_for_report(value) : coordinate(value, length)}};
  }
  step["couplings"] = std::move(couplings);
  return step;
}

// `text` (a JSON value dumped at indent 2 from level 0) as an element of an array at level 1.
void append_array_element(std::string& out, const nlohmann::ordered_json& element, bool first) {
  const std::string text = element.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  out += first ? "\n    " : ",\n    ";
  for (const char c : text) {
    out += c;
    if (c == '\n') out += "    ";
  }
}

// Replaces `"key": []` in `head` (an object dumped at indent 2) by `"key": [` + elements + `]`,
// as nlohmann would print the array there.
void splice_array(std::string& head, const std::string& key, const std::string& elements) {
  const std::string empty = "\"" + key + "\": []";
  const std::size_t at = head.find(empty);
  if (at == std::string::npos || elements.empty()) return;
  head.replace(at, empty.size(), "\"" + key + "\": [" + elements + "\n  ]");
}

}  // namespace

std::string positions_json_text(const network::Model& model, const PositionSweep& sweep) {
  const double length = sweep.plan.length;
  nlohmann::ordered_json j;
  j["kind"] = "network";
  j["command"] = "move";
  if (!model.name.empty()) j["name"] = model.name;
  j["characteristic_length"] = rounded_for_report(length);
  j["inputs"] = names_of(model, sweep.plan.drivers, false);
  j["groups"] = nlohmann::ordered_json::array();
  for (const auto& g : sweep.plan.groups) {
    nlohmann::ordered_json group;
    group["number"] = g.number;
    group["bodies"] = names_of(model, g.bodies, true);
    group["couplings"] = names_of(model, g.couplings, false);
    group["type"] = g.type;
    group["method"] = kinematics::group_method_name(g.method);
    group["branch"] = g.branch;
    j["groups"].push_back(std::move(group));
  }
  j["steps"] = nlohmann::ordered_json::array();
  j["not_assembled"] = nlohmann::ordered_json::array();
  add_versions(j);
  // Each step is dumped on its own and the text spliced in: the steps of a long sweep (10^7) are
  // never one JSON tree, whose destruction under memory exhaustion would allocate and abort.
  std::string steps;
  std::vector<nlohmann::ordered_json> not_assembled;
  for (std::size_t s = 0; s < sweep.results.size(); ++s) append_array_element(steps, position_step_json(model, sweep, s, not_assembled), s == 0);
  std::string failures;
  for (std::size_t f = 0; f < not_assembled.size(); ++f) append_array_element(failures, not_assembled[f], f == 0);
  std::string text = j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  splice_array(text, "steps", steps);
  splice_array(text, "not_assembled", failures);
  return text + "\n";
}

std::string positions_text(const network::Model& model, const PositionSweep& sweep) {
  using kinematics::AssemblyStatus;
  const double length = sweep.plan.length;
  std::string out = fmt::format("Positions of {}, solved group by group\n", model.name.empty() ? "the mechanism" : model.name);
  out += fmt::format("  inputs: {} (revolute: rad, counter-clockwise; prismatic: length units; relative to the file's configuration)\n",
                     fmt::join(names_of(model, sweep.plan.drivers, false), ", "));
  out += "\nGroups in order of formation:\n";
  for (const auto& g : sweep.plan.groups) {
    out += fmt::format("  {}: {}", group_label(model, g),
                       g.method == kinematics::GroupMethod::newton ? "Newton's method"
                       : g.method == kinematics::GroupMethod::driving_link ? "closed form (driving link)"
                                                                           : "closed form");
    out += fmt::format("; branch: {}\n", g.branch);
  }
  std::size_t failures = 0;
  for (const auto& r : sweep.results) failures += r.failed_group ? 1 : 0;
  out += "\nPositions (revolute couplings: point x, y; prismatic couplings: slide):\n";
  for (std::size_t s = 0; s < sweep.results.size(); ++s) {
    const auto& r = sweep.results[s];
    out += "  " + inputs_text(model, sweep, s) + ": ";
    if (r.failed_group) {
      const auto& g = sweep.plan.groups[*r.failed_group];
      out += fmt::format("cannot be assembled: {}: {}\n", group_label(model, g), r.groups[*r.failed_group].reason);
      continue;
    }
    std::vector<std::string> singular;
    for (std::size_t g = 0; g < r.groups.size(); ++g)
      if (r.groups[g].status == AssemblyStatus::singular)
        singular.push_back(fmt::format("{} is at a singular position ({})", group_label(model, sweep.plan.groups[g]), r.groups[g].reason));
    out += fmt::format("residual {:.3g};", three_significant(r.max_residual));
    for (std::size_t c = 0; c < model.couplings.size(); ++c) {
      const auto& coupling = model.couplings[c];
      const auto point = kinematics::coupling_point(model, r.poses, static_cast<int>(c));
      if (coupling.type == screw::CouplingType::revolute)
        out += fmt::format(" {} ({}, {})", coupling.name, printed_number(coordinate(point[0], length)), printed_number(coordinate(point[1], length)));
      else
        out += fmt::format(" {} slide {}", coupling.name, printed_number(coordinate(kinematics::coupling_value(model, r.poses, static_cast<int>(c)), length)));
    }
    out += "\n";
    for (const auto& text : singular) out += "    " + text + "\n";
  }
  if (failures > 0) {
    out += fmt::format("\nNot assembled at {} of {} input set{}; the first group that cannot be placed:\n", failures, sweep.results.size(),
                       sweep.results.size() == 1 ? "" : "s");
    // Runs of consecutive failing steps, each with its first and last input values.
    for (std::size_t s = 0; s < sweep.results.size();) {
      if (!sweep.results[s].failed_group) {
        ++s;
        continue;
      }
      std::size_t e = s;
      while (e + 1 < sweep.results.size() && sweep.results[e + 1].failed_group == sweep.results[s].failed_group) ++e;
      const auto& g = sweep.plan.groups[*sweep.results[s].failed_group];
      if (e == s) out += fmt::format("  {}: {}\n", inputs_text(model, sweep, s), group_label(model, g));
      else out += fmt::format("  from {} to {}: {}\n", inputs_text(model, sweep, s), inputs_text(model, sweep, e), group_label(model, g));
      s = e + 1;
    }
  }
  return out;
}

}  // namespace kinestat::report
