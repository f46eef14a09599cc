// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/json_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include "kinestat/design/screw_text.hpp"
#include "kinestat/framework/body_motions.hpp"
#include "kinestat/framework/analysed_cost.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/report/analysed_cost_report.hpp"
#include "kinestat/report/generic_text.hpp"
#include "kinestat/report/rank_status_text.hpp"
#include "kinestat/report/verdict_report.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::report {

using framework::FrameworkResult;
using framework::FrameworkModel;

namespace {

double rounded(double value) { return rounded_for_report(value); }

std::string number(double value) { return fmt::format("{:.6g}", rounded(value)); }

// Rank evidence keeps tiny values (a dropped singular value of 1e-16 is information).
double significant(double value) {
  if (!std::isfinite(value) || value == 0.0) return value;
  return std::strtod(fmt::format("{:.10g}", value).c_str(), nullptr);
}
std::string evidence(double value) { return fmt::format("{:.3g}", significant(value)); }
double evidence_number(double value) { return std::strtod(evidence(value).c_str(), nullptr); }

// The smallest and largest of the length-scaling factors (framework::physical_scaling), to
// four digits: they come from an iteration, and only their spread is information.
std::array<double, 2> factor_range(const Eigen::VectorXd& factors) {
  if (factors.size() == 0) return {1.0, 1.0};
  auto four = [](double v) { return std::strtod(fmt::format("{:.4g}", v).c_str(), nullptr); };
  return {four(factors.minCoeff()), four(factors.maxCoeff())};
}
double spread(const Eigen::VectorXd& factors) { return factors.size() == 0 ? 1.0 : factors.maxCoeff() / factors.minCoeff(); }
// The text report mentions the scaling only when it does something noticeable.
constexpr double kShownScaleSpread = 1.01;

const framework::CoordinateRef& column_ref(const FrameworkResult& a, Eigen::Index column) {
  return a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(column)])];
}

const framework::DeformationRef& row_ref(const FrameworkResult& a, Eigen::Index row) {
  return a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(row)])];
}

std::string deformation_name(const FrameworkModel& model, const framework::DeformationRef& d) {
  return framework::deformation_names(model, model.elements[d.element])[d.deformation];
}

// Large models (the sparse path) write vectors compactly: only their non-zero components.
bool compact(const FrameworkResult& a) { return a.method == framework::RankMethod::sparse_qr; }

// Rigid parts of a mode listed in the text detail; all of them in the JSON.
constexpr std::size_t kTextParts = 6;

// "body 'stage': C, P1, P2" or "B, C": a rigid part of a mode by its body and nodes.
std::string part_label(const FrameworkModel& model, const framework::MovingPart& part) {
  std::vector<std::string> names;
  for (std::size_t n : part.nodes) names.push_back(io::printable_text(model.nodes[n].name));
  const std::string nodes = fmt::format("{}", fmt::join(names, ", "));
  return part.body.empty() ? nodes : fmt::format("body '{}': {}", io::printable_text(part.body), nodes);
}

// The rigid parts of a mode (framework/body_motions.hpp): nodes, body, motion in words, twist
// (angular velocity; velocity at the origin, file units, per unit mode amplitude), share.
nlohmann::ordered_json parts_json(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& velocities) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& part : framework::moving_parts(model, a, velocities)) {
    nlohmann::ordered_json p = json_object(5);
    p["nodes"] = nlohmann::ordered_json::array();
    for (std::size_t n : part.nodes) p["nodes"].push_back(model.nodes[n].name);
    if (!part.body.empty()) p["body"] = part.body;
    p["motion"] = design::motion_text(part.twist, a.length);
    p["twist"] = nlohmann::ordered_json::array();
    for (Eigen::Index i = 0; i < 6; ++i) p["twist"].push_back(rounded(part.twist(i)));
    p["share"] = rounded(part.share);
    list.push_back(std::move(p));
  }
  return list;
}

// The smallest |entry| of `v` a listing gives: every entry for the full listing, else those
// above kModeZero times the largest (relative: a unit-norm vector of 10^6 entries has entries of
// 10^-3, and one scaled otherwise is listed alike).
double listed_above(const Eigen::VectorXd& v, VectorListing listing) {
  if (listing == VectorListing::full) return -1.0;
  return v.size() == 0 ? 0.0 : kinestat::kModeZero * v.cwiseAbs().maxCoeff();
}

