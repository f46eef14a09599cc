// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/framework_verdict.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "kinestat/design/framework_change_application.hpp"
#include "kinestat/design/screw_text.hpp"
#include "kinestat/framework/body_motions.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

namespace {

using framework::DeformationRole;
using framework::Element;
using framework::ElementType;
using framework::FrameworkModel;
using framework::FrameworkResult;

// A change is looked for among the coordinates (bars) that move at least this fraction of the
// most moving one (pair): a support or bar on a node that barely moves would be ill-conditioned.
constexpr double kUsefulShare = 0.25;
// Bars between every two nodes are tried up to this many nodes (quadratic).
constexpr std::size_t kMostBarNodes = 300;
// Parts named in a mode's one-line description; the rest are its participants.
constexpr std::size_t kPartsInDescription = 2;

const framework::DeformationRef& row_deformation(const FrameworkResult& a, Eigen::Index row) {
  return a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(row)])];
}

const framework::CoordinateRef& column_coordinate(const FrameworkResult& a, Eigen::Index column) {
  return a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(column)])];
}

std::string slot_name(int slot) { return framework::kSlotNames[static_cast<std::size_t>(slot)]; }

// A rigid body's deformation "P2.rz" in words: "P2 about z relative to C".
std::string rigid_link_words(const FrameworkModel& model, const Element& body, std::size_t deformation) {
  const auto slots_per_node = framework::deformation_count(model.dimension, body) / (body.nodes.size() - 1);
  const auto& node = model.nodes[body.nodes[1 + deformation / slots_per_node]];
  const std::string name = framework::deformation_names(model, body)[deformation];
  const std::string slot = name.substr(name.rfind('.') + 1);
  const bool turn = slot.size() == 2;
  return fmt::format("{} {} {} relative to {}", node.name, turn ? "about" : "along", turn ? slot.substr(1) : slot,
                     model.nodes[body.nodes[0]].name);
}

bool is_elongation(const FrameworkModel& model, const Element& element, std::size_t deformation) {
  return element.type != ElementType::rigid_body && framework::deformation_names(model, element)[deformation] == "elongation";
}

// A stress resultant in words: tension or compression for an elongation (positive = tension,
// docs/framework.md), otherwise the sense of a moment or internal force.
std::string resultant_words(const FrameworkModel& model, const Element& element, std::size_t deformation, double value) {
  const char* sense = value > 0 ? "+" : "-";
  if (is_elongation(model, element, deformation)) return value > 0 ? "tension" : "compression";
  if (element.type == ElementType::rigid_body) {
    const std::string name = framework::deformation_names(model, element)[deformation];
    return fmt::format("internal {} {}", name.substr(name.rfind('.') + 1).size() == 2 ? "moment" : "force", sense);
  }
  const std::string name = framework::deformation_names(model, element)[deformation];
  return fmt::format("{} moment {}", name == "torsion" ? "twisting" : "bending", sense);
}

// The participant of row `row` of a stress state: a bar, a beam's deformation, a rigid body's link.
Participant stress_participant(const FrameworkModel& model, const FrameworkResult& a, Eigen::Index row, double value, double share) {
  const auto& d = row_deformation(a, row);
  const Element& element = model.elements[d.element];
  const std::string detail = resultant_words(model, element, d.deformation, value);
  if (element.type == ElementType::truss) return {"bar", element.name, share, detail};
  if (element.type == ElementType::rigid_body)
    return {"rigid body", fmt::format("{} ({})", element.name, rigid_link_words(model, element, d.deformation)), share, detail};
  return {"deformation", framework_row_name(model, a, row), share, detail};
}

// The change that releases row `row`: a bar is removed, a beam's deformation or a rigid body's
// link released.
DesignChange release_change(const FrameworkModel& model, const FrameworkResult& a, Eigen::Index row) {
  const auto& d = row_deformation(a, row);
  const Element& element = model.elements[d.element];
  const std::string reason = "removes a redundant constraint (self-stress)";
  if (element.type == ElementType::truss && element.roles[d.deformation] == DeformationRole::fixed)
    return {"remove", "bar", element.name, "removed", reason + ": the bar is not needed to hold the nodes", "", {}};
  if (element.type == ElementType::rigid_body)
    return {"release", "rigid body", framework_row_name(model, a, row), "released",
            fmt::format("{}: let {} (a compliance of body '{}')", reason, rigid_link_words(model, element, d.deformation), element.name),
            "rigid", {}};
  return {"release", "deformation", framework_row_name(model, a, row), "released", reason, "rigid", {}};
}

