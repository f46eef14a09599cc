// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/network_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/report/generic_text.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/linear_form_text.hpp"
#include "kinestat/report/rank_status_text.hpp"
#include "kinestat/report/verdict_report.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::report {

namespace {

using network::LinearForms;
using network::NetworkResult;
using Index = Eigen::Index;
using Json = nlohmann::ordered_json;
using io::printable_text;

// Names as the text reports print them: control characters escaped (io::printable_text).
std::vector<std::string> printable_names(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  out.reserve(names.size());
  for (const auto& name : names) out.push_back(printable_text(name));
  return out;
}

std::vector<std::string> names_of(const std::vector<int>& indices, const std::vector<network::Magnitude>& magnitudes) {
  std::vector<std::string> names;
  for (int i : indices) names.push_back(magnitudes[static_cast<std::size_t>(i)].name);
  return names;
}

// Coefficients this small relative to the largest are rounding noise in floating point.
double noise_level(const LinearForms& forms) {
  if (forms.exact || forms.values.size() == 0) return 0.0;
  return kCoefficientZero * forms.values.cwiseAbs().maxCoeff();
}

std::vector<std::string> coordinate_letters(const NetworkResult& r, bool motion) {
  const auto& letters = motion ? screw::kMotionLetters : screw::kActionLetters;
  std::vector<std::string> out;
  const std::vector<int> components = r.d == 6 ? std::vector<int>{0, 1, 2, 3, 4, 5} : std::vector<int>{2, 3, 4};
  for (int c : components) out.emplace_back(1, letters[static_cast<std::size_t>(c)]);
  return out;
}

std::string rank_text(const char* symbol, const linalg::RankDecision& rank) {
  if (rank.exact) return fmt::format("{} = {} (exact)", symbol, rank.rank);
  const std::string factor =
      rank.factor_estimated ? fmt::format(", sigma_min of the kept block R11 about {}", number_text(rank.factor_smallest)) : "";
  return fmt::format("{} = {} (smallest kept singular value {}{}, largest dropped {}, gap {})", symbol, rank.rank,
                     number_text(rank.smallest_kept), factor, number_text(rank.largest_dropped),
                     std::isinf(rank.gap()) ? "infinite" : number_text(rank.gap()));
}

std::vector<std::string> warnings(const NetworkResult& r) {
  std::vector<std::string> list;
  if (r.circulation.solution.rank.close())
    list.push_back("the rank m of the network unit motion matrix is a close decision: the geometry is near one with a different FN and CN");
  if (r.cutset_law.solution.rank.close())
    list.push_back("the rank a of the network unit action matrix is a close decision: the geometry is near one with a different FN and CN");
  if (!r.identities_hold) list.push_back("the identities FN - CN = F - d*l and CN - FN = C - d*k do not all hold (numerical trouble)");
  if (!r.motion_methods_agree) list.push_back("the circulation law and the cutset-motion method give different motion matrices");
  if (!r.action_methods_agree) list.push_back("the cutset law and the circuit-action method give different action matrices");
  if (r.floating_point_disagreement)
    list.push_back(fmt::format("floating point gives FN = {}, CN = {}: the model's long decimals are probably rounded; "
                               "consider --float",
                               r.floating_point_disagreement->first, r.floating_point_disagreement->second));
  return list;
}

Json body_json(const std::string& name) {
  const bool integer = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) { return ch >= '0' && ch <= '9'; }) &&
                       name.size() < 10;
  return integer ? Json(std::stoi(name)) : Json(name);
}

// A pair's bodies, direct coupling and counts, as both the dense and the sparse report write them.
template <class Pair>
Json pair_counts_json(const network::Model& model, const Pair& p) {
  Json pair;
  pair["bodies"] = {body_json(model.bodies[static_cast<std::size_t>(p.body_i)]), body_json(model.bodies[static_cast<std::size_t>(p.body_j)])};
  pair["coupling"] = p.coupling ? Json(model.couplings[static_cast<std::size_t>(*p.coupling)].name) : Json(nullptr);
  pair["f"] = p.f;
  pair["fij"] = p.fij;
  pair["c"] = p.c;
  pair["cij"] = p.cij;
  return pair;
}

Json rank_json(const linalg::RankDecision& rank) { return rank_decision_json(rank); }

Json expressions_json(const LinearForms& forms, Index first_row, Index rows, const std::vector<std::string>& primaries) {
  Json list = Json::array();
  const double noise = noise_level(forms);
  for (Index r = 0; r < rows; ++r) list.push_back(linear_form_text(forms, first_row + r, primaries, noise));
  return list;
}

Json int_matrix_json(const Eigen::MatrixXi& m) {
  Json rows = Json::array();
  for (Index r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    rows.push_back(row);
  }
  return rows;
}

Json rational_matrix_json(const linalg::RationalMatrix& m) {
  Json rows = Json::array();
  for (Index r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (Index c = 0; c < m.cols(); ++c) {
      const linalg::Rational& x = m(r, c);
      if (x.get_den() == 1 && abs(x) < 1000000000) {
        row.push_back(x.get_num().get_si());
      } else {
        row.push_back(x.get_d());
      }
    }
    rows.push_back(row);
  }
  return rows;
}

