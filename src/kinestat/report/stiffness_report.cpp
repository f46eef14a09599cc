// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/stiffness_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/report/json_text.hpp"

namespace kinestat::report {

namespace {

using framework::ElementStressResultants;
using framework::NodeStiffness;
using framework::OverConstraintCost;

// Ten significant digits, -0 as 0. Physical values have units, so no absolute zero cut
// (rounded_for_report's is for normalised numbers).
double physical(double value) {
  if (!std::isfinite(value) || value == 0.0) return value == 0.0 ? 0.0 : value;
  char digits[32];
  const auto written = std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, 10);
  double r = 0.0;
  std::from_chars(digits, written.ptr, r);
  return r == 0.0 ? 0.0 : r;
}
std::string precise(double value) { return std::isnan(value) ? "n/a" : fmt::format("{:.6g}", physical(value)); }
// The relative change from `without` to `with`, as a signed percentage ("0" when none).
std::string change(double without, double with) {
  if (without == 0.0 || !std::isfinite(without) || !std::isfinite(with)) return "";
  const double relative = (with - without) / std::abs(without);
  if (physical(with) == physical(without)) return "0";
  return fmt::format("{:+.2g}%", 100 * relative);
}
std::string shown(double value) { return std::isnan(value) ? "n/a" : fmt::format("{:.4g}", physical(value)); }
nlohmann::ordered_json json_number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(physical(value)) : nlohmann::ordered_json(nullptr);
}


std::string element_name(const framework::FrameworkModel& model, std::size_t element) {
  return io::printable_text(model.elements[element].name);
}
std::string deformation_label(const framework::FrameworkModel& model, const framework::FrameworkIndexing& indexing, Eigen::Index d) {
  const framework::DeformationRef& ref = indexing.deformations[static_cast<std::size_t>(d)];
  const framework::Element& element = model.elements[ref.element];
  return element.name + "." + framework::deformation_names(model, element)[ref.deformation];
}

nlohmann::ordered_json element_json(const framework::FrameworkModel& model, const ElementStressResultants& e) {
  nlohmann::ordered_json j = json_object(5);
  j["element"] = model.elements[e.element].name;
  j["force"] = json_number(e.force);
  j["moment"] = json_number(e.moment);
  j["torque"] = json_number(e.torque);
  j["stress"] = json_number(e.stress);
  return j;
}

nlohmann::ordered_json directions_json(const std::vector<framework::DirectionStiffness>& directions) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const framework::DirectionStiffness& d : directions)
    list.push_back({{"coordinate", d.coordinate}, {"stiffness", json_number(d.stiffness)}, {"rotation", d.rotation}});
  return list;
}

nlohmann::ordered_json node_stiffness_json(const NodeStiffness& s) {
  nlohmann::ordered_json j = json_object(3);
  j["motion"] = directions_json(s.motion);
  j["support"] = directions_json(s.support);
  j["support_ratio"] = s.support_ratio ? json_number(*s.support_ratio) : nlohmann::ordered_json(nullptr);
  return j;
}

nlohmann::ordered_json frequencies_json(const framework::VibrationModes& modes) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  const Eigen::Index count = std::min(kReportedFrequencies, modes.frequencies.size());
  for (Eigen::Index i = 0; i < count; ++i) list.push_back(json_number(modes.frequencies(i)));
  return list;
}

// The misfit as given: one length ("0.01 mm"), or per element ("0.02 mm in d1, 0.01 mm in d2,
// 0.005 mm elsewhere"; "none elsewhere" without a plain value).
std::string tolerance_text(const framework::MisfitTolerance& tolerance, const std::string& length) {
  if (tolerance.per_element.empty()) return fmt::format("{} {}", shown(tolerance.value.value_or(0.0)), length);
  std::string out;
  for (const auto& [element, value] : tolerance.per_element)
    out += fmt::format("{}{} {} in {}", out.empty() ? "" : ", ", shown(value), length, io::printable_text(element));
  return out + (tolerance.value ? fmt::format(", {} {} elsewhere", shown(*tolerance.value), length) : ", none elsewhere");
}