// Mode velocities grouped by node, in node order, coordinates in slot order.
nlohmann::ordered_json velocities_by_node(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& v,
                                          VectorListing listing) {
  nlohmann::ordered_json nodes = nlohmann::ordered_json::object();
  const double above = listed_above(v, listing);
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    if (!(std::abs(v(j)) > above)) continue;
    const auto& c = column_ref(a, j);
    nodes[model.nodes[c.node].name][framework::kSlotNames[static_cast<std::size_t>(c.slot)]] = rounded(v(j));
  }
  return nodes;
}

// Names of the parts that take part in the states of cause `geometry`: the nodes the modes move
// and the elements the stress states load, in model order.
std::vector<std::string> geometric_nodes(const FrameworkModel& model, const FrameworkResult& a, const framework::GenericFramework& g) {
  std::vector<bool> involved(model.nodes.size(), false);
  for (std::size_t k = 0; k < a.modes.size() && k < g.mode_causes.size(); ++k)
    if (g.mode_causes[k] == linalg::Cause::geometry)
      for (Eigen::Index col : a.modes[k].moving)
        if (std::abs(a.modes[k].velocities(col)) > kinestat::kModeZero) involved[column_ref(a, col).node] = true;
  std::vector<std::string> names;
  for (std::size_t n = 0; n < involved.size(); ++n)
    if (involved[n]) names.push_back(model.nodes[n].name);
  return names;
}

std::vector<std::string> geometric_elements(const FrameworkModel& model, const FrameworkResult& a, const framework::GenericFramework& g) {
  std::vector<bool> involved(model.elements.size(), false);
  for (std::size_t k = 0; k < a.stresses.size() && k < g.stress_causes.size(); ++k)
    if (g.stress_causes[k] == linalg::Cause::geometry)
      for (Eigen::Index row = 0; row < a.stresses[k].resultants.size(); ++row)
        if (std::abs(a.stresses[k].resultants(row)) > kinestat::kModeZero) involved[row_ref(a, row).element] = true;
  std::vector<std::string> names;
  for (std::size_t e = 0; e < involved.size(); ++e)
    if (involved[e]) names.push_back(model.elements[e].name);
  return names;
}

std::string generic_method(const framework::GenericFramework& g) {
  return g.exact ? fmt::format("exact rank of D(c) (bars, modulo primes) at {} random realisations", g.realisations)
                 : fmt::format("SVD rank of D(c) at {} random realisations (floating point: beams or rigid bodies)", g.realisations);
}

std::vector<std::string> printable_all(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& n : names) out.push_back(io::printable_text(n));
  return out;
}

std::vector<std::string> generic_explanation(const FrameworkModel& model, const FrameworkResult& a, const framework::GenericFramework& g,
                                             bool printable) {
  auto nodes = geometric_nodes(model, a, g), elements = geometric_elements(model, a, g);
  if (printable) {
    nodes = printable_all(nodes);
    elements = printable_all(elements);
  }
  return {generic_count_text("mechanisms", a.mechanisms, g.mechanisms, nodes, "nodes"),
          generic_count_text("self_stresses", a.self_stresses, g.self_stresses, elements, "elements")};
}

std::string component_text(const FrameworkModel& model, const framework::LamanCount::Component& component) {
  std::vector<std::string> names;
  if (component.ground) names.push_back("ground");
  for (std::size_t n : component.nodes) names.push_back(io::printable_text(model.nodes[n].name));
  return fmt::format("{{{}}}", fmt::join(names, ", "));
}