std::string int_matrix_text(const Eigen::MatrixXi& m) {
  std::string text;
  for (Index r = 0; r < m.rows(); ++r) {
    text += "   ";
    for (Index c = 0; c < m.cols(); ++c) text += fmt::format(" {:>2}", m(r, c));
    text += "\n";
  }
  return text;
}

std::string rational_matrix_text(const linalg::RationalMatrix& m) {
  std::vector<std::string> cells;
  std::size_t width = 1;
  for (Index r = 0; r < m.rows(); ++r)
    for (Index c = 0; c < m.cols(); ++c) {
      cells.push_back(sgn(m(r, c)) == 0 ? "0" : (m(r, c).get_den() == 1 ? m(r, c).get_str() : number_text(m(r, c).get_d())));
      width = std::max(width, cells.back().size());
    }
  std::string text;
  for (Index r = 0; r < m.rows(); ++r) {
    text += "   ";
    for (Index c = 0; c < m.cols(); ++c) text += fmt::format(" {:>{}}", cells[static_cast<std::size_t>(r * m.cols() + c)], width);
    text += "\n";
  }
  return text;
}

// [M]d,e or [A]d,e: rows are coordinates, columns couplings.
std::string contracted_text(const network::Model& model, const NetworkResult& r, const LinearForms& forms,
                            const std::vector<std::string>& primaries, bool motion) {
  const double noise = noise_level(forms);
  std::vector<std::vector<std::string>> cells(static_cast<std::size_t>(r.d));
  std::vector<std::size_t> width(static_cast<std::size_t>(r.e), 1);
  for (int e = 0; e < r.e; ++e) {
    width[static_cast<std::size_t>(e)] = printable_text(model.couplings[static_cast<std::size_t>(e)].name).size();
    for (int c = 0; c < r.d; ++c) {
      cells[static_cast<std::size_t>(c)].push_back(linear_form_text(forms, e * r.d + c, primaries, noise));
      width[static_cast<std::size_t>(e)] = std::max(width[static_cast<std::size_t>(e)], cells[static_cast<std::size_t>(c)].back().size());
    }
  }
  std::string text = "      ";
  for (int e = 0; e < r.e; ++e)
    text += fmt::format("  {:>{}}", printable_text(model.couplings[static_cast<std::size_t>(e)].name), width[static_cast<std::size_t>(e)]);
  text += "\n";
  const auto letters = coordinate_letters(r, motion);
  for (int c = 0; c < r.d; ++c) {
    text += fmt::format("    {} ", letters[static_cast<std::size_t>(c)]);
    for (int e = 0; e < r.e; ++e)
      text += fmt::format("  {:>{}}", cells[static_cast<std::size_t>(c)][static_cast<std::size_t>(e)], width[static_cast<std::size_t>(e)]);
    text += "\n";
  }
  return text;
}

// A numeric value, or "?" when it depends on a primary that was given no value.
std::string value_text(double value) { return std::isnan(value) ? "?" : number_text(value); }
// The same in JSON: null when undetermined.
Json value_json(double value) { return std::isnan(value) ? Json(nullptr) : Json(value); }

std::string joined_or_dash(const std::vector<std::string>& names) { return names.empty() ? "-" : fmt::format("{}", fmt::join(names, ", ")); }

std::string generic_method(const network::GenericNetwork& g) {
  return fmt::format("rank of M^N at {} random realisations of the same couplings, each modulo {} primes (exact)", g.realisations,
                     g.primes);
}

std::vector<std::string> special_coupling_names(const network::Model& model, const network::GenericNetwork& g) {
  std::vector<std::string> names;
  if (g.special_couplings)
    for (int e : *g.special_couplings) names.push_back(model.couplings[static_cast<std::size_t>(e)].name);
  return names;
}

// The primaries of one cause, e.g. "sa, ta".
std::vector<std::string> primaries_of(const std::vector<std::string>& primaries, const std::vector<network::Cause>& causes,
                                      network::Cause cause) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < primaries.size() && i < causes.size(); ++i)
    if (causes[i] == cause) out.push_back(primaries[i]);
  return out;
}

std::string generic_text(const network::Model& model, const NetworkResult& r, const network::GenericNetwork& g,
                         const std::vector<std::string>& motion_primaries, const std::vector<std::string>& action_primaries) {
  const auto involved = printable_names(special_coupling_names(model, g));
  std::string t = fmt::format("Generic answer (the same couplings at a random realisation): FN = {}, CN = {}; m = {} by the {}\n", g.FN,
                              g.CN, g.m, generic_method(g));
  t += "  " + generic_count_text("FN", r.FN, g.FN, involved, "couplings") + "\n";
  t += "  " + generic_count_text("CN", r.CN, g.CN, involved, "couplings") + "\n";
  auto causes_line = [&](const char* what, const std::vector<std::string>& primaries, const std::vector<network::Cause>& causes) {
    const auto topology = primaries_of(primaries, causes, network::Cause::topology);
    const auto geometry = primaries_of(primaries, causes, network::Cause::geometry);
    if (!primaries.empty())
      t += fmt::format("  {} by primary variable: topology {}; geometry {}\n", what, joined_or_dash(topology), joined_or_dash(geometry));
  };
  causes_line("motions", motion_primaries, g.motion_causes);
  causes_line("self-stresses", action_primaries, g.action_causes);
  if (g.special_couplings && !g.special_couplings->empty())
    t += fmt::format("  special geometry: a random change of any one of couplings {} alone removes a special motion or self-stress\n",
                     fmt::join(involved, ", "));
  return t;
}