std::string statement(const framework::FrameworkModel& model, const OverConstraintCost& cost) {
  const CostUnits u = cost_units(model);
  const framework::MisfitResult& m = cost.misfit;
  if (m.self_stresses == 0)
    return fmt::format("no self-stress: exactly constrained against misfit, so a misfit of {} is taken up without stress, "
                       "and stiffness and eigenfrequencies do not change with it",
                       tolerance_text(m.tolerance, u.length));
  if (!m.computed)
    return fmt::format("{} self-stress{}, but no stress vectors were computed (a large model analysed by sparse QR): "
                       "misfit stress not computed",
                       m.self_stresses, m.self_stresses == 1 ? "" : "es");
  if (!m.worst_source) return "no held length deformation takes part in a self-stress: misfit stress not computed";
  const ElementStressResultants& w = m.worst;
  const std::string stress = std::isnan(w.stress) ? "" : fmt::format("a peak stress of {} {}, ", shown(w.stress), u.stress);
  return fmt::format("{} self-stress{}; the worst case is a misfit of {} {} in {}: it gives {} {}an axial force of {} {}{}",
                     m.self_stresses, m.self_stresses == 1 ? "" : "es", shown(m.worst_misfit), u.length,
                     io::printable_text(deformation_label(model, cost.indexing, *m.worst_source)), element_name(model, w.element),
                     stress, shown(w.force), u.force,
                     w.moment != 0.0 ? fmt::format(" and a bending moment of {} {}", shown(w.moment), u.moment) : "");
}

std::string stiffness_unit(const CostUnits& u, bool rotation) {
  return rotation ? u.moment + "/rad" : u.force + "/" + u.length;
}

}  // namespace

CostUnits cost_units(const framework::FrameworkModel& model) {
  CostUnits u;
  u.length = model.units.empty() ? "m" : model.units;
  u.stress = u.length == "m" ? "Pa" : "N/" + u.length + "^2";
  u.moment = "N*" + u.length;
  return u;
}

std::string over_constraint_text(const framework::FrameworkModel& model, const OverConstraintCost& cost) {
  const CostUnits u = cost_units(model);
  const framework::MisfitTolerance& tolerance = cost.misfit.tolerance;
  std::string out = tolerance.per_element.empty()
                        ? fmt::format("Cost of over-constraint (misfit {} per held deformation, force method):\n",
                                      tolerance_text(tolerance, u.length))
                        : fmt::format("Cost of over-constraint (misfit per held deformation: {}; force method):\n",
                                      tolerance_text(tolerance, u.length));
  out += "  " + statement(model, cost) + "\n";
  if (!cost.misfit.elements.empty()) {
    out += fmt::format("  {:<20} {:>14} {:>14} {:>16}\n", "element", "force [" + u.force + "]", "moment [" + u.moment + "]",
                       "stress [" + u.stress + "]");
    for (const ElementStressResultants& e : cost.misfit.elements)
      out += fmt::format("  {:<20} {:>14} {:>14} {:>16}\n", element_name(model, e.element), shown(e.force), shown(e.moment), shown(e.stress));
  }
  const std::string node = io::printable_text(model.nodes[cost.node].name);
  out += fmt::format("  {:<24} {:>14} {:>14} {:>10}\n", "stiffness at " + node, "without misfit", "with misfit", "change");
  auto rows = [&](const char* kind, const std::vector<framework::DirectionStiffness>& without,
                  const std::vector<framework::DirectionStiffness>& with) {
    for (std::size_t i = 0; i < without.size() && i < with.size(); ++i)
      out += fmt::format("    {:<8} {:<13} {:>14} {:>14} {:>10}  {}\n", kind, without[i].coordinate, precise(without[i].stiffness),
                         precise(with[i].stiffness), change(without[i].stiffness, with[i].stiffness), stiffness_unit(u, without[i].rotation));
  };
  rows("motion", cost.without.motion, cost.with.motion);
  rows("support", cost.without.support, cost.with.support);
  if (cost.without.support_ratio && cost.with.support_ratio)
    out += fmt::format("    {:<22} {:>14} {:>14} {:>10}\n", "support / motion", precise(*cost.without.support_ratio),
                       precise(*cost.with.support_ratio), change(*cost.without.support_ratio, *cost.with.support_ratio));
  if (cost.modes_without && cost.modes_with) {
    out += fmt::format("  {:<24} {:>14} {:>14} {:>10}\n", "eigenfrequency [Hz]", "without misfit", "with misfit", "change");
    const Eigen::Index count = std::min(kReportedFrequencies, cost.modes_without->frequencies.size());
    for (Eigen::Index i = 0; i < count && i < cost.modes_with->frequencies.size(); ++i)
      out += fmt::format("    {:<22} {:>14} {:>14} {:>10}\n", i + 1, precise(cost.modes_without->frequencies(i)),
                         precise(cost.modes_with->frequencies(i)),
                         change(cost.modes_without->frequencies(i), cost.modes_with->frequencies(i)));
    if (cost.modes_with->frequencies.size() > 0 && cost.modes_with->frequencies(0) < 0)
      out += "    a negative frequency is a mode the prestressed stiffness does not hold (buckling)\n";
  } else {
    out += "  eigenfrequencies: the model gives no masses\n";
  }
  return out;
}