nlohmann::ordered_json generic_json(const FrameworkModel& model, const FrameworkResult& a, const framework::GenericFramework& g) {
  nlohmann::ordered_json j;
  j["mechanisms"] = g.mechanisms;
  j["self_stresses"] = g.self_stresses;
  j["rank"] = g.rank;
  j["method"] = generic_method(g);
  j["exact"] = g.exact;
  j["special"] = {{"mechanisms", a.mechanisms - g.mechanisms}, {"self_stresses", a.self_stresses - g.self_stresses}};
  j["split_residual"] = std::round(g.split_residual * 1e6) / 1e6;
  j["special_nodes"] = geometric_nodes(model, a, g);
  j["special_elements"] = geometric_elements(model, a, g);
  j["explanation"] = generic_explanation(model, a, g, false);
  if (g.laman) {
    nlohmann::ordered_json components = nlohmann::ordered_json::array();
    for (const auto& c : g.laman->rigid_components) {
      std::vector<std::string> names;
      for (std::size_t n : c.nodes) names.push_back(model.nodes[n].name);
      components.push_back({{"nodes", names}, {"ground", c.ground}});
    }
    j["laman"] = {{"rank", g.laman->rank},
                  {"mechanisms", g.laman->mechanisms},
                  {"self_stresses", g.laman->self_stresses},
                  {"agrees", g.laman->rank == g.rank},
                  {"rigid_components", components}};
  } else {
    j["laman"] = nullptr;
  }
  return j;
}

// Short code of an OrderReason in the JSON.
const char* order_reason_code(framework::OrderReason reason) {
  using framework::OrderReason;
  switch (reason) {
    case OrderReason::prestress_stable: return "prestress_stable";
    case OrderReason::blocked_by_stress: return "blocked_by_stress";
    case OrderReason::rigid_motion: return "rigid_motion";
    case OrderReason::traced: return "traced";
    case OrderReason::trace_failed: return "trace_failed";
    case OrderReason::no_second_order_model: return "no_second_order_model";
    case OrderReason::not_computed: return "not_computed";
  }
  return "not_computed";
}

// The reason of a mode's order in words, for the text report.
std::string order_reason_text(const framework::ModeOrder& o) {
  using framework::OrderReason;
  switch (o.reason) {
    case OrderReason::prestress_stable:
      return "blocked at second order: the self-stress below makes the geometric stiffness positive definite on every "
             "non-rigid mode (prestress stable)";
    case OrderReason::blocked_by_stress:
      return fmt::format("this mode does not extend to second order: the self-stress below does work {} on it (relative); "
                         "the mechanism space is not prestress stable, so other combinations of modes may move",
                         evidence(o.second_order_work));
    case OrderReason::rigid_motion: return "a rigid motion of the whole model";
    case OrderReason::traced:
      return fmt::format("passes second order (work {}) and was traced over {} with closure residual {} (relative)",
                         evidence(o.second_order_work), number(o.trace.amplitude), evidence(o.trace.max_residual));
    case OrderReason::trace_failed:
      return fmt::format("passes second order (work {}) but the trace lost closure at step {} (residual {}): "
                         "possibly blocked at a higher order",
                         evidence(o.second_order_work), o.trace.failed_step, evidence(o.trace.max_residual));
    case OrderReason::no_second_order_model:
      return "no second-order model for some element";
    case OrderReason::not_computed: return "second order not computed (model too large, or tracing off)";
  }
  return "";
}

// The path summary of a traced mode.
nlohmann::ordered_json trace_json(const framework::FiniteTrace& trace) {
  nlohmann::ordered_json t;
  t["amplitude"] = rounded(trace.amplitude);
  t["max_residual"] = evidence_number(trace.max_residual);
  t["rank_along_path"] = trace.rank_along_path;
  t["closed"] = trace.closed;
  t["rank_drops"] = trace.rank_drops;
  return t;
}

}  // namespace

std::vector<std::string> framework_generic_sentences(const FrameworkModel& model, const FrameworkResult& analysis,
                                                     const framework::GenericFramework& generic) {
  return generic_explanation(model, analysis, generic, false);
}

std::string framework_row_label(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index row) {
  const auto& d = row_ref(analysis, row);
  return model.elements[d.element].name + "." + deformation_name(model, d);
}

std::string framework_column_label(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index column) {
  const auto& c = column_ref(analysis, column);
  return model.nodes[c.node].name + "." + framework::kSlotNames[static_cast<std::size_t>(c.slot)];
}