// Second order (issue 13): one line per primary motion, then prestress stability.
std::string second_order_text(const network::NetworkSecondOrder& s, const std::vector<std::string>& motion_primaries) {
  std::string t = "Second order (Lie brackets of the coupling twists around each circuit):\n";
  if (!s.unmodelled_couplings.empty()) {
    std::vector<std::string> names;
    for (const auto& n : s.unmodelled_couplings) names.push_back(printable_text(n));
    t += fmt::format("  not classified: couplings {} are higher pairs or custom screws, whose finite motion needs curvatures the model "
                     "does not give\n",
                     fmt::join(names, ", "));
    return t;
  }
  const auto residual = [](double value) { return fmt::format("{:.3g}", rank_evidence_number(value)); };
  for (std::size_t k = 0; k < s.motions.size() && k < motion_primaries.size(); ++k) {
    const auto& m = s.motions[k];
    std::string why;
    switch (m.reason) {
      case network::NetworkOrderReason::blocked_by_stress:
        why = fmt::format("a self-stress does work on it at second order (relative {:.3g}): it cannot move finitely", m.second_order_work);
        break;
      case network::NetworkOrderReason::prestress_stable:
        why = "a combination of the self-stresses blocks every motion at once (prestress stable)";
        break;
      case network::NetworkOrderReason::passes_second_order:
        why = "no self-stress does work on it at second order; a finite motion is possible (not traced)";
        break;
      case network::NetworkOrderReason::no_self_stress: why = "CN = 0: nothing blocks it at second order (not traced)"; break;
      case network::NetworkOrderReason::traced:
        why = fmt::format("passes second order (work {:.3g}) and was traced over {} with closure residual {} (relative)",
                          m.second_order_work, fmt::format("{:.6g}", rounded_for_report(m.trace.amplitude)), residual(m.trace.max_residual));
        break;
      case network::NetworkOrderReason::trace_failed:
        why = fmt::format("passes second order (work {:.3g}) but the trace lost closure at step {} (residual {}): possibly blocked at a "
                          "higher order",
                          m.second_order_work, m.trace.failed_step, residual(m.trace.max_residual));
        break;
      case network::NetworkOrderReason::no_second_order_model: why = "not classified (model too large or space not modelled)"; break;
    }
    t += fmt::format("  motion {}: {}: {}\n", printable_text(motion_primaries[k]), network::network_motion_order_name(m.order), why);
    if (m.traced && !m.trace.rank_drops.empty())
      t += fmt::format("    rank of the closure Jacobian along the path: {}; it drops at point(s) {} (0 = the start): a singular "
                       "configuration -- branch point or change of mobility\n",
                       fmt::join(m.trace.rank_along_path, " "), fmt::join(m.trace.rank_drops, ", "));
  }
  return t;
}

// The path summary of a traced motion: the keys of a traced framework mode.
Json trace_json(const network::NetworkTrace& trace) {
  Json t;
  t["amplitude"] = rounded_for_report(trace.amplitude);
  t["max_residual"] = rank_evidence_number(trace.max_residual);
  t["rank_along_path"] = trace.rank_along_path;
  t["closed"] = trace.closed;
  t["rank_drops"] = trace.rank_drops;
  return t;
}

Json second_order_json(const network::NetworkSecondOrder& s, const std::vector<std::string>& motion_primaries) {
  Json j;
  Json motions = Json::array();
  for (std::size_t k = 0; k < s.motions.size() && k < motion_primaries.size(); ++k) {
    const auto& m = s.motions[k];
    Json motion;
    motion["primary"] = motion_primaries[k];
    motion["order"] = network::network_motion_order_name(m.order);
    motion["order_reason"] = network::network_order_reason_name(m.reason);
    motion["second_order_work"] = std::round(m.second_order_work * 1e9) / 1e9;
    if (m.blocking_stress.size() > 0) {
      Json stress = Json::array();
      for (Eigen::Index i = 0; i < m.blocking_stress.size(); ++i) stress.push_back(std::round(m.blocking_stress(i) * 1e9) / 1e9);
      motion["blocking_stress"] = stress;
    }
    if (m.traced) motion["trace"] = trace_json(m.trace);
    motions.push_back(motion);
  }
  j["motions"] = motions;
  j["prestress_stability"] = {{"tested", s.prestress_tested},
                              {"stable", s.prestress_stable},
                              {"smallest_eigenvalue", std::round(s.smallest_eigenvalue * 1e9) / 1e9}};
  j["unmodelled_couplings"] = s.unmodelled_couplings;
  return j;
}