std::string node_list(const FrameworkModel& model, const std::vector<std::size_t>& nodes) {
  constexpr std::size_t kShown = 4;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < nodes.size() && i < kShown; ++i) names.push_back(model.nodes[nodes[i]].name);
  if (nodes.size() > kShown) names.push_back(fmt::format("... {} nodes", nodes.size()));
  return fmt::format("{}", fmt::join(names, ", "));
}

// "body 'stage' (C, P1, P2, P3, ... 6 nodes)" or "nodes E, F" or "node E".
std::string part_name(const FrameworkModel& model, const framework::MovingPart& part) {
  if (!part.body.empty()) return fmt::format("body '{}' ({})", part.body, node_list(model, part.nodes));
  return fmt::format("{} {}", part.nodes.size() == 1 ? "node" : "nodes", node_list(model, part.nodes));
}

// The mode's rigid parts as participants ("part"), strongest first, and a one-line summary.
std::vector<Participant> part_participants(const FrameworkModel& model, const std::vector<framework::MovingPart>& parts, double length) {
  std::vector<Participant> list;
  for (const auto& part : parts) list.push_back({"part", part_name(model, part), part.share, motion_text(part.twist, length)});
  return list;
}

std::string parts_summary(const std::vector<Participant>& parts) {
  if (parts.empty()) return "";
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < parts.size() && i < kPartsInDescription; ++i)
    shown.push_back(fmt::format("{}: {}", parts[i].name, parts[i].detail));
  std::string text = fmt::format("{}", fmt::join(shown, "; "));
  if (parts.size() > kPartsInDescription) text += fmt::format("; {} more parts move", parts.size() - kPartsInDescription);
  return text;
}

// Orthonormal basis (columns) of the span of `columns`, by column-pivoted QR (deterministic).
Eigen::MatrixXd orthonormal(const Eigen::MatrixXd& columns) {
  if (columns.cols() == 0) return columns;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(columns);
  qr.setThreshold(kRigidMotionZero);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(columns.rows(), qr.rank());
  return q;
}

// `basis` with the direction `row` (over its rows) taken out: the motions row·x = 0 leaves.
Eigen::MatrixXd without(const Eigen::MatrixXd& basis, const Eigen::VectorXd& row) {
  const Eigen::VectorXd c = basis.transpose() * row;
  if (c.norm() == 0.0 || basis.cols() == 0) return basis;
  // Householder reflection taking c to a multiple of e1; the other columns span c's complement.
  Eigen::VectorXd v = c / c.norm();
  v(0) += v(0) >= 0 ? 1.0 : -1.0;
  Eigen::MatrixXd h = Eigen::MatrixXd::Identity(c.size(), c.size()) - 2.0 * v * v.transpose() / v.squaredNorm();
  return basis * h.rightCols(c.size() - 1);
}

// A node's weight as the carrier of a motion: a rigid body's reference node (the stage's own
// node), then its other nodes, then nodes joining several beams (a platform), then the rest.
std::vector<int> carrier_weights(const FrameworkModel& model) {
  std::vector<int> weight(model.nodes.size(), 1);
  std::vector<int> beams(model.nodes.size(), 0);
  for (const Element& element : model.elements) {
    if (element.type == ElementType::rigid_body) {
      for (std::size_t k = 0; k < element.nodes.size(); ++k) weight[element.nodes[k]] = std::max(weight[element.nodes[k]], k == 0 ? 4 : 3);
    } else if (element.type == ElementType::beam) {
      for (std::size_t n : element.nodes) ++beams[n];
    }
  }
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (beams[n] >= 2) weight[n] = std::max(weight[n], 2);
  return weight;
}