std::string framework_classification(const FrameworkResult& a) {
  return fmt::format("statically {}, kinematically {}", a.statically_determinate() ? "determinate" : "indeterminate",
                     a.kinematically_determinate() ? "determinate" : "indeterminate");
}

namespace {

// Sections of framework_report_json, in the order of their keys.

// Model, counts and classification: "kind" to "count".
void add_count_keys(nlohmann::ordered_json& j, const FrameworkModel& model, const FrameworkResult& a,
                    const framework::GenericFramework* generic) {
  j["kind"] = "framework";
  if (!model.name.empty()) j["name"] = model.name;
  j["space"] = model.dimension == 2 ? "planar" : "spatial";
  j["dimension"] = model.dimension;
  j["rows"] = a.m;
  j["cols"] = a.n;
  j["rank"] = a.rank;
  j["classification"] = framework_classification(a);
  j["statically_determinate"] = a.statically_determinate();
  j["kinematically_determinate"] = a.kinematically_determinate();
  j["exactly_constrained"] = a.exactly_constrained();
  j["mechanisms"] = a.mechanisms;
  j["self_stresses"] = a.self_stresses;
  if (generic) j["generic"] = generic_json(model, a, *generic);
  const auto& c = a.count;
  j["count"] = {{"coordinates", c.coordinates},
                {"fixed_coordinates", c.fixed_coordinates},
                {"dependent_coordinates", c.dependent_coordinates},
                {"independent_coordinates", c.independent_coordinates},
                {"fixed_deformations", c.fixed_deformations},
                {"independent_deformations", c.independent_deformations},
                {"released_deformations", c.released_deformations},
                {"declared_dof", c.declared_dof()},
                {"grubler_dof", c.grubler_dof()},
                {"square", c.square()}};
}

// The rank decision and its evidence, and the labels of D(c)'s rows and columns: "method" to
// "column_labels".
void add_rank_keys(nlohmann::ordered_json& j, const FrameworkModel& model, const FrameworkResult& a) {
  j["method"] = a.method == framework::RankMethod::dense_svd ? "dense_svd" : "sparse_qr";
  j["characteristic_length"] = rounded(a.length);
  j["length_scaling"] = {{"row_factors", factor_range(a.row_scale)}, {"column_factors", factor_range(a.column_scale)}};
  j["rank_decision"] = rank_decision_json(a.decision, EvidenceDigits::ten_significant);
  // Unknown (null) on the sparse path, which computes no singular values.
  if (a.singular_values.size() == 0 && a.m > 0 && a.n > 0) j["relative_smallest_singular_value"] = nullptr;
  else j["relative_smallest_singular_value"] = significant(a.relative_smallest_singular_value());
  j["singular_values"] = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < a.singular_values.size(); ++i) j["singular_values"].push_back(significant(a.singular_values(i)));
  // One label per row and column (10^6 of them for a large lattice): the arrays are reserved
  // and filled through a reference, not looked up among the report's keys for every label.
  auto& row_labels = (j["row_labels"] = nlohmann::ordered_json::array()).get_ref<nlohmann::ordered_json::array_t&>();
  row_labels.reserve(static_cast<std::size_t>(a.m));
  for (Eigen::Index i = 0; i < a.m; ++i) row_labels.emplace_back(framework_row_label(model, a, i));
  auto& column_labels = (j["column_labels"] = nlohmann::ordered_json::array()).get_ref<nlohmann::ordered_json::array_t&>();
  column_labels.reserve(static_cast<std::size_t>(a.n));
  for (Eigen::Index i = 0; i < a.n; ++i) column_labels.emplace_back(framework_column_label(model, a, i));
}

// A stress state's resultants: {element, deformation, value} per row of D(c) listed.
nlohmann::ordered_json resultants_json(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& resultants,
                                       VectorListing listing) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  const double above = listed_above(resultants, listing);
  for (Eigen::Index i = 0; i < resultants.size(); ++i) {
    if (!(std::abs(resultants(i)) > above)) continue;
    const auto& ref = row_ref(a, i);
    nlohmann::ordered_json entry = json_object(3);
    entry["element"] = model.elements[ref.element].name;
    entry["deformation"] = deformation_name(model, ref);
    entry["value"] = rounded(resultants(i));
    list.push_back(std::move(entry));
  }
  return list;
}

