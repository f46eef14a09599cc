// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/structure_report.hpp"

#include "kinestat/io/printable_text.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/verdict_report.hpp"
#include "kinestat/report/markup_escape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "kinestat/structure/structural_diagram.hpp"

namespace kinestat::report {

using structure::StructureResult;
using structure::PairKind;
using structure::StructuralGroup;
using structure::StructureModel;

std::string group_name(int number) {
  if (number <= 0) return "frame";
  if (number >= 4000) return fmt::format("SG-{}", number);
  static const std::pair<int, const char*> numerals[] = {{1000, "M"}, {900, "CM"}, {500, "D"}, {400, "CD"},
                                                         {100, "C"},  {90, "XC"},  {50, "L"},  {40, "XL"},
                                                         {10, "X"},   {9, "IX"},   {5, "V"},   {4, "IV"}, {1, "I"}};
  std::string roman;
  for (const auto& [value, letters] : numerals)
    for (; number >= value; number -= value) roman += letters;
  return "SG-" + roman;
}

namespace {

std::string body_list(const std::vector<int>& bodies) {
  std::string out = "{";
  for (std::size_t i = 0; i < bodies.size(); ++i) out += (i ? ", " : "") + std::to_string(bodies[i] + 1);
  return out + "}";
}

bool named(const StructureModel& model) {
  for (int b = 0; b < model.body_count(); ++b)
    if (model.body_names[b] != std::to_string(b + 1)) return true;
  return false;
}

std::string names_of(const StructureModel& model, const std::vector<int>& bodies) {
  std::string out;
  for (std::size_t i = 0; i < bodies.size(); ++i) out += (i ? ", " : "") + io::printable_text(structure::body_label(model, bodies[i]));
  return out;
}

std::string space_name(const StructureModel& model) { return model.dimension == 6 ? "spatial" : "planar"; }

std::string method_name(structure::SearchMethod method) {
  return method == structure::SearchMethod::matching ? "matching" : "seed";
}

std::vector<std::vector<int>> stages_of(const StructureResult& d) {
  std::vector<std::vector<int>> stages;
  for (const StructuralGroup& g : d.groups) {
    if (static_cast<int>(stages.size()) < g.stage) stages.resize(g.stage);
    stages[g.stage - 1].push_back(g.number);
  }
  return stages;
}

std::string after_text(const std::vector<int>& after) {
  std::string out;
  for (std::size_t i = 0; i < after.size(); ++i) out += (i ? ", " : "") + group_name(after[i]);
  return out;
}

void append_matrix(std::string& out, const std::vector<std::vector<int>>& m, const std::string& indent) {
  int width = 1;
  for (const auto& row : m)
    for (int v : row) width = std::max(width, static_cast<int>(std::to_string(v).size()));
  for (const auto& row : m) {
    out += indent;
    for (std::size_t j = 0; j < row.size(); ++j) out += fmt::format("{}{:>{}}", j ? " " : "", row[j], width);
    out += '\n';
  }
}

void append_undecomposed(std::string& out, const StructureModel& model, const StructureResult& d) {
  const auto& u = d.undecomposed;
  if (u.empty()) return;
  const int count =
      static_cast<int>(u.over_constrained.size() + u.under_constrained.size() + u.blocked.size());
  out += fmt::format("\nNot decomposed: {} of {} movable bodies (mobility {}, inputs {}).\n", count,
                     model.body_count() - 1, model.mobility(), model.input_count());
  if (!u.over_constrained.empty())
    out += fmt::format("  over-constrained: bodies {}: {} constraint(s) or input(s) too many; remove inputs or pairs there\n",
                       body_list(u.over_constrained), u.redundant);
  if (u.over_constrained_part.size() > u.over_constrained.size())
    out += fmt::format("    the redundancy can sit on any pair of the over-constrained part, bodies {};\n"
                       "    which of its bodies Eq. 1 still places can depend on the body numbering\n",
                       body_list(u.over_constrained_part));
  if (!u.under_constrained.empty())
    out += fmt::format("  under-constrained: bodies {}: {} input(s) missing; drive more pairs there\n",
                       body_list(u.under_constrained), u.missing);
  if (!u.blocked.empty())
    out += fmt::format("  blocked: bodies {}: they depend on the over-constrained part or are not connected to the frame\n",
                       body_list(u.blocked));
}

std::string placement_text(const StructureModel& model, const std::vector<int>& inputs) {
  std::string out;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    if (inputs[k] == 0) continue;
    if (!out.empty()) out += ", ";
    const auto& p = model.pairs[k];
    out += fmt::format("({} {})", p.a + 1, p.b + 1) + (inputs[k] > 1 ? fmt::format(" x{}", inputs[k]) : "");
  }
  return out.empty() ? "none" : out;
}

}  // namespace