Json generic_json(const network::Model& model, const NetworkResult& r, const network::GenericNetwork& g,
                  const std::vector<std::string>& motion_primaries, const std::vector<std::string>& action_primaries) {
  Json j;
  j["FN"] = g.FN;
  j["CN"] = g.CN;
  j["rank_motion"] = g.m;
  j["method"] = generic_method(g);
  j["special"] = {{"FN", r.FN - g.FN}, {"CN", r.CN - g.CN}};
  auto states = [](const std::vector<std::string>& primaries, const std::vector<network::Cause>& causes) {
    Json out = Json::array();
    for (std::size_t i = 0; i < primaries.size() && i < causes.size(); ++i)
      out.push_back({{"primary", primaries[i]}, {"cause", network::cause_name(causes[i])}});
    return out;
  };
  j["motions"] = states(motion_primaries, g.motion_causes);
  j["self_stresses"] = states(action_primaries, g.action_causes);
  j["split_residual"] = std::round(g.split_residual * 1e6) / 1e6;
  if (g.special_couplings) j["special_couplings"] = special_coupling_names(model, g);
  else j["special_couplings"] = nullptr;
  j["explanation"] = network_generic_sentences(model, r, g);
  return j;
}


}  // namespace

std::vector<std::string> network_generic_sentences(const network::Model& model, const NetworkResult& r, const network::GenericNetwork& g) {
  const auto involved = special_coupling_names(model, g);
  return {generic_count_text("FN", r.FN, g.FN, involved, "couplings"), generic_count_text("CN", r.CN, g.CN, involved, "couplings")};
}

namespace {

// Sections of network_report_text and network_report_json, in the order they are written.

// The counts: bodies, couplings, circuits, cutsets, the two ranks and their evidence, FN, CN,
// the class and Davies' identities.
std::string network_counts_text(const network::Model& model, const NetworkResult& r) {
  std::string t = fmt::format("{}\n", r.model_name.empty() ? "Coupling network" : printable_text(r.model_name));
  t += fmt::format("  coupling network, {} (d = {}){}; {}\n", r.d == 6 ? "spatial" : "planar", r.d,
                   model.units.empty() ? "" : ", lengths in " + printable_text(model.units), printable_text(r.arithmetic_reason));
  t += fmt::format("  bodies n = {}, couplings e = {}, circuits l = {}, cutsets k = {}\n", r.bodies, r.e, r.l, r.k);
  t += fmt::format("  gross degree of freedom F = {}, gross degree of constraint C = {}\n", r.F, r.C);
  t += fmt::format("  rank of the network unit motion matrix: {}\n", rank_text("m", r.circulation.solution.rank));
  t += fmt::format("    {}\n", rank_status_text(r.circulation.solution.rank));
  t += fmt::format("  rank of the network unit action matrix: {}\n", rank_text("a", r.cutset_law.solution.rank));
  t += fmt::format("    {}\n", rank_status_text(r.cutset_law.solution.rank));
  if (r.modular_check)
    t += fmt::format("  modular check: M^N has rank {} modulo {} large primes ({} agree), a certain lower bound of its exact rank; {}\n",
                     r.modular_check->rank, r.modular_check->primes, r.modular_check->agreeing,
                     r.modular_check->followed ? "the floating-point decisions were moved to it" : "the floating-point decision agrees");
  t += fmt::format("  nett degree of freedom    FN = {}\n", r.FN);
  t += fmt::format("  nett degree of constraint CN = {}\n", r.CN);
  t += fmt::format("  class: {}\n", network::class_description(r.classification));
  t += fmt::format("  identities FN = F - m = d*k - a, CN = C - a = d*l - m, FN - CN = F - d*l: {}\n",
                   r.identities_hold ? "hold" : "FAIL");
  return t;
}

// The magnitudes of a law as linear forms of the primaries, with their values when given.
std::string magnitudes_text(const char* title, const std::vector<network::Magnitude>& magnitudes, const LinearForms& forms,
                            const std::vector<std::string>& primaries, const std::optional<Eigen::VectorXd>& values) {
  std::string t = fmt::format("{}\n", title);
  const double noise = noise_level(forms);
  for (std::size_t i = 0; i < magnitudes.size(); ++i) {
    t += fmt::format("  {:<10} = {}", printable_text(magnitudes[i].name), linear_form_text(forms, static_cast<Index>(i), primaries, noise));
    if (values) t += fmt::format("   = {}", value_text((*values)(static_cast<Index>(i))));
    t += "\n";
  }
  return t;
}

// Each coupling's numeric screw (a column of `columns`).
std::string numeric_screws_text(const network::Model& model, const NetworkResult& r, const char* title, const Eigen::MatrixXd& columns) {
  std::string t = fmt::format("\n{}\n", title);
  for (int e = 0; e < r.e; ++e) {
    std::vector<std::string> coordinates;
    for (int c = 0; c < r.d; ++c) coordinates.push_back(value_text(columns(c, e)));
    t += fmt::format("  {:<10} ({})\n", printable_text(model.couplings[static_cast<std::size_t>(e)].name), fmt::join(coordinates, ", "));
  }
  return t;
}

// The pairs of bodies (seed 000, Table 1) with their freedoms, constraints and primaries.
std::string pairs_text(const network::Model& model, const NetworkResult& r, const std::vector<std::string>& motion_primaries,
                       const std::vector<std::string>& action_primaries) {
  std::string t = "\nPairs of bodies (seed 000, Table 1; an absent coupling counts as f = d, c = 0):\n";
  t += fmt::format("  {:<12} {:<10} {:>3} {:>4}  {:<18} {:>3} {:>4}  {}\n", "bodies", "coupling", "f", "fij",
                   "motion primaries", "c", "cij", "action primaries");
  for (const auto& p : r.pairs) {
    const std::string bodies = printable_text(model.bodies[static_cast<std::size_t>(p.body_i)]) + ", " +
                               printable_text(model.bodies[static_cast<std::size_t>(p.body_j)]);
    const std::string coupling = p.coupling ? printable_text(model.couplings[static_cast<std::size_t>(*p.coupling)].name) : "absent";
    std::vector<std::string> mp, ap;
    for (int i : p.motion_primaries) mp.push_back(motion_primaries[static_cast<std::size_t>(i)]);
    for (int i : p.action_primaries) ap.push_back(action_primaries[static_cast<std::size_t>(i)]);
    t += fmt::format("  {:<12} {:<10} {:>3} {:>4}  {:<18} {:>3} {:>4}  {}\n", bodies, coupling, p.f, p.fij, joined_or_dash(mp), p.c,
                     p.cij, joined_or_dash(ap));
  }
  return t;
}

// `--matrices`: B, Q, BM, QA and the unit matrices.
std::string matrices_text(const NetworkResult& r) {
  std::string t = "\nCircuit matrix [B]l,e:\n" + int_matrix_text(r.B);
  t += "Cutset matrix [Q]k,e:\n" + int_matrix_text(r.Q);
  t += "Motion-graph circuit matrix [BM]l,F:\n" + int_matrix_text(r.BM);
  t += "Action-graph cutset matrix [QA]k,C:\n" + int_matrix_text(r.QA);
  t += "Unit motion matrix [M^D]d,F:\n" + rational_matrix_text(r.MD);
  t += "Unit action matrix [A^D]d,C:\n" + rational_matrix_text(r.AD);
  t += "Network unit motion matrix [M^N]dl,F:\n" + rational_matrix_text(r.MN);
  t += "Network unit action matrix [A^N]dk,C:\n" + rational_matrix_text(r.AN);
  return t;
}

// Missing values, whether the two methods agree, and the warnings.
std::string checks_text(const NetworkResult& r) {
  std::string t;
  if (!r.missing_motion_values.empty())
    t += fmt::format("\nValues: no value for the motion primaries {}; what depends on them is shown as ?\n",
                     fmt::join(printable_names(r.missing_motion_values), ", "));
  if (!r.missing_action_values.empty())
    t += fmt::format("\nValues: no value for the action primaries {}; what depends on them is shown as ?\n",
                     fmt::join(printable_names(r.missing_action_values), ", "));
  t += fmt::format("\nMethods agree: circulation law and cutset motions {}; cutset law and circuit actions {}\n",
                   r.motion_methods_agree ? "yes" : "NO", r.action_methods_agree ? "yes" : "NO");
  return t;
}

std::string warnings_text(const NetworkResult& r) {
  const auto warning_list = warnings(r);
  if (warning_list.empty()) return {};
  std::string t = "\nWarnings:\n";
  for (const auto& w : warning_list) t += "  - " + w + "\n";
  return t;
}

}  // namespace