// `count` columns of D(c) to support, each stopping one more of `basis`'s motions: greedily,
// among the coordinates that move at least kUsefulShare of the most moving one, the heaviest
// carrier (translations before rotations), then one of a node already supported (so that a
// free body is held 3-2-1 at few nodes), then the largest motion, ties to the earlier
// coordinate. `basis` is left with the motions the chosen supports do not stop.
std::vector<Eigen::Index> choose_supports(const FrameworkModel& model, const FrameworkResult& a, Eigen::MatrixXd& basis, Eigen::Index count,
                                          std::vector<bool>& supported_node) {
  const auto weight = carrier_weights(model);
  std::vector<Eigen::Index> chosen;
  for (Eigen::Index t = 0; t < count; ++t) {
    const Eigen::VectorXd norms = basis.rowwise().norm();
    if (norms.size() == 0 || norms.maxCoeff() <= kRigidMotionZero) break;
    const double most = norms.maxCoeff();
    Eigen::Index best = -1;
    std::tuple<int, int, double> best_key{-1, -1, 0.0};
    for (Eigen::Index c = 0; c < norms.size(); ++c) {
      if (norms(c) < kUsefulShare * most) continue;
      const auto& ref = column_coordinate(a, c);
      const std::tuple<int, int, double> key{weight[ref.node] * (framework::is_translation(ref.slot) ? 2 : 1),
                                             supported_node[ref.node] ? 1 : 0, norms(c)};
      const bool heavier = std::get<0>(key) != std::get<0>(best_key) ? std::get<0>(key) > std::get<0>(best_key)
                           : std::get<1>(key) != std::get<1>(best_key) ? std::get<1>(key) > std::get<1>(best_key)
                                                                        : std::get<2>(key) > std::get<2>(best_key) * (1.0 + kPivotTie);
      if (best < 0 || heavier) {
        best_key = key;
        best = c;
      }
    }
    chosen.push_back(best);
    supported_node[column_coordinate(a, best).node] = true;
    basis = without(basis, Eigen::VectorXd::Unit(basis.rows(), best));
  }
  return chosen;
}

struct BarChoice {
  std::size_t p = 0, q = 0;
  double length = 0.0;
};

// `count` bars between nodes in different rigid parts of the motions of `basis`: each bar the
// shortest among those that stop at least kUsefulShare of the most any bar stops.
std::vector<BarChoice> choose_bars(const FrameworkModel& model, const FrameworkResult& a, Eigen::MatrixXd basis, Eigen::Index count) {
  std::vector<BarChoice> chosen;
  const std::size_t nodes = model.nodes.size();
  if (nodes > kMostBarNodes || count == 0) return chosen;
  std::set<std::pair<std::size_t, std::size_t>> joined;
  for (const Element& element : model.elements)
    for (std::size_t i : element.nodes)
      for (std::size_t j : element.nodes)
        if (i < j) joined.insert({i, j});
  const int translations = model.dimension == 2 ? 2 : 3;
  // Column of D(c) of every dependent coordinate (-1: fixed or independent, at rest).
  std::vector<Eigen::Index> column_of(a.indexing.coordinates.size(), -1);
  for (std::size_t c = 0; c < a.partition.dependent_coordinates.size(); ++c)
    column_of[static_cast<std::size_t>(a.partition.dependent_coordinates[c])] = static_cast<Eigen::Index>(c);
  // The bar's elongation rate as a row over the columns: -e on p's translations, +e on q's.
  const auto bar_entries = [&](std::size_t p, std::size_t q) {
    std::vector<std::pair<Eigen::Index, double>> entries;
    const Eigen::Vector3d e = (model.nodes[q].position - model.nodes[p].position).normalized();
    for (int s = 0; s < translations; ++s) {
      for (const auto& [node, sign] : {std::pair{p, -1.0}, std::pair{q, 1.0}}) {
        const Eigen::Index coordinate = a.indexing.coordinate_of[node][static_cast<std::size_t>(s)];
        const Eigen::Index column = coordinate < 0 ? -1 : column_of[static_cast<std::size_t>(coordinate)];
        if (column >= 0) entries.push_back({column, sign * e(s)});
      }
    }
    return entries;
  };
  const auto bar_row = [&](std::size_t p, std::size_t q) {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(basis.rows());
    for (const auto& [column, value] : bar_entries(p, q)) row(column) += value;
    return row;
  };
  const auto stopped = [&](std::size_t p, std::size_t q) {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(basis.cols());
    for (const auto& [column, value] : bar_entries(p, q)) c += value * basis.row(column).transpose();
    return c.norm();
  };
  const double size = framework::characteristic_length(model);
  for (Eigen::Index t = 0; t < count; ++t) {
    std::vector<std::pair<BarChoice, double>> options;
    double most = 0.0;
    for (std::size_t p = 0; p < nodes; ++p) {
      for (std::size_t q = p + 1; q < nodes; ++q) {
        const double length = (model.nodes[q].position - model.nodes[p].position).norm();
        if (joined.count({p, q}) || !(length > kCoincident * size)) continue;
        const double stops = stopped(p, q);
        most = std::max(most, stops);
        options.push_back({{p, q, length}, stops});
      }
    }
    if (!(most > kRigidMotionZero)) break;
    const BarChoice* best = nullptr;
    for (const auto& [bar, stops] : options) {
      if (stops < kUsefulShare * most) continue;
      if (!best || bar.length < best->length * (1.0 - kPivotTie)) best = &bar;
    }
    chosen.push_back(*best);
    joined.insert({best->p, best->q});
    basis = without(basis, bar_row(best->p, best->q));
  }
  return chosen;
}