// Mode k: velocities, moving coordinates, rigid parts, cause and order.
nlohmann::ordered_json mode_json(const FrameworkModel& model, const FrameworkResult& a, std::size_t k,
                                 const framework::GenericFramework* generic, VectorListing listing) {
  const auto& mode = a.modes[k];
  nlohmann::ordered_json m = json_object(8);
  m["velocities"] = velocities_by_node(model, a, mode.velocities, listing);
  m["moving"] = nlohmann::ordered_json::array();
  for (Eigen::Index col : mode.moving) m["moving"].push_back(framework_column_label(model, a, col));
  if (!mode.rigid_motion.empty()) {
    // A rigid motion of the whole model: no cause or order of its own (issue 35).
    m["rigid_motion"] = mode.rigid_motion;
    return m;
  }
  m["parts"] = parts_json(model, a, mode.velocities);
  if (generic && k < generic->mode_causes.size()) m["cause"] = linalg::cause_name(generic->mode_causes[k]);
  if (k < a.orders.size()) {
    const framework::ModeOrder& o = a.orders[k];
    m["order"] = framework::motion_order_name(o.order);
    m["order_reason"] = order_reason_code(o.reason);
    m["second_order_work"] = evidence_number(o.second_order_work);
    if (o.blocking_stress.size() > 0) m["blocking_stress"] = resultants_json(model, a, o.blocking_stress, listing);
    if (o.traced) m["trace"] = trace_json(o.trace);
  }
  return m;
}

nlohmann::ordered_json prestress_json(const FrameworkModel& model, const FrameworkResult& a, VectorListing listing) {
  nlohmann::ordered_json p = json_object(8);
  p["stable"] = a.prestress.stable;
  p["nonrigid_modes"] = a.prestress.nonrigid_modes;
  p["rigid_motions"] = a.prestress.rigid_motions;
  p["smallest_eigenvalue"] = evidence_number(a.prestress.smallest_eigenvalue);
  p["exhaustive"] = a.prestress.exhaustive;
  p["stress"] = resultants_json(model, a, a.prestress.stress, listing);
  return p;
}

nlohmann::ordered_json stresses_json(const FrameworkModel& model, const FrameworkResult& a, const framework::GenericFramework* generic,
                                     VectorListing listing) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < a.stresses.size(); ++k) {
    const auto& state = a.stresses[k];
    nlohmann::ordered_json s = json_object(4);
    s["resultants"] = resultants_json(model, a, state.resultants, listing);
    s["candidates"] = nlohmann::ordered_json::array();
    for (Eigen::Index row : state.candidates) s["candidates"].push_back(framework_row_label(model, a, row));
    if (generic && k < generic->stress_causes.size()) s["cause"] = linalg::cause_name(generic->stress_causes[k]);
    list.push_back(std::move(s));
  }
  return list;
}

// The proposal: one minimal set of releases and of coordinates to constrain.
void add_proposal_keys(nlohmann::ordered_json& j, const FrameworkModel& model, const FrameworkResult& a) {
  j["releases"] = nlohmann::ordered_json::array();
  for (Eigen::Index row : a.releases) {
    const auto& ref = row_ref(a, row);
    j["releases"].push_back({{"element", model.elements[ref.element].name}, {"deformation", deformation_name(model, ref)}});
  }
  j["constrain"] = nlohmann::ordered_json::array();
  for (Eigen::Index col : a.constrain) {
    const auto& ref = column_ref(a, col);
    j["constrain"].push_back(
        {{"node", model.nodes[ref.node].name}, {"coordinate", framework::kSlotNames[static_cast<std::size_t>(ref.slot)]}});
  }
}

}  // namespace

const char* vector_listing_name(VectorListing listing) { return listing == VectorListing::full ? "full" : "non_zero"; }