nlohmann::ordered_json over_constraint_json(const framework::FrameworkModel& model, const OverConstraintCost& cost) {
  const framework::MisfitResult& m = cost.misfit;
  nlohmann::ordered_json misfit = json_object(9);
  const bool per_element = !m.tolerance.per_element.empty();
  // Per element without a plain value: the elements not named have none, `value` is null.
  misfit["value"] = per_element && !m.tolerance.value ? nlohmann::ordered_json(nullptr) : json_number(m.value);
  if (per_element) {
    nlohmann::ordered_json named = json_object(m.tolerance.per_element.size());
    for (const auto& [element, value] : m.tolerance.per_element) named[element] = json_number(value);
    misfit["per_element"] = std::move(named);
  }
  misfit["unit"] = cost_units(model).length;
  misfit["self_stresses"] = m.self_stresses;
  misfit["statement"] = statement(model, cost);
  if (m.worst_source) {
    nlohmann::ordered_json worst = element_json(model, m.worst);
    worst["source"] = deformation_label(model, cost.indexing, *m.worst_source);
    worst["self_stress"] = m.worst_self_stress + 1;
    misfit["worst"] = std::move(worst);
  } else {
    misfit["worst"] = nullptr;
  }
  misfit["elements"] = nlohmann::ordered_json::array();
  for (const ElementStressResultants& e : m.elements) misfit["elements"].push_back(element_json(model, e));
  misfit["participating"] = nlohmann::ordered_json::array();
  for (Eigen::Index d : m.participating) misfit["participating"].push_back(deformation_label(model, cost.indexing, d));
  nlohmann::ordered_json stiffness = json_object(3);
  stiffness["at"] = model.nodes[cost.node].name;
  stiffness["without"] = node_stiffness_json(cost.without);
  stiffness["with"] = node_stiffness_json(cost.with);
  misfit["stiffness"] = std::move(stiffness);
  nlohmann::ordered_json out = json_object(3);
  out["misfit"] = std::move(misfit);
  if (cost.modes_without && cost.modes_with) {
    out["frequencies"] = frequencies_json(*cost.modes_without);
    out["frequencies_with_misfit"] = frequencies_json(*cost.modes_with);
  }
  return out;
}

}  // namespace kinestat::report