// The moving parts of the mode (columns of D(c)) carrying coordinate `column`, in words.
std::string carrier_words(const FrameworkModel& model, const FrameworkResult& a, Eigen::Index column) {
  const auto& ref = column_coordinate(a, column);
  for (const Element& element : model.elements)
    if (element.type == ElementType::rigid_body && !element.nodes.empty() && element.nodes[0] == ref.node)
      return fmt::format("{} is the reference node of body '{}'", model.nodes[ref.node].name, element.name);
  for (const Element& element : model.elements)
    if (element.type == ElementType::rigid_body &&
        std::find(element.nodes.begin(), element.nodes.end(), ref.node) != element.nodes.end())
      return fmt::format("{} is a node of body '{}'", model.nodes[ref.node].name, element.name);
  return fmt::format("{} moves in it", model.nodes[ref.node].name);
}

DesignChange support_change(const FrameworkModel& model, const FrameworkResult& a, Eigen::Index column, bool rigid_motion) {
  const std::string target = framework_column_name(model, a, column);
  return {"support", "coordinate", target, "fixed",
          fmt::format("removes {}; {}: support it, or drive {} as an input if that motion is intended",
                      rigid_motion ? "a rigid motion of the whole model" : "an extra motion (mechanism)",
                      carrier_words(model, a, column), target),
          "free", {}};
}

DesignChange bar_change(const FrameworkModel& model, const BarChoice& bar) {
  const auto& p = model.nodes[bar.p];
  const auto& q = model.nodes[bar.q];
  return {"add", "bar", p.name + kBarNodeSeparator + q.name, fmt::format("a bar of length {:.4g}", bar.length),
          fmt::format("removes an extra motion (mechanism): {} and {} lie in different rigid parts of it, the bar keeps their distance",
                      p.name, q.name),
          "", {}};
}

std::string set_text(const std::vector<DesignChange>& set) {
  std::vector<std::string> parts;
  for (const auto& c : set)
    parts.push_back(c.action == "add" ? fmt::format("add bar {}", c.target) : fmt::format("{} {}", c.action, c.target));
  return fmt::format("{}", fmt::join(parts, ", "));
}

struct Reanalysis {
  bool passed = false;
  std::string why;  ///< when not passed
  FrameworkResult after;
};