nlohmann::ordered_json framework_report_json(const FrameworkModel& model, const FrameworkResult& a, const design::Verdict* verdict,
                                             const framework::GenericFramework* generic, VectorListing listing,
                                             const framework::AnalysedCost* cost) {
  nlohmann::ordered_json j = json_object(48);
  add_count_keys(j, model, a, generic);
  add_rank_keys(j, model, a);
  j["vectors"] = a.vectors;
  j["vector_listing"] = vector_listing_name(listing);
  if (compact(a) && a.vectors) {
    // The first vector_limit of each, as basic null vectors of the sparse R factors.
    j["vector_limit"] = a.vector_limit;
    j["null_space_residual"] = evidence_number(a.null_space_residual);
  }
  auto& modes = (j["modes"] = nlohmann::ordered_json::array()).get_ref<nlohmann::ordered_json::array_t&>();
  for (std::size_t k = 0; k < a.modes.size(); ++k) modes.push_back(mode_json(model, a, k, generic, listing));
  if (a.prestress.tested) j["prestress_stability"] = prestress_json(model, a, listing);
  j["stresses"] = stresses_json(model, a, generic, listing);
  if (cost) j.update(analysed_cost_json(model, *cost));  // issue 38: stiffness, misfit, frequencies
  add_proposal_keys(j, model, a);
  if (verdict) return lead_with_verdict(*verdict, std::move(j), model.units);
  return j;
}