std::string network_report_text(const network::Model& model, const NetworkResult& r, const NetworkReportOptions& options) {
  const auto motion_primaries = printable_names(names_of(r.primary_motion, r.motions));
  const auto action_primaries = printable_names(names_of(r.primary_action, r.actions));
  const auto coupling_name = [&](std::size_t e) { return printable_text(model.couplings[e].name); };
  std::string t = options.verdict ? verdict_text(*options.verdict) : std::string();
  t += network_counts_text(model, r);
  t += "\n";
  if (options.generic) t += generic_text(model, r, *options.generic, motion_primaries, action_primaries) + "\n";
  if (options.second_order) t += second_order_text(*options.second_order, motion_primaries) + "\n";
  std::vector<std::string> branch_names, chord_names;
  for (int b : r.branches) branch_names.push_back(coupling_name(static_cast<std::size_t>(b)));
  for (int c : r.chords) chord_names.push_back(coupling_name(static_cast<std::size_t>(c)));
  t += fmt::format("Spanning tree: branches {}; chords {}\n", joined_or_dash(branch_names), joined_or_dash(chord_names));
  t += fmt::format("Primary variables: motions {}; actions {}\n", joined_or_dash(motion_primaries), joined_or_dash(action_primaries));
  t += "\n";
  t += magnitudes_text("Motion magnitudes [c]F (circulation law):", r.motions, r.motion_magnitudes, motion_primaries, r.motion_values);
  t += magnitudes_text("Action magnitudes [C]C (cutset law):", r.actions, r.action_magnitudes, action_primaries, r.action_values);
  t += "\nMotion matrix [M]d,e (motion of each coupling's second body relative to its first):\n";
  t += contracted_text(model, r, r.circulation.contracted, motion_primaries, true);
  t += "\nAction matrix [A]d,e (action transmitted by each coupling):\n";
  t += contracted_text(model, r, r.cutset_law.contracted, action_primaries, false);
  if (r.coupling_motion_values) t += numeric_screws_text(model, r, "Numeric motion of each coupling (axis formation):", *r.coupling_motion_values);
  if (r.coupling_action_values) t += numeric_screws_text(model, r, "Numeric action of each coupling (ray formation):", *r.coupling_action_values);
  t += checks_text(r);
  t += pairs_text(model, r, motion_primaries, action_primaries);
  if (options.matrices) t += matrices_text(r);
  t += warnings_text(r);
  return t;
}