// The changed design re-analysed: it passes with no extra motion, no redundant constraint and
// the same declared intended motions.
Reanalysis reanalyse(const FrameworkModel& model, const FrameworkResult& before, const std::vector<DesignChange>& set,
                     const framework::AnalysisOptions& options) {
  framework::AnalysisOptions counts_only = options;
  counts_only.vectors = false;
  counts_only.sparse_vectors = 0;
  Reanalysis r;
  r.after = framework::analyse_framework(apply_framework_change_set(model, set), counts_only);
  const auto& after = r.after;
  if (after.count.declared_dof() != before.count.declared_dof())
    r.why = fmt::format("the declared intended motions change from {} to {}", before.count.declared_dof(), after.count.declared_dof());
  else if (after.mechanisms != 0 || after.self_stresses != 0)
    r.why = fmt::format("re-analysed: {}", constraint_words(static_cast<int>(after.mechanisms), static_cast<int>(after.self_stresses)));
  r.passed = r.why.empty();
  return r;
}

}  // namespace

std::string framework_row_name(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index row) {
  const auto& d = row_deformation(analysis, row);
  const auto& element = model.elements[d.element];
  return element.name + "." + framework::deformation_names(model, element)[d.deformation];
}

std::string framework_column_name(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index column) {
  const auto& c = column_coordinate(analysis, column);
  return model.nodes[c.node].name + "." + slot_name(c.slot);
}

namespace {

// Sections of framework_verdict: the states (rigid motions, internal mechanisms, self-stresses),
// the candidate change sets, and the re-analysis that chooses among them.

// The rigid motions of the whole model as one state (rigid_mode_basis.hpp names them); none
// when the supports stop them all.
std::optional<VerdictState> rigid_motions_state(const FrameworkModel& model, const std::vector<std::string>& rigid) {
  if (rigid.empty()) return std::nullopt;
  const bool unsupported = static_cast<int>(rigid.size()) == (model.dimension == 2 ? 3 : 6);
  VerdictState state{"extra motion",
                     unsupported ? fmt::format("no supports: {} rigid motions", rigid.size())
                                 : fmt::format("not enough supports: {}", fmt::join(rigid, "; ")),
                     {}};
  for (const auto& name : rigid) state.participants.push_back({"motion", name, 1.0 / static_cast<double>(rigid.size()), "rigid-body motion"});
  return state;
}

// Internal mechanism `internal` (mode k of the report): its order, and the rigid parts that move
// (or, when none is found, the coordinates that carry the mode).
VerdictState internal_mechanism_state(const FrameworkModel& model, const FrameworkResult& a, std::size_t k, std::size_t internal,
                                      bool after_rigid_motions) {
  const std::string order = k < a.orders.size() && a.orders[k].order != framework::MotionOrder::undetermined
                                ? std::string(framework::motion_order_name(a.orders[k].order))
                                : "";
  const Eigen::VectorXd& velocity = a.modes[k].velocities;
  std::vector<Participant> parts = part_participants(model, framework::moving_parts(model, a, velocity), a.length);
  std::string where = after_rigid_motions ? fmt::format("internal mechanism {} (mode {} of the report)", internal, k + 1)
                                          : fmt::format("mechanism {}", k + 1);
  if (!order.empty()) where += fmt::format(" ({})", order);
  VerdictState state{"extra motion", where, {}};
  if (parts.size() == 1) state.description += ": " + parts_summary(parts);
  else if (parts.size() > 1) state.description += fmt::format(": {} rigid parts move", parts.size());
  if (parts.empty()) {
    for (Eigen::Index col : a.modes[k].moving) {
      const double share = velocity(col) * velocity(col) / std::max(velocity.squaredNorm(), 1e-300);
      if (share > kShareZero)
        state.participants.push_back({"coordinate", framework_column_name(model, a, col), share,
                                      velocity(col) > 0 ? "moves +" : "moves -"});
    }
  } else {
    state.participants = std::move(parts);
  }
  rank_participants(state.participants);
  return state;
}

// Stress state k as a redundant constraint: the resultants that carry it, and how many bars
// are in tension and in compression.
VerdictState framework_self_stress_state(const FrameworkModel& model, const FrameworkResult& a, std::size_t k) {
  const Eigen::VectorXd& stress = a.stresses[k].resultants;
  int tension = 0, compression = 0;
  VerdictState state{"self-stress", "", {}};
  for (Eigen::Index row = 0; row < stress.size(); ++row) {
    const double share = stress(row) * stress(row) / std::max(stress.squaredNorm(), 1e-300);
    if (share <= kShareZero) continue;
    const auto& d = row_deformation(a, row);
    if (is_elongation(model, model.elements[d.element], d.deformation)) ++(stress(row) > 0 ? tension : compression);
    state.participants.push_back(stress_participant(model, a, row, stress(row), share));
  }
  state.description = fmt::format("redundant constraint {}", k + 1);
  if (tension + compression > 0)
    state.description += fmt::format(" ({} in tension, {} in compression, or all reversed)", tension, compression);
  rank_participants(state.participants);
  return state;
}

// Every extra motion and redundant constraint of the analysis as a state of the verdict.
void add_verdict_states(Verdict& v, const FrameworkModel& model, const FrameworkResult& a) {
  std::vector<std::string> rigid;
  for (const auto& mode : a.modes)
    if (!mode.rigid_motion.empty()) rigid.push_back(mode.rigid_motion);
  if (auto state = rigid_motions_state(model, rigid)) v.states.push_back(std::move(*state));
  std::size_t internal = 0;
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    if (!a.modes[k].rigid_motion.empty()) continue;
    v.states.push_back(internal_mechanism_state(model, a, k, ++internal, !rigid.empty()));
  }
  for (std::size_t k = 0; k < a.stresses.size(); ++k) v.states.push_back(framework_self_stress_state(model, a, k));
}