std::string structure_report_text(const StructureReport& report) {
  const StructureModel& model = report.model;
  const StructureResult& d = report.decomposition;
  std::string out;
  if (report.verdict) out += verdict_text(*report.verdict);
  out += "Structural analysis" + (model.name.empty() ? std::string() : ": " + io::printable_text(model.name)) + "\n";
  if (!report.units.empty()) out += fmt::format("  units: {}\n", io::printable_text(report.units));
  out += fmt::format("  {} (d = {}), {} bodies (body 1 is the frame), {} pairs, {} input(s), mobility {}\n",
                     space_name(model), model.dimension, model.body_count(), model.pairs.size(), model.input_count(),
                     model.mobility());
  out += fmt::format("  search: {}\n", report.method == structure::SearchMethod::matching
                                           ? "constraint matching (Dulmage-Mendelsohn blocks), polynomial"
                                           : "the seed's Algorithms 1-3 (chains of growing length)");
  out += fmt::format("\nStructural groups in order of formation ({}), Eq. 1: Sc - nc = {} (P - Nm):\n", d.groups.size(),
                     model.dimension);
  const bool with_names = named(model);
  for (const StructuralGroup& g : d.groups) {
    out += fmt::format("  {:<8} bodies {:<12} Nm {:>2}  nc {:>2}  P {:>2}  Sc {:>2}  stage {:>2}  after {}", group_name(g.number),
                       body_list(g.bodies), g.Nm, g.nc, g.P, g.Sc, g.stage, after_text(g.after));
    if (with_names) out += "  (" + names_of(model, g.bodies) + ")";
    out += '\n';
  }
  if (d.groups.empty()) out += "  none\n";
  append_undecomposed(out, model, d);
  if (model.body_count() <= kMaxDenseBodies) {
    out += "\nResult matrix Result.Res (row 1: group of each body; row r: DOF received by body r from each column):\n";
    append_matrix(out, d.result_matrix(), "  ");
  }
  if (const auto* t = report.transformations) {
    out += "\nStructural transformations (other placements of the inputs):\n";
    if (!t->enumerated) {
      out += fmt::format("  not enumerated: more than {} placements\n", t->placements - 1);
    } else {
      out += fmt::format("  {} placement(s) of {} input(s); {} decomposable, {} not; best first:\n", t->placements,
                         model.input_count(), t->ranked.size(), t->not_decomposable);
      const std::size_t shown = std::min<std::size_t>(t->ranked.size(), 10);
      for (std::size_t i = 0; i < shown; ++i) {
        const auto& x = t->ranked[i];
        std::string groups;
        for (const auto& g : x.decomposition.groups) groups += (groups.empty() ? "" : " ") + body_list(g.bodies);
        out += fmt::format("  {:>3}. inputs on {}: {} groups, largest group {} bodies, {} stages{}\n      {}\n", i + 1,
                           placement_text(model, x.inputs), x.decomposition.groups.size(), x.largest_group, x.stages,
                           x.original ? "  (as given)" : "", groups);
      }
      if (shown < t->ranked.size()) out += fmt::format("  ... {} more (see --json)\n", t->ranked.size() - shown);
      for (std::size_t i = shown; i < t->ranked.size(); ++i)
        if (t->ranked[i].original) out += fmt::format("  The placement as given ranks {} of {}.\n", i + 1, t->ranked.size());
    }
  }
  return out;
}