namespace {

// The model and its counts: "kind" to "identities_hold".
void add_network_count_keys(Json& j, const network::Model& model, const NetworkResult& r) {
  j["kind"] = "network";
  j["name"] = r.model_name;
  j["space"] = r.d == 6 ? "spatial" : "planar";
  j["dimension"] = r.d;
  j["arithmetic"] = r.exact ? "exact" : "floating";
  j["arithmetic_reason"] = r.arithmetic_reason;
  Json bodies = Json::array();
  for (const auto& b : model.bodies) bodies.push_back(body_json(b));
  j["bodies"] = bodies;
  j["n"] = r.bodies;
  j["e"] = r.e;
  j["F"] = r.F;
  j["C"] = r.C;
  j["l"] = r.l;
  j["k"] = r.k;
  j["rank_motion"] = r.m;
  j["rank_action"] = r.a;
  j["FN"] = r.FN;
  j["CN"] = r.CN;
  j["classification"] = network::class_id(r.classification);
  j["classification_description"] = network::class_description(r.classification);
  j["identities_hold"] = r.identities_hold;
}

// The evidence of both ranks (and the modular check), and the length scale of floating point.
void add_rank_evidence_keys(Json& j, const NetworkResult& r) {
  j["rank_evidence"] = {{"motion", rank_json(r.circulation.solution.rank)}, {"action", rank_json(r.cutset_law.solution.rank)}};
  if (r.modular_check)
    j["rank_evidence"]["modular"] = {{"rank_motion", r.modular_check->rank},
                                     {"primes", r.modular_check->primes},
                                     {"agreeing", r.modular_check->agreeing},
                                     {"followed", r.modular_check->followed}};
  if (!r.exact) j["length_scale"] = r.length_scale;
}

// Each magnitude as a linear form of the primaries: name -> text.
Json magnitudes_json(const std::vector<network::Magnitude>& magnitudes, const LinearForms& forms, const std::vector<std::string>& primaries) {
  Json out = Json::object();
  const double noise = noise_level(forms);
  for (std::size_t i = 0; i < magnitudes.size(); ++i)
    out[magnitudes[i].name] = linear_form_text(forms, static_cast<Index>(i), primaries, noise);
  return out;
}

// Each magnitude's unit screw and coupling.
Json unit_screws_json(const network::Model& model, const std::vector<network::Magnitude>& magnitudes) {
  Json out = Json::array();
  for (const auto& m : magnitudes) {
    Json coordinates = Json::array();
    for (const auto& x : m.unit_screw.coordinates) coordinates.push_back(x.get_d());
    out.push_back({{"name", m.name}, {"coupling", model.couplings[static_cast<std::size_t>(m.coupling)].name}, {"unit_screw", coordinates}});
  }
  return out;
}

// The contracted matrix: coupling -> its d expressions.
Json contracted_json(const network::Model& model, const NetworkResult& r, const LinearForms& forms, const std::vector<std::string>& primaries) {
  Json out = Json::object();
  for (int e = 0; e < r.e; ++e) out[model.couplings[static_cast<std::size_t>(e)].name] = expressions_json(forms, e * r.d, r.d, primaries);
  return out;
}

Json network_pairs_json(const network::Model& model, const NetworkResult& r, const std::vector<std::string>& motion_primaries,
                        const std::vector<std::string>& action_primaries) {
  Json pairs = Json::array();
  for (const auto& p : r.pairs) {
    Json pair = pair_counts_json(model, p);
    Json mp = Json::array(), ap = Json::array();
    for (int i : p.motion_primaries) mp.push_back(motion_primaries[static_cast<std::size_t>(i)]);
    for (int i : p.action_primaries) ap.push_back(action_primaries[static_cast<std::size_t>(i)]);
    pair["motion_primaries"] = mp;
    pair["action_primaries"] = ap;
    pair["motion_system"] = expressions_json(p.motion_system, 0, r.d, motion_primaries);
    pair["action_system"] = expressions_json(p.action_system, 0, r.d, action_primaries);
    pairs.push_back(pair);
  }
  return pairs;
}

// The numeric values of the magnitudes and coupling screws (primaries given values), and the
// primaries without one.
Json network_values_json(const network::Model& model, const NetworkResult& r) {
  Json values = Json::object();
  auto numeric = [&](const std::vector<network::Magnitude>& magnitudes, const Eigen::VectorXd& v) {
    Json out = Json::object();
    for (std::size_t i = 0; i < magnitudes.size(); ++i) out[magnitudes[i].name] = value_json(v(static_cast<Index>(i)));
    return out;
  };
  auto screws = [&](const Eigen::MatrixXd& columns) {
    Json out = Json::object();
    for (int e = 0; e < r.e; ++e) {
      Json coordinates = Json::array();
      for (int c = 0; c < r.d; ++c) coordinates.push_back(value_json(columns(c, e)));
      out[model.couplings[static_cast<std::size_t>(e)].name] = coordinates;
    }
    return out;
  };
  if (r.motion_values) values["motions"] = numeric(r.motions, *r.motion_values);
  if (r.coupling_motion_values) values["coupling_motions"] = screws(*r.coupling_motion_values);
  if (r.action_values) values["actions"] = numeric(r.actions, *r.action_values);
  if (r.coupling_action_values) values["coupling_actions"] = screws(*r.coupling_action_values);
  if (!r.missing_motion_values.empty() || !r.missing_action_values.empty()) {
    std::vector<std::string> missing = r.missing_motion_values;
    missing.insert(missing.end(), r.missing_action_values.begin(), r.missing_action_values.end());
    values["missing"] = missing;
  }
  return values;
}

Json network_matrices_json(const NetworkResult& r) {
  return {{"B", int_matrix_json(r.B)},        {"Q", int_matrix_json(r.Q)},        {"BM", int_matrix_json(r.BM)},
          {"QA", int_matrix_json(r.QA)},      {"MD", rational_matrix_json(r.MD)}, {"AD", rational_matrix_json(r.AD)},
          {"MN", rational_matrix_json(r.MN)}, {"AN", rational_matrix_json(r.AN)}};
}

}  // namespace