namespace {

// Sections of framework_report_text, in the order they are printed.

// The text report, one line at a time.
struct TextLines {
  std::string out;
  void operator()(const std::string& text) { out += text + "\n"; }
};

// Labels carry node and element names: printed through io::printable_text.
std::string printable_row_label(const FrameworkModel& model, const FrameworkResult& a, Eigen::Index row) {
  return io::printable_text(framework_row_label(model, a, row));
}
std::string printable_column_label(const FrameworkModel& model, const FrameworkResult& a, Eigen::Index column) {
  return io::printable_text(framework_column_label(model, a, column));
}

// The model, its coordinates and deformations and Gruebler's count.
void count_text(TextLines& line, const FrameworkModel& model, const FrameworkResult& a) {
  using io::printable_text;
  line(fmt::format("framework{} ({}, {} nodes, {} elements{})", model.name.empty() ? "" : " " + printable_text(model.name),
                   model.dimension == 2 ? "planar" : "spatial", model.nodes.size(), model.elements.size(),
                   model.units.empty() ? "" : ", lengths in " + printable_text(model.units)));
  const auto& c = a.count;
  line(fmt::format("coordinates: {} = {} fixed + {} dependent + {} independent", c.coordinates, c.fixed_coordinates,
                   c.dependent_coordinates, c.independent_coordinates));
  line(fmt::format("deformations: {} fixed + {} independent + {} released", c.fixed_deformations, c.independent_deformations,
                   c.released_deformations));
  line(fmt::format("Gruebler count (eq 15): n_dof = {} - ({} + {}) = {}; declared {} -> D(c) {}", c.coordinates,
                   c.fixed_coordinates, c.fixed_deformations, c.grubler_dof(), c.declared_dof(),
                   c.square() ? "square" : "not square"));
}

// D(c)'s rank, its decision and evidence, the classification and the counts.
void rank_section_text(TextLines& line, const FrameworkResult& a) {
  line(fmt::format("D(c): {} rows x {} columns, rank {} ({}{})", a.m, a.n, a.rank,
                   a.method == framework::RankMethod::dense_svd ? "SVD"
                   : a.vectors                                  ? "sparse QR"
                                                                : "sparse QR, counts only",
                   fmt::format(", characteristic length {}", number(a.length))));
  if (spread(a.row_scale) > kShownScaleSpread || spread(a.column_scale) > kShownScaleSpread) {
    const auto rows = factor_range(a.row_scale), cols = factor_range(a.column_scale);
    line(fmt::format("scaled by element lengths before the rank decision: row factors {} to {}, column factors {} to {}",
                     evidence(rows[0]), evidence(rows[1]), evidence(cols[0]), evidence(cols[1])));
  }
  line(fmt::format("rank decision: threshold {}, smallest kept {}{}, largest dropped {}", evidence(a.decision.threshold),
                   evidence(a.decision.smallest_kept),
                   a.decision.factor_estimated ? fmt::format(" (sigma_min of the kept block R11 about {})", evidence(a.decision.factor_smallest))
                                               : std::string(),
                   evidence(a.decision.largest_dropped)));
  line(fmt::format("  {}", rank_status_text(a.decision)));
  // Said only when it is so (issue 35): the coordinates reach several sizes of the model from
  // the origin (input_rounding = ε × largest coordinate / size), not for a model centred there.
  constexpr double kFarFromOrigin = 4.0;
  if (a.decision.threshold == a.decision.rounding_level && a.decision.input_rounding > kFarFromOrigin * kEpsilon)
    line(fmt::format("threshold raised to the rounding of the input: the coordinates, {:.3g} times the model's size from the "
                     "origin, fix its geometry only to {} of that size",
                     a.decision.input_rounding / kEpsilon, evidence(a.decision.input_rounding)));
  if (a.singular_values.size() > 0)
    line(fmt::format("smallest/largest singular value: {}", evidence(a.relative_smallest_singular_value())));
  line(fmt::format("classification: {}", framework_classification(a)));
  line(fmt::format("{} extra motion(s) (mechanisms: the seed's kinematically indeterminate modes), {} redundant constraint(s) "
                   "(self-stresses){}",
                   a.mechanisms, a.self_stresses, a.exactly_constrained() ? ": exactly constrained" : ""));
}

// The generic answer, its explanation and the Laman count.
void generic_section_text(TextLines& line, const FrameworkModel& model, const FrameworkResult& a, const framework::GenericFramework& generic) {
  line(fmt::format("generic answer (the same nodes, elements and supports at a random realisation): {} mode(s), {} stress state(s); {}",
                   generic.mechanisms, generic.self_stresses, generic_method(generic)));
  for (const auto& sentence : generic_explanation(model, a, generic, true)) line("  " + sentence);
  if (generic.laman) {
    std::vector<std::string> components;
    for (const auto& component : generic.laman->rigid_components) components.push_back(component_text(model, component));
    line(fmt::format("  Laman count (pebble game): rank {}, {} mode(s), {} stress state(s){}; rigid components: {}", generic.laman->rank,
                     generic.laman->mechanisms, generic.laman->self_stresses,
                     generic.laman->rank == generic.rank ? ", agrees" : ", DISAGREES with the generic rank",
                     components.empty() ? "-" : fmt::format("{}", fmt::join(components, " "))));
  }
}

// A self-stress that blocks or stabilises, its resultants above kModeZero.
void stress_lines(TextLines& line, const FrameworkModel& model, const FrameworkResult& a, const std::string& title,
                  const Eigen::VectorXd& resultants) {
  line(title);
  for (Eigen::Index row = 0; row < resultants.size(); ++row)
    if (std::abs(resultants(row)) > kModeZero)
      line(fmt::format("  {:>24} {:>12}", printable_row_label(model, a, row), number(resultants(row))));
}

// Mode k: its cause, rigid parts, velocities and order.
void mode_text(TextLines& line, const FrameworkModel& model, const FrameworkResult& a, std::size_t k,
               const framework::GenericFramework* generic) {
  const bool rigid = !a.modes[k].rigid_motion.empty();
  const std::string cause = rigid ? ": rigid-body motion, " + a.modes[k].rigid_motion
                            : generic && k < generic->mode_causes.size() ? ", from the " + linalg::cause_name(generic->mode_causes[k])
                                                                         : "";
  line(fmt::format("mode {} (velocities; translations per characteristic length){}{}", k + 1, cause, rigid ? "" : ":"));
  if (!rigid) {
    const auto parts = framework::moving_parts(model, a, a.modes[k].velocities);
    for (std::size_t p = 0; p < parts.size() && p < kTextParts; ++p)
      line(fmt::format("  rigid part {}: {}", part_label(model, parts[p]), design::motion_text(parts[p].twist, a.length)));
    if (parts.size() > kTextParts) line(fmt::format("  ... and {} more rigid parts (see --json)", parts.size() - kTextParts));
  }
  for (Eigen::Index col : a.modes[k].moving)
    line(fmt::format("  {:>16} {:>12}", printable_column_label(model, a, col), number(a.modes[k].velocities(col))));
  if (rigid || k >= a.orders.size()) return;
  const framework::ModeOrder& o = a.orders[k];
  line(fmt::format("  order: {} -- {}", framework::motion_order_name(o.order), order_reason_text(o)));
  if (o.reason == framework::OrderReason::blocked_by_stress) stress_lines(line, model, a, "  blocking self-stress:", o.blocking_stress);
  if (o.traced) {
    line(fmt::format("  rank of D(c) along the path: {}", fmt::join(o.trace.rank_along_path, " ")));
    if (!o.trace.rank_drops.empty())
      line(fmt::format("  rank drops at point(s) {} (0 = the start): a singular configuration -- branch point or change of mobility",
                       fmt::join(o.trace.rank_drops, ", ")));
  }
}

void prestress_text(TextLines& line, const FrameworkModel& model, const FrameworkResult& a) {
  line(fmt::format("prestress stability ({} non-rigid mode(s), {} rigid motion(s); search {}): {}, smallest eigenvalue {} "
                   "(relative)",
                   a.prestress.nonrigid_modes, a.prestress.rigid_motions,
                   a.prestress.exhaustive ? "exhaustive over the stress combinations" : "sampled, may miss one",
                   a.prestress.stable ? "STABLE -- every non-rigid mode is blocked at second order" : "not stable",
                   evidence(a.prestress.smallest_eigenvalue)));
  if (a.prestress.stable) stress_lines(line, model, a, "  the stabilising self-stress (positive: tension):", a.prestress.stress);
}

// Stress state k: its cause and non-zero resultants.
void stress_state_text(TextLines& line, const FrameworkModel& model, const FrameworkResult& a, std::size_t k,
                       const framework::GenericFramework* generic) {
  const std::string cause =
      generic && k < generic->stress_causes.size() ? ", from the " + linalg::cause_name(generic->stress_causes[k]) : "";
  line(fmt::format("stress state {} (generalised stress resultants){}:", k + 1, cause));
  for (Eigen::Index row = 0; row < a.stresses[k].resultants.size(); ++row)
    if (a.stresses[k].resultants(row) != 0.0)
      line(fmt::format("  {:>24} {:>12}", printable_row_label(model, a, row), number(a.stresses[k].resultants(row))));
}

// The proposal (releases, coordinates to constrain), or why there is none.
void proposal_text(TextLines& line, const FrameworkModel& model, const FrameworkResult& a) {
  if (!a.releases.empty()) {
    std::string list;
    for (Eigen::Index row : a.releases) list += (list.empty() ? "" : ", ") + printable_row_label(model, a, row);
    line("release (one minimal set): " + list);
  }
  if (!a.constrain.empty()) {
    std::string list;
    for (Eigen::Index col : a.constrain) list += (list.empty() ? "" : ", ") + printable_column_label(model, a, col);
    line("constrain or declare independent (one minimal set): " + list);
  }
  if (!a.vectors && (a.mechanisms > 0 || a.self_stresses > 0))
    line("(model too large for the dense SVD: modes and stress states not computed; --vectors K gives the first K)");
}

}  // namespace

std::string framework_report_text(const FrameworkModel& model, const FrameworkResult& a, const design::Verdict* verdict,
                                  const framework::GenericFramework* generic, const framework::AnalysedCost* cost) {
  TextLines line;
  if (verdict) line.out = verdict_text(*verdict);
  if (cost) line.out += analysed_cost_text(model, *cost);  // issue 38: the cost of over-constraint
  count_text(line, model, a);
  rank_section_text(line, a);
  if (generic) generic_section_text(line, model, a, *generic);
  if (compact(a) && a.vectors)
    line(fmt::format("vectors from the sparse R factors: first {} of {} mode(s), first {} of {} stress state(s); "
                     "largest relative residual {}",
                     a.modes.size(), a.mechanisms, a.stresses.size(), a.self_stresses, evidence(a.null_space_residual)));
  for (std::size_t k = 0; k < a.modes.size(); ++k) mode_text(line, model, a, k, generic);
  if (a.prestress.tested) prestress_text(line, model, a);
  for (std::size_t k = 0; k < a.stresses.size(); ++k) stress_state_text(line, model, a, k, generic);
  proposal_text(line, model, a);
  return line.out;
}

}  // namespace kinestat::report
