// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/analysed_cost_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/stiffness_report.hpp"

namespace kinestat::report {

namespace {

// The consistent unit names of a model whose length unit is `length` (docs/stiffness.md).
// The stiffness units besides the cost's (report::cost_units: length, stress).
struct StiffnessUnits {
  std::string length, translation, rotation, coupling, stress;
};

StiffnessUnits stiffness_units(const framework::FrameworkModel& model) {
  const CostUnits u = cost_units(model);
  return {u.length, u.force + "/" + u.length, u.moment + "/rad", u.force + "/rad", u.stress};
}

nlohmann::ordered_json cost_matrix_json(const Eigen::MatrixXd& matrix) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) row.push_back(rounded_for_report(matrix(i, j)));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string cost_shown(double value) { return std::isnan(value) ? "n/a" : fmt::format("{:.4g}", value); }

// "x 0.525 N/mm, z 21000 N/mm"
std::string cost_directions_text(const std::vector<framework::DirectionStiffness>& list, const StiffnessUnits& units) {
  std::string out;
  for (const framework::DirectionStiffness& d : list)
    out += fmt::format("{}{} {} {}", out.empty() ? "" : ", ", d.coordinate, fmt::format("{:.6g}", d.stiffness),
                       d.rotation ? units.rotation : units.translation);
  return out;
}

// Per unit misfit: the worst case and its elements, then the stiffness and frequencies
// without misfit (those with a misfit depend on its size: `--misfit`).
std::string per_unit_cost_text(const framework::FrameworkModel& model, const framework::OverConstraintCost& cost) {
  const StiffnessUnits units = stiffness_units(model);
  std::string out = fmt::format("Cost of over-constraint (per {0} of misfit, force method; stresses are linear in the misfit: "
                                "scale them, or give --misfit VALUE):\n",
                                units.length);
  out += "  " + over_constraint_json(model, cost)["misfit"]["statement"].get<std::string>() + "\n";
  if (!cost.misfit.elements.empty()) {
    out += fmt::format("  {:<20} {:>14} {:>14} {:>16}\n", "element", "force [N]", "moment [N*" + units.length + "]",
                       "stress [" + units.stress + "]");
    for (const framework::ElementStressResultants& e : cost.misfit.elements)
      out += fmt::format("  {:<20} {:>14} {:>14} {:>16}\n", io::printable_text(model.elements[e.element].name), cost_shown(e.force),
                         cost_shown(e.moment), cost_shown(e.stress));
  }
  const framework::NodeStiffness& s = cost.without;
  std::string stiffness = fmt::format("  stiffness at {}: ", io::printable_text(model.nodes[cost.node].name));
  if (!s.motion.empty()) stiffness += "motion " + cost_directions_text(s.motion, units);
  if (!s.support.empty()) stiffness += std::string(s.motion.empty() ? "" : "; ") + "support " + cost_directions_text(s.support, units);
  if (s.support_ratio) stiffness += fmt::format("; support / motion {:.6g}", *s.support_ratio);
  out += stiffness + "\n";
  if (cost.modes_without) {
    std::string list;
    const Eigen::Index count = std::min(kReportedFrequencies, cost.modes_without->frequencies.size());
    for (Eigen::Index i = 0; i < count; ++i)
      list += fmt::format("{}{:.6g}", i ? ", " : "", cost.modes_without->frequencies(i));
    out += "  lowest eigenfrequencies [Hz]: " + list + "\n";
  }
  return out;
}

}  // namespace

nlohmann::ordered_json node_stiffness_json(const framework::FrameworkModel& model, const framework::NodeStiffness& result) {
  const StiffnessUnits units = stiffness_units(model);
  nlohmann::ordered_json out = json_object(10);
  out["at"] = model.nodes[result.node].name;
  out["coordinates"] = result.coordinates;
  out["matrix"] = cost_matrix_json(result.matrix);
  out["compliance"] = result.compliance ? cost_matrix_json(*result.compliance) : nlohmann::ordered_json(nullptr);
  out["units"] = {{"length", units.length}, {"force", "N"}, {"translation", units.translation}, {"rotation", units.rotation},
                  {"coupling", units.coupling}};
  nlohmann::ordered_json principal = nlohmann::ordered_json::array();
  for (const framework::PrincipalStiffness& p : result.principal) {
    nlohmann::ordered_json direction = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < p.direction.size(); ++k) direction.push_back(rounded_for_report(p.direction(k)));
    principal.push_back({{"stiffness", rounded_for_report(p.stiffness)},
                         {"kind", p.rotation ? "rotation" : "translation"},
                         {"unit", p.rotation ? units.rotation : units.translation},
                         {"direction", std::move(direction)}});
  }
  out["principal"] = std::move(principal);
  out["length_scale"] = rounded_for_report(result.length_scale);
  auto directions = [&](const std::vector<framework::DirectionStiffness>& list) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (const framework::DirectionStiffness& d : list)
      array.push_back({{"coordinate", d.coordinate}, {"stiffness", rounded_for_report(d.stiffness)},
                       {"unit", d.rotation ? units.rotation : units.translation}});
    return array;
  };
  out["motion"] = directions(result.motion);
  out["support"] = directions(result.support);
  out["support_ratio"] =
      result.support_ratio ? nlohmann::ordered_json(rounded_for_report(*result.support_ratio)) : nlohmann::ordered_json(nullptr);
  return out;
}

std::string analysed_cost_text(const framework::FrameworkModel& model, const framework::AnalysedCost& cost) {
  if (!cost.cost) return "Cost of over-constraint: not computed: " + io::printable_text(cost.not_computed) + "\n\n";
  if (cost.per_unit) return per_unit_cost_text(model, *cost.cost) + "\n";
  return over_constraint_text(model, *cost.cost) + "\n";
}

nlohmann::ordered_json analysed_cost_json(const framework::FrameworkModel& model, const framework::AnalysedCost& cost) {
  nlohmann::ordered_json out = json_object(5);
  if (!cost.cost) {
    out["stiffness"] = nullptr;
    out["misfit"] = nullptr;
    out["cost_not_computed"] = cost.not_computed;
    return out;
  }
  out["stiffness"] = node_stiffness_json(model, cost.cost->without);
  const nlohmann::ordered_json block = over_constraint_json(model, *cost.cost);
  for (auto item = block.begin(); item != block.end(); ++item) out[item.key()] = item.value();
  out["misfit"]["per_unit"] = cost.per_unit;
  if (cost.per_unit) {
    // The prestressed stiffness and frequencies depend on the misfit's size (and the
    // frequencies not linearly): only for a given --misfit.
    out["misfit"]["stiffness"].erase("with");
    out.erase("frequencies_with_misfit");
  }
  return out;
}

}  // namespace kinestat::report