Json network_report_json(const network::Model& model, const NetworkResult& r, const NetworkReportOptions& options) {
  const auto motion_primaries = names_of(r.primary_motion, r.motions);
  const auto action_primaries = names_of(r.primary_action, r.actions);
  Json j;
  add_network_count_keys(j, model, r);
  if (options.generic) j["generic"] = generic_json(model, r, *options.generic, motion_primaries, action_primaries);
  if (options.second_order) j["second_order"] = second_order_json(*options.second_order, motion_primaries);
  add_rank_evidence_keys(j, r);
  Json branches = Json::array(), chords = Json::array();
  for (int b : r.branches) branches.push_back(model.couplings[static_cast<std::size_t>(b)].name);
  for (int c : r.chords) chords.push_back(model.couplings[static_cast<std::size_t>(c)].name);
  j["tree"] = {{"branches", branches}, {"chords", chords}};
  j["primary_motion"] = motion_primaries;
  j["primary_action"] = action_primaries;
  j["motions"] = magnitudes_json(r.motions, r.motion_magnitudes, motion_primaries);
  j["actions"] = magnitudes_json(r.actions, r.action_magnitudes, action_primaries);
  j["unit_motions"] = unit_screws_json(model, r.motions);
  j["unit_actions"] = unit_screws_json(model, r.actions);
  j["motion_matrix"] = contracted_json(model, r, r.circulation.contracted, motion_primaries);
  j["action_matrix"] = contracted_json(model, r, r.cutset_law.contracted, action_primaries);
  j["methods_agree"] = {{"motion", r.motion_methods_agree}, {"action", r.action_methods_agree}};
  j["pairs"] = network_pairs_json(model, r, motion_primaries, action_primaries);
  if (r.motion_values || r.action_values) j["values"] = network_values_json(model, r);
  j["warnings"] = warnings(r);
  if (options.matrices) j["matrices"] = network_matrices_json(r);
  if (options.verdict) return lead_with_verdict(*options.verdict, std::move(j), model.units);
  return j;
}

namespace {

// What the sparse path does not compute, said in every sparse report; the last entry depends on
// whether pairs were chosen.
std::vector<std::string> sparse_left_out(const network::SparseNetworkResult& r, const std::vector<network::SparsePairFreedom>* pairs) {
  std::vector<std::string> out{"spanning tree, circuits and cutsets", "unit and contracted matrices", "primary variables and magnitudes"};
  if (!pairs) {
    out.emplace_back("pair systems (fij, cij)");
    return out;
  }
  std::set<std::pair<int, int>> listed;
  for (const auto& p : *pairs) listed.insert({p.body_i, p.body_j});
  const auto n = static_cast<long long>(r.bodies);
  out.push_back(fmt::format("pair systems (linear forms in the primaries); fij and cij of the {} pairs of bodies not listed "
                            "(--pair, --coupled-pairs)",
                            n * (n - 1) / 2 - static_cast<long long>(listed.size())));
  return out;
}

std::string pair_bodies(const network::Model& model, const network::SparsePairFreedom& p) {
  return printable_text(model.bodies[static_cast<std::size_t>(p.body_i)]) + ", " + printable_text(model.bodies[static_cast<std::size_t>(p.body_j)]);
}

std::vector<std::string> coupling_names(const network::Model& model, const std::vector<int>& couplings) {
  std::vector<std::string> names;
  names.reserve(couplings.size());
  for (int c : couplings) names.push_back(model.couplings[static_cast<std::size_t>(c)].name);
  return names;
}

}  // namespace