namespace {

// Sections of structure_report_json, in the order of their keys.

using nlohmann::ordered_json;

// Body indices 1-based, as the paper numbers them.
ordered_json one_based(const std::vector<int>& bodies) {
  ordered_json list = ordered_json::array();
  for (int b : bodies) list.push_back(b + 1);
  return list;
}

ordered_json structure_pairs_json(const StructureModel& model) {
  ordered_json pairs = ordered_json::array();
  for (const auto& p : model.pairs) {
    ordered_json q;
    q["between"] = {p.a + 1, p.b + 1};
    q["pair"] = p.kind == PairKind::lower ? "lower" : "higher";
    q["freedoms"] = p.freedoms;
    q["inputs"] = p.inputs;
    pairs.push_back(q);
  }
  return pairs;
}

// The groups ("groups") and their bodies in order of formation ("order").
void add_group_keys(ordered_json& j, const StructureResult& d) {
  ordered_json groups = ordered_json::array();
  ordered_json order = ordered_json::array();
  for (const StructuralGroup& g : d.groups) {
    ordered_json x;
    x["number"] = g.number;
    x["name"] = group_name(g.number);
    x["bodies"] = one_based(g.bodies);
    x["Nm"] = g.Nm;
    x["nc"] = g.nc;
    x["P"] = g.P;
    x["Sc"] = g.Sc;
    x["after"] = g.after;
    x["stage"] = g.stage;
    groups.push_back(x);
    order.push_back(one_based(g.bodies));
  }
  j["groups"] = groups;
  j["order"] = order;
}

// The bodies in no group (null when the decomposition is complete).
ordered_json undecomposed_json(const StructureResult& d) {
  if (d.complete()) return nullptr;
  const auto& u = d.undecomposed;
  ordered_json x;
  x["over_constrained"] = one_based(u.over_constrained);
  x["redundant"] = u.redundant;
  x["over_constrained_part"] = one_based(u.over_constrained_part);
  x["under_constrained"] = one_based(u.under_constrained);
  x["missing_inputs"] = u.missing;
  x["blocked"] = one_based(u.blocked);
  return x;
}

// Placement `rank` (1-based) of the inputs: where they are, its groups and matrices.
ordered_json placement_json(const StructureModel& model, const structure::Transformation& r, std::size_t rank) {
  ordered_json y;
  y["rank"] = rank;
  y["original"] = r.original;
  ordered_json inputs = ordered_json::array();
  for (std::size_t k = 0; k < r.inputs.size(); ++k) {
    if (r.inputs[k] == 0) continue;
    ordered_json z;
    z["between"] = {model.pairs[k].a + 1, model.pairs[k].b + 1};
    z["inputs"] = r.inputs[k];
    inputs.push_back(z);
  }
  y["inputs"] = inputs;
  ordered_json tg = ordered_json::array();
  for (const auto& g : r.decomposition.groups) tg.push_back(one_based(g.bodies));
  y["groups"] = tg;
  y["group_count"] = r.decomposition.groups.size();
  y["largest_group"] = r.largest_group;
  y["stages"] = r.stages;
  const auto adjacency = structure::adjacency_of(structure::with_inputs(model, r.inputs));
  y["adjacency"] = adjacency.empty() ? ordered_json(nullptr) : ordered_json(adjacency);
  y["result_matrix"] = model.body_count() <= kMaxDenseBodies ? ordered_json(r.decomposition.result_matrix()) : ordered_json(nullptr);
  return y;
}

// The other placements of the inputs, best first (null when not asked for).
ordered_json transformations_json(const StructureModel& model, const structure::TransformationSet* t) {
  if (!t) return nullptr;
  ordered_json x;
  x["placements"] = t->placements;
  x["enumerated"] = t->enumerated;
  x["not_decomposable"] = t->not_decomposable;
  ordered_json ranked = ordered_json::array();
  for (std::size_t i = 0; i < t->ranked.size(); ++i) ranked.push_back(placement_json(model, t->ranked[i], i + 1));
  x["ranked"] = ranked;
  return x;
}

}  // namespace

std::string structure_report_json(const StructureReport& report) {
  const StructureModel& model = report.model;
  const StructureResult& d = report.decomposition;
  ordered_json j;
  j["kind"] = "structure";
  j["name"] = model.name;
  j["space"] = space_name(model);
  j["dimension"] = model.dimension;
  j["bodies"] = model.body_names;
  j["pairs"] = structure_pairs_json(model);
  j["mobility"] = model.mobility();
  j["inputs"] = model.input_count();
  j["method"] = method_name(report.method);
  j["complete"] = d.complete();
  add_group_keys(j, d);
  j["stages"] = stages_of(d);
  j["result_matrix"] = model.body_count() <= kMaxDenseBodies ? ordered_json(d.result_matrix()) : ordered_json(nullptr);
  ordered_json assignments = ordered_json::array();
  for (const auto& a : d.assignments) assignments.push_back({a.receiver + 1, a.assigner + 1, a.value});
  j["assignments"] = assignments;
  j["undecomposed"] = undecomposed_json(d);
  j["transformations"] = transformations_json(model, report.transformations);
  if (report.verdict) return json_text(with_notices(lead_with_verdict(*report.verdict, std::move(j), report.units), report.notices));
  return json_text(with_notices(std::move(j), report.notices));
}

std::string structure_dot(const StructureModel& model, const StructureResult& d) {
  const auto diagram = structure::structural_diagram(d);
  std::string out = "digraph structure {\n";
  // A DOT string: control characters escaped as in every text report, then quoted.
  std::string title;
  for (char c : io::printable_text(model.name.empty() ? std::string("structural diagram") : model.name)) {
    if (c == '"' || c == '\\') title += '\\';
    title += c;
  }
  out += "  label=\"" + title + "\";\n  labelloc=t;\n";
  out += "  rankdir=TB;\n  node [shape=circle, fontname=\"Helvetica\"];\n";
  for (const auto& n : diagram.nodes) {
    if (n.group == 0) out += "  g0 [label=\"0\", xlabel=\"frame\"];\n";
    else out += fmt::format("  g{} [label=\"({}, {})\", xlabel=\"{}\"];\n", n.group, n.Nm, n.nc, group_name(n.group));
  }
  for (int layer = 0; layer < diagram.layers; ++layer) {
    std::string same;
    for (const auto& n : diagram.nodes)
      if (n.layer == layer) same += fmt::format(" g{};", n.group);
    out += "  { rank=same;" + same + " }\n";
  }
  for (const auto& a : diagram.arrows) out += fmt::format("  g{} -> g{};\n", a.from, a.to);
  out += "}\n";
  return out;
}

}  // namespace kinestat::report