// Change sets that stop the extra motions (all of them known): supports for the rigid motions
// of the whole model first (bars cannot stop them); the motions left are then stopped by bars
// between rigid parts or by more supports. Bars first for a bar framework, supports first
// otherwise; each set begins with the analysis' releases.
std::vector<std::vector<DesignChange>> motion_change_sets(const FrameworkModel& model, const FrameworkResult& a,
                                                          const std::vector<DesignChange>& releases) {
  Eigen::MatrixXd rigid_basis(a.n, 0), internal_basis(a.n, 0);
  for (const auto& mode : a.modes) {
    Eigen::MatrixXd& target = mode.rigid_motion.empty() ? internal_basis : rigid_basis;
    target.conservativeResize(Eigen::NoChange, target.cols() + 1);
    target.col(target.cols() - 1) = mode.velocities;
  }
  rigid_basis = orthonormal(rigid_basis);
  internal_basis = orthonormal(internal_basis);
  Eigen::MatrixXd all(a.n, rigid_basis.cols() + internal_basis.cols());
  all << rigid_basis, internal_basis;
  all = orthonormal(all);

  std::vector<bool> supported_node(model.nodes.size(), false);
  Eigen::MatrixXd rigid_left = rigid_basis;
  const auto rigid_columns = choose_supports(model, a, rigid_left, rigid_basis.cols(), supported_node);
  std::vector<DesignChange> rigid_supports;
  Eigen::MatrixXd left = all;
  for (Eigen::Index c : rigid_columns) {
    rigid_supports.push_back(support_change(model, a, c, true));
    left = without(left, Eigen::VectorXd::Unit(a.n, c));
  }
  std::vector<DesignChange> with_bars = releases;
  const auto bars = choose_bars(model, a, left, left.cols());
  if (left.cols() > 0 && static_cast<Eigen::Index>(bars.size()) == left.cols()) {
    with_bars.insert(with_bars.end(), rigid_supports.begin(), rigid_supports.end());
    for (const auto& bar : bars) with_bars.push_back(bar_change(model, bar));
  } else {
    with_bars.clear();
  }
  std::vector<DesignChange> with_supports = releases;
  with_supports.insert(with_supports.end(), rigid_supports.begin(), rigid_supports.end());
  for (Eigen::Index c : choose_supports(model, a, left, left.cols(), supported_node))
    with_supports.push_back(support_change(model, a, c, false));
  const bool bar_framework = std::all_of(model.elements.begin(), model.elements.end(),
                                         [](const Element& e) { return e.type == ElementType::truss; });
  std::vector<std::vector<DesignChange>> sets;
  if (bar_framework && !with_bars.empty()) sets.push_back(with_bars);
  sets.push_back(with_supports);
  if (!bar_framework && !with_bars.empty()) sets.push_back(with_bars);
  return sets;
}