std::string sparse_network_report_text(const network::Model& model, const network::SparseNetworkResult& r, const design::Verdict* verdict,
                                       const std::vector<network::SparsePairFreedom>* pairs) {
  std::string t = verdict ? verdict_text(*verdict) : std::string();
  t += fmt::format("{}\n", model.name.empty() ? "Coupling network" : printable_text(model.name));
  t += fmt::format("  coupling network, {} (d = {}); sparse body-twist form, floating point\n", r.d == 6 ? "spatial" : "planar", r.d);
  t += fmt::format("  bodies n = {}, couplings e = {}, circuits l = {}\n", r.bodies, r.e, r.l);
  t += fmt::format("  gross degree of freedom F = {}, gross degree of constraint C = {}\n", r.F, r.C);
  t += fmt::format("  rank of the body-twist constraint matrix K (C x d(n-1)): {}\n", rank_text("rank K", r.rank));
  t += fmt::format("    {}\n", rank_status_text(r.rank));
  t += fmt::format("  nett degree of freedom    FN = d(n-1) - rank K = {}\n", r.FN);
  t += fmt::format("  nett degree of constraint CN = C - rank K = {}\n", r.CN);
  t += fmt::format("  class: {}\n", network::class_description(r.classification));
  t += fmt::format("Couplings that carry a self-stress ({}): {}\n", r.stressed.size(), joined_or_dash(printable_names(coupling_names(model, r.stressed))));
  t += fmt::format("Couplings that move ({}): {}\n", r.moving.size(), joined_or_dash(printable_names(coupling_names(model, r.moving))));
  if (r.stress_support_zero > kSupportZero || r.motion_support_zero > kSupportZero)
    t += fmt::format("  (entries below {} of the largest (self-stress) and {} (motion) are not told from zero: the factors' "
                     "attainable accuracy)\n",
                     number_text(r.stress_support_zero), number_text(r.motion_support_zero));
  if (r.motion_basis.cols() > 0 || r.stress_basis.cols() > 0) {
    t += fmt::format("Basis vectors of the verdict: {} motion(s) from the QR of K ({}), {} self-stress(es) from the QR of K^T; "
                     "largest residual |K x| / (sigma_max |x|) = {}\n",
                     r.motion_basis.cols(), rank_text("rank", r.motion_factor_rank), r.stress_basis.cols(), number_text(r.basis_residual));
  }
  if (pairs) {
    t += "Pairs of bodies (seed 000, Table 1; an absent coupling counts as f = d, c = 0; from d generic motions and self-stresses):\n";
    t += fmt::format("  {:<24} {:<10} {:>3} {:>4} {:>3} {:>4}\n", "bodies", "coupling", "f", "fij", "c", "cij");
    for (const auto& p : *pairs)
      t += fmt::format("  {:<24} {:<10} {:>3} {:>4} {:>3} {:>4}\n", pair_bodies(model, p),
                       p.coupling ? printable_text(model.couplings[static_cast<std::size_t>(*p.coupling)].name) : std::string("absent"),
                       p.f, p.fij, p.c, p.cij);
  }
  t += fmt::format("Not computed on the sparse path (use the dense path for these): {}\n", fmt::join(sparse_left_out(r, pairs), "; "));
  if (r.rank.close()) t += "Warning: the rank of K is a close decision: the geometry is near one with a different FN and CN\n";
  if (r.rank.factor_estimated && r.rank.factor_smallest <= r.rank.threshold)
    t += fmt::format("Warning: the kept columns of the sparse factors are nearly dependent (sigma_min of R11 about {}, at or below "
                     "the threshold {}): rank K may be too high, so FN and CN too low, by the number of such values\n",
                     number_text(r.rank.factor_smallest), number_text(r.rank.threshold));
  return t;
}

nlohmann::ordered_json sparse_network_report_json(const network::Model& model, const network::SparseNetworkResult& r,
                                           const design::Verdict* verdict, const std::vector<network::SparsePairFreedom>* pairs) {
  Json j;
  j["kind"] = "network";
  if (!model.name.empty()) j["name"] = model.name;
  j["method"] = "sparse_body_twist";
  j["d"] = r.d;
  j["n"] = r.bodies;
  j["e"] = r.e;
  j["F"] = r.F;
  j["C"] = r.C;
  j["l"] = r.l;
  j["FN"] = r.FN;
  j["CN"] = r.CN;
  j["classification"] = network::class_id(r.classification);
  j["classification_description"] = network::class_description(r.classification);
  j["rank_evidence"] = {{"body_twist", rank_json(r.rank)}};
  j["stressed_couplings"] = coupling_names(model, r.stressed);
  j["moving_couplings"] = coupling_names(model, r.moving);
  j["null_space_residual"] = r.residual;
  j["support_zero"] = {{"self_stresses", r.stress_support_zero}, {"motions", r.motion_support_zero}};
  if (r.motion_basis.cols() > 0 || r.stress_basis.cols() > 0) {
    j["basis_vectors"] = {{"motions", r.motion_basis.cols()},
                          {"self_stresses", r.stress_basis.cols()},
                          {"motion_factor_rank", rank_json(r.motion_factor_rank)},
                          {"residual", r.basis_residual}};
  }
  if (pairs) {
    Json rows = Json::array();
    for (const auto& p : *pairs) {
      rows.push_back(pair_counts_json(model, p));
    }
    j["pairs"] = rows;
  }
  j["not_computed"] = sparse_left_out(r, pairs);
  if (verdict) return lead_with_verdict(*verdict, std::move(j), model.units);
  return j;
}

}  // namespace kinestat::report