// Candidate sets: the releases of the analysis' proposal, then for the extra motions either
// bars between rigid parts (internal mechanisms; rigid motions of the whole need supports) or
// supports at the nodes that carry them; last the analysis' own proposal.
std::vector<std::vector<DesignChange>> candidate_change_sets(const FrameworkModel& model, const FrameworkResult& a) {
  std::vector<DesignChange> releases;
  for (Eigen::Index row : a.releases) releases.push_back(release_change(model, a, row));
  std::vector<std::vector<DesignChange>> candidates;
  const bool modes_complete = static_cast<Eigen::Index>(a.modes.size()) == a.mechanisms;
  if (a.mechanisms > 0 && modes_complete) candidates = motion_change_sets(model, a, releases);
  // The analysis' own proposal (a pivoted QR's columns), supported rather than driven: tried
  // only when no set above passes (it supports whichever coordinate the QR met last, such as
  // a wire's end rather than the platform).
  std::vector<DesignChange> proposal = releases;
  for (Eigen::Index c : a.constrain) proposal.push_back(support_change(model, a, c, false));
  candidates.push_back(proposal);
  return candidates;
}

// Each candidate set is re-analysed before it is proposed: the first that passes is the
// verdict's change, the others that pass its alternatives, the rest turned down with the reason.
void choose_change_set(Verdict& v, const FrameworkModel& model, const FrameworkResult& a,
                       const std::vector<std::vector<DesignChange>>& candidates, const framework::AnalysisOptions& options) {
  std::optional<Reanalysis> chosen;
  std::set<std::string> seen;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const auto& set = candidates[k];
    if (k + 1 == candidates.size() && k > 0 && chosen) break;
    const std::string text = set_text(set);
    if (!seen.insert(text).second) continue;
    Reanalysis r = reanalyse(model, a, set, options);
    if (!r.passed) {
      v.rejected.push_back(fmt::format("{}: {}", text, r.why));
      continue;
    }
    if (!chosen) {
      v.changes = set;
      chosen = std::move(r);
    } else {
      v.alternatives.push_back(set);
    }
  }
  if (!chosen) {
    v.changes = candidates.back();
    v.changes_verified = false;
    v.becomes = "no change set found passes the re-analysis (see the sets turned down)";
    return;
  }
  const FrameworkResult& after = chosen->after;
  v.changes_verified = true;
  v.becomes = fmt::format("exactly constrained: D(c) {} x {}, rank {}; {} declared, as before", after.m, after.n, after.rank,
                          counted(after.count.declared_dof(), "intended motion", "intended motions"));
  v.verification.push_back(fmt::format("every set shown was re-analysed: 0 extra motions, 0 redundant constraints, the same {} declared",
                                       counted(a.count.declared_dof(), "intended motion", "intended motions")));
}

}  // namespace

Verdict framework_verdict(const FrameworkModel& model, const FrameworkResult& a, const framework::AnalysisOptions& options) {
  Verdict v;
  v.extra_motions = static_cast<int>(a.mechanisms);
  v.redundant_constraints = static_cast<int>(a.self_stresses);
  v.exactly_constrained = a.exactly_constrained();
  v.intended_motions = static_cast<int>(a.count.declared_dof());
  v.intended_basis = "declared independent coordinates and deformations ('independent:')";
  v.summary = summary_sentence(v.extra_motions, v.redundant_constraints, v.intended_motions);
  note_near_rank_change(v, a.decision.distance(), a.mechanisms > 0);
  add_verdict_states(v, model, a);
  v.motion_participants = strongest(v.states, "extra motion");
  v.constraint_participants = strongest(v.states, "self-stress");

  if (v.exactly_constrained) {
    v.changes_verified = true;
    v.becomes = "unchanged: already exactly constrained";
    return v;
  }
  if (!a.vectors) {
    v.note = "the model is too large for the dense SVD: no modes, stress states or proposal were computed";
    return v;
  }
  choose_change_set(v, model, a, candidate_change_sets(model, a), options);
  return v;
}

}  // namespace kinestat::design
