// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/analyse_network.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "kinestat/graph/coupling_graph.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/linalg/modular_rank.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/magnitude_names.hpp"
#include "kinestat/network/unit_matrices.hpp"

namespace kinestat::network {

namespace {

using linalg::Rational;
using linalg::RationalMatrix;
using Index = Eigen::Index;

// ---- LinearForms arithmetic, exact when both operands are exact --------------------------

LinearForms forms_from(const RationalMatrix& exact) { return {exact.to_double(), exact}; }

// unit (rows x n) times forms (n x p).
LinearForms times(const RationalMatrix& unit, const LinearForms& forms) {
  if (forms.exact) return forms_from(unit * *forms.exact);
  return {unit.to_double() * forms.values, std::nullopt};
}

LinearForms zero_forms(Index rows, Index cols, bool exact) {
  LinearForms z{Eigen::MatrixXd::Zero(rows, cols), std::nullopt};
  if (exact) z.exact = RationalMatrix(rows, cols);
  return z;
}

LinearForms block_rows(const LinearForms& forms, Index row, Index rows) {
  // With no primaries (FN or CN = 0) the forms have no columns and no storage; Eigen blocks of
  // them would offset a null pointer.
  if (forms.values.cols() == 0) return zero_forms(rows, 0, forms.exact.has_value());
  LinearForms b{forms.values.middleRows(row, rows), std::nullopt};
  if (forms.exact) b.exact = forms.exact->block(row, 0, rows, forms.exact->cols());
  return b;
}

LinearForms combine(const LinearForms& a, const LinearForms& b, int sign) {
  LinearForms sum{a.values + sign * b.values, std::nullopt};
  if (a.exact && b.exact) sum.exact = sign > 0 ? *a.exact + *b.exact : *a.exact - *b.exact;
  return sum;
}


LinearForms stack(const std::vector<LinearForms>& blocks, Index cols, bool exact) {
  Index rows = 0;
  for (const auto& b : blocks) rows += b.values.rows();
  LinearForms s = zero_forms(rows, cols, exact);
  Index row = 0;
  if (cols == 0) return s;  // nothing to copy (and no storage to take blocks of)
  for (const auto& b : blocks) {
    s.values.middleRows(row, b.values.rows()) = b.values;
    if (exact) s.exact->set_block(row, 0, *b.exact);
    row += b.values.rows();
  }
  return s;
}

// Rank of forms: exact, or against an absolute threshold `reference * relative` (relative:
// Tolerances::pair_rank).
linalg::RankDecision forms_rank(const LinearForms& forms, double reference, double relative) {
  if (forms.values.size() == 0) return linalg::RankDecision{0, forms.exact.has_value(), 0, 0, 0, 0};
  if (forms.exact) {
    linalg::RankDecision d;
    d.exact = true;
    d.rank = linalg::exact_rank(*forms.exact);
    return d;
  }
  const double largest = forms.values.norm();
  if (largest <= relative * reference) {
    linalg::RankDecision d;
    d.threshold = d.rounding_level = relative * reference;
    d.largest = d.largest_dropped = largest;
    return d;
  }
  linalg::RankTolerance tolerance;
  tolerance.relative = relative * reference / largest;
  return linalg::numerical_rank(forms.values, tolerance);
}

// Maps each d-row block of `forms` (coupling-major or body-major) from the analysis frame to
// the user's frame, column by column.
template <class ToUser>
LinearForms blocks_to_user(const LinearForms& forms, int d, ToUser to_user) {
  LinearForms user = forms;
  const Index blocks = forms.values.rows() / d;
  for (Index b = 0; b < blocks; ++b)
    for (Index p = 0; p < forms.values.cols(); ++p) {
      std::vector<Rational> v(static_cast<std::size_t>(d));
      if (forms.exact) {
        for (int r = 0; r < d; ++r) v[static_cast<std::size_t>(r)] = (*forms.exact)(b * d + r, p);
        const auto u = to_user(v);
        for (int r = 0; r < d; ++r) (*user.exact)(b * d + r, p) = u[static_cast<std::size_t>(r)];
        for (int r = 0; r < d; ++r) user.values(b * d + r, p) = u[static_cast<std::size_t>(r)].get_d();
      } else {
        // Doubles go through rationals exactly (every finite double is a rational).
        for (int r = 0; r < d; ++r) v[static_cast<std::size_t>(r)] = Rational(forms.values(b * d + r, p));
        const auto u = to_user(v);
        for (int r = 0; r < d; ++r) user.values(b * d + r, p) = u[static_cast<std::size_t>(r)].get_d();
      }
    }
  return user;
}

// ---- the four methods -------------------------------------------------------------------

linalg::HomogeneousSolution solve(const RationalMatrix& a, bool exact, const Tolerances& tolerances, double input_rounding) {
  return exact ? linalg::solve_homogeneous(a)
               : linalg::solve_homogeneous(a.to_double(), {tolerances.rank, input_rounding}, tolerances.free_variable);
}

// ε × the largest coupling-point coordinate (user frame) over the analysis frame's length: how
// precisely coordinates written at full precision fix the geometry (linalg::input_rounding_level).
double input_rounding(const Model& model, const AnalysisFrame& frame) { return frame.input_rounding(model); }

LinearForms solution_forms(const linalg::HomogeneousSolution& s) {
  return {s.coefficients, s.exact_coefficients};
}

// [M]d,e (or [A]d,e) from coupling magnitudes: coupling e's block is unit_e * K_e.
LinearForms contract_couplings(const RationalMatrix& unit, const std::vector<int>& first, const LinearForms& k, int d,
                               bool exact) {
  std::vector<LinearForms> blocks;
  for (std::size_t e = 0; e + 1 < first.size(); ++e) {
    const int n = first[e + 1] - first[e];
    const RationalMatrix unit_e = unit.block(0, first[e], d, n);
    blocks.push_back(n == 0 ? zero_forms(d, k.values.cols(), exact) : times(unit_e, block_rows(k, first[e], n)));
  }
  return stack(blocks, k.values.cols(), exact);
}

// [M]d,e = [Mk]d,k [Q]k,e (eq. 14a) or [A]d,e = [Al]d,l [B]l,e (eq. 14b), for every primary:
// coupling e's block is sum over graph rows g of G(g, e) * (block g of the system vector).
LinearForms contract_graph(const LinearForms& system, const Eigen::MatrixXi& graph_matrix, int d, bool exact) {
  std::vector<LinearForms> blocks;
  for (Index e = 0; e < graph_matrix.cols(); ++e) {
    LinearForms block = zero_forms(d, system.values.cols(), exact);
    for (Index g = 0; g < graph_matrix.rows(); ++g) {
      const int sign = graph_matrix(g, e);
      if (sign != 0) block = combine(block, block_rows(system, g * d, d), sign);
    }
    blocks.push_back(block);
  }
  return stack(blocks, system.values.cols(), exact);
}

// The column spaces of two sets of forms coincide.
bool same_span(const LinearForms& a, const LinearForms& b, double relative) {
  if (a.values.cols() != b.values.cols()) return false;
  if (a.values.cols() == 0) return true;
  if (a.exact && b.exact) {
    const Index ra = linalg::exact_rank(*a.exact), rb = linalg::exact_rank(*b.exact);
    return ra == rb && linalg::exact_rank(a.exact->append_columns(*b.exact)) == ra;
  }
  Eigen::MatrixXd joined(a.values.rows(), a.values.cols() + b.values.cols());
  joined << a.values, b.values;
  const double reference = std::max(a.values.norm(), b.values.norm());
  const auto ra = forms_rank(a, reference, relative).rank, rb = forms_rank(b, reference, relative).rank;
  return ra == rb && forms_rank({joined, std::nullopt}, reference, relative).rank == ra;
}

// Magnitudes of unit translations and torques scale with length; the rest do not.
bool scales_with_length(const screw::UnitScrew& screw) {
  return screw.kind == screw::UnitScrewKind::translation || screw.kind == screw::UnitScrewKind::torque;
}

// K_user = D K_frame D_free^-1 with D = diag(L or 1) per magnitude.
LinearForms to_user_magnitudes(const LinearForms& k, const std::vector<Magnitude>& magnitudes,
                               const std::vector<int>& free_variables, const Rational& length) {
  if (length == 1) return k;
  LinearForms user = k;
  auto factor = [&](std::size_t i) { return scales_with_length(magnitudes[i].unit_screw) ? length : Rational(1); };
  for (Index i = 0; i < k.values.rows(); ++i)
    for (Index p = 0; p < k.values.cols(); ++p) {
      const Rational f = factor(static_cast<std::size_t>(i)) / factor(static_cast<std::size_t>(free_variables[static_cast<std::size_t>(p)]));
      if (f == 1) continue;
      user.values(i, p) *= f.get_d();
      if (user.exact) (*user.exact)(i, p) *= f;
    }
  return user;
}

// ---- model checks and choices ----------------------------------------------------------

int coupling_index(const Model& model, const std::string& name) {
  for (std::size_t i = 0; i < model.couplings.size(); ++i)
    if (model.couplings[i].name == name) return static_cast<int>(i);
  return -1;
}

graph::SpanningTree choose_tree(const Model& model, const graph::CouplingGraph& graph, int ground) {
  if (model.chords.empty()) return graph.breadth_first_tree(ground);
  std::vector<int> chords;
  for (std::size_t i = 0; i < model.chords.size(); ++i) {
    const int c = coupling_index(model, model.chords[i]);
    if (c < 0) throw ModelError("chords", static_cast<int>(i), fmt::format("unknown coupling '{}' in chords", model.chords[i]));
    chords.push_back(c);
  }
  try {
    return graph.tree_with_chords(chords);
  } catch (const graph::TreeError& error) {
    const std::string closing =
        error.edge() < 0 ? std::string()
                         : fmt::format(", closed by coupling '{}' (make one coupling of that circuit a chord)",
                                       model.couplings[static_cast<std::size_t>(error.edge())].name);
    throw ModelError("chords", -1, fmt::format("these chords do not leave a spanning tree: {}{}", error.what(), closing));
  }
}

void check_connected(const Model& model, const graph::CouplingGraph& graph) {
  const auto components = graph.components();
  if (components.size() <= 1) return;
  std::string list;
  for (const auto& component : components) {
    std::string bodies;
    for (int b : component) bodies += (bodies.empty() ? "" : ", ") + model.bodies[static_cast<std::size_t>(b)];
    list += (list.empty() ? "{" : "; {") + bodies + "}";
  }
  throw ModelError("couplings", -1,
                   fmt::format("the bodies are not all connected by couplings; {} separate groups: {}. "
                               "Analyse each group as its own model, or add the missing couplings",
                               components.size(), list));
}

double elimination_work(int rows, int cols) {
  return static_cast<double>(rows) * cols * std::min(rows, cols);
}

// A relative tolerance that makes decide_rank keep exactly `rank` of `singular_values`: the
// geometric mean of the last kept and the first dropped value.
Tolerances tolerance_for_rank(Tolerances t, const Eigen::VectorXd& singular_values, Index rank) {
  const double largest = singular_values.size() > 0 ? singular_values(0) : 0.0;
  if (largest <= 0.0 || rank >= singular_values.size()) {
    t.rank = 0.0;
  } else if (rank <= 0) {
    t.rank = 1.0;
  } else {
    const double kept = singular_values(rank - 1), dropped = singular_values(rank);
    t.rank = (dropped > 0.0 ? std::sqrt(kept * dropped) : kept / 2) / largest;
  }
  return t;
}

bool choose_exact(const Model& model, Arithmetic arithmetic, std::string& reason) {
  switch (arithmetic) {
    case Arithmetic::exact: reason = "exact rational arithmetic (requested)"; return true;
    case Arithmetic::floating: reason = "floating point (requested)"; return false;
    case Arithmetic::automatic: break;
  }
  if (model.max_significant_digits <= kExactMaxSignificantDigits) {
    reason = "exact rational arithmetic: every number in the model is a short decimal";
    return true;
  }
  reason = fmt::format(
      "floating point: the model has numbers with {} significant digits, taken to be rounded irrational values",
      model.max_significant_digits);
  return false;
}

std::vector<Index> chosen_primaries(const std::vector<std::string>& requested, const std::vector<Magnitude>& magnitudes,
                                    const std::vector<std::size_t>& request_index, Index nullity, const char* kind,
                                    const char* total_name) {
  std::vector<Index> chosen;
  for (std::size_t i = 0; i < requested.size(); ++i) {
    for (std::size_t m = 0; m < magnitudes.size(); ++m)
      if (magnitudes[m].name == requested[i]) chosen.push_back(static_cast<Index>(m));
  }
  if (static_cast<Index>(chosen.size()) != nullity) {
    throw ModelError("primary", request_index.empty() ? -1 : static_cast<int>(request_index.front()),
                     fmt::format("{} {} primary variable(s) given but {} = {}: give exactly {} {} primaries or none",
                                 chosen.size(), kind, total_name, nullity, nullity, kind));
  }
  return chosen;
}

// ---- the stages -------------------------------------------------------------------------
// analyse_network runs these in order; each is a pure function of the model, the options and
// the stages before it, and returns a plain struct (docs/network.md, "The analysis in stages").

// Stage 1 (frame-free): the coupling graph, its spanning tree and the circuit and cutset
// matrices (seed 000 eqs 3a, 3b).
struct NetworkTopologyStage {
  graph::CouplingGraph graph;
  graph::SpanningTree tree;
  Eigen::MatrixXi B, Q;
  graph::TreeWalk walk;  ///< from the ground: how each body's motion sums the couplings' motions
};

NetworkTopologyStage network_topology_stage(const Model& model, int ground) {
  std::vector<graph::Edge> edges;
  for (const auto& c : model.couplings) edges.push_back({c.from, c.to});
  graph::CouplingGraph graph(static_cast<int>(model.bodies.size()), edges);
  check_connected(model, graph);
  graph::SpanningTree tree = choose_tree(model, graph, ground);
  Eigen::MatrixXi B = graph.circuit_matrix(tree);
  Eigen::MatrixXi Q = graph.cutset_matrix(tree);
  graph::TreeWalk walk = graph.walk(tree, ground);
  return {std::move(graph), std::move(tree), std::move(B), std::move(Q), std::move(walk)};
}

// Stage 2, the one boundary into the analysis frame: the arithmetic, the frame every decision
// is made in (the user's own frame for exact arithmetic, where rationals need no
// conditioning; centred on the couplings and scaled by their extent in floating point), and
// the unit matrices in both frames: `solved` for the decisions, `user` for the report.
struct ConditionedNetworkStage {
  bool exact = false;
  std::string arithmetic_reason;
  bool certify = false;  ///< floating point whose ranks of M^N are checked modulo primes
  AnalysisFrame frame;   ///< origin and length unit of the decisions (user frame and units)
  double input_rounding = 0.0;  ///< floating point: rounding level of the input in `frame`
  UnitMatrices user, solved;
  std::vector<Magnitude> motions, actions;  ///< unit screws in the user's frame
};

ConditionedNetworkStage condition_network_stage(const Model& model, const NetworkTopologyStage& topology,
                                                const AnalysisOptions& options) {
  const int d = model.space.dimension();
  ConditionedNetworkStage s;
  s.exact = choose_exact(model, options.arithmetic, s.arithmetic_reason);
  const auto basis_of = [&](std::size_t i, const screw::CouplingGeometry& geometry) {
    const auto& c = model.couplings[i];
    try {
      return screw::coupling_basis(c.type, geometry, model.space);
    } catch (const screw::GeometryError& error) {
      throw ModelError("couplings", static_cast<int>(i), fmt::format("coupling '{}': {}", c.name, error.what()));
    }
  };
  std::vector<screw::CouplingBasis> user_bases;
  for (std::size_t i = 0; i < model.couplings.size(); ++i) user_bases.push_back(basis_of(i, model.couplings[i].geometry));
  // Large models of short decimals: floating point, its ranks checked by modular arithmetic.
  int freedoms = 0;
  for (const auto& b : user_bases) freedoms += static_cast<int>(b.motions.size());
  const int circuit_rows = d * static_cast<int>(topology.B.rows());
  s.certify = s.exact && options.arithmetic == Arithmetic::automatic &&
              elimination_work(circuit_rows, freedoms) > kExactEliminationWork;
  if (s.certify) {
    s.exact = false;
    s.arithmetic_reason = fmt::format(
        "floating point with ranks checked by modular arithmetic: every number is a short decimal, but exact elimination of "
        "the {} x {} matrix M^N would be slow",
        circuit_rows, freedoms);
  }
  s.frame = s.exact ? AnalysisFrame{} : AnalysisFrame::of(model);
  s.input_rounding = s.exact ? 0.0 : input_rounding(model, s.frame);
  s.user = unit_matrices(user_bases, d, topology.B, topology.Q);
  if (s.exact) {
    s.solved = s.user;  // the identity frame: the same bases
  } else {
    std::vector<screw::CouplingBasis> frame_bases;
    for (std::size_t i = 0; i < model.couplings.size(); ++i)
      frame_bases.push_back(basis_of(i, s.frame.to_frame(model.couplings[i].geometry, model.space)));
    s.solved = unit_matrices(frame_bases, d, topology.B, topology.Q);
  }

  std::vector<std::string> motion_names, action_names;
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    for (std::size_t j = 0; j < user_bases[i].motions.size(); ++j)
      motion_names.push_back(magnitude_name(model.couplings[i].name, user_bases[i].motions[j], static_cast<int>(j)));
    for (std::size_t j = 0; j < user_bases[i].actions.size(); ++j)
      action_names.push_back(magnitude_name(model.couplings[i].name, user_bases[i].actions[j], static_cast<int>(j)));
  }
  make_unique(motion_names);
  make_unique(action_names);
  for (std::size_t i = 0, n = 0, a = 0; i < model.couplings.size(); ++i) {
    for (const auto& u : user_bases[i].motions) s.motions.push_back({motion_names[n++], static_cast<int>(i), u});
    for (const auto& u : user_bases[i].actions) s.actions.push_back({action_names[a++], static_cast<int>(i), u});
  }
  return s;
}

// Stage 3 (analysis frame): the ranks of the four methods, (i) circulation law, (ii) cutset
// law, (iii) cutset motions, (iv) circuit actions, with their homogeneous solutions; in
// floating point with the modular check of M^N when `certify`.
struct NetworkRanksStage {
  linalg::HomogeneousSolution circulation, cutset_law, cutset_motion, circuit_action;
  std::optional<ModularCheck> modular_check;
};

// The rank of the user's (rational) M^N modulo large primes is a certain lower bound of its
// exact rank, and equal to it unless both primes divide every non-zero maximal minor. The
// floating-point decisions follow it when they differ (a = C - (d l - m) by the identities),
// unless `follow` is false (the user set the tolerance).
void certify_network_ranks(NetworkRanksStage& s, const ConditionedNetworkStage& c, int d, const Tolerances& base, bool follow) {
  const linalg::ModularRank check = linalg::modular_rank(c.user.MN);
  s.modular_check = ModularCheck{static_cast<int>(check.rank), check.primes, check.agreeing, false};
  if (!follow || check.primes == 0 || check.rank == s.circulation.rank.rank) return;
  const Index l = c.solved.MN.rows() / d;
  const Index m = check.rank, a = c.solved.AD.cols() - (static_cast<Index>(d) * l - m);
  const Eigen::VectorXd motion_values = s.circulation.singular_values;
  const Eigen::VectorXd action_values = s.cutset_law.singular_values;
  s.circulation = solve(c.solved.MN, false, tolerance_for_rank(base, motion_values, m), 0.0);
  s.circuit_action = solve(c.solved.MN.transpose(), false, tolerance_for_rank(base, motion_values, m), 0.0);
  s.cutset_law = solve(c.solved.AN, false, tolerance_for_rank(base, action_values, a), 0.0);
  s.cutset_motion = solve(c.solved.AN.transpose(), false, tolerance_for_rank(base, action_values, a), 0.0);
  s.modular_check->followed = true;
}

NetworkRanksStage decide_network_ranks_stage(const ConditionedNetworkStage& c, int d, const Tolerances& tol) {
  NetworkRanksStage s;
  s.circulation = solve(c.solved.MN, c.exact, tol, c.input_rounding);
  s.cutset_law = solve(c.solved.AN, c.exact, tol, c.input_rounding);
  s.cutset_motion = solve(c.solved.AN.transpose(), c.exact, tol, c.input_rounding);
  s.circuit_action = solve(c.solved.MN.transpose(), c.exact, tol, c.input_rounding);
  // A tolerance the user chose is kept; the check is still reported.
  if (c.certify) certify_network_ranks(s, c, d, tol, !tol.rank);
  return s;
}

// Each body's motion relative to the ground (d rows, one column per primary motion), summed
// along the tree walk from the ground over the coupling blocks of `contracted`.
std::vector<LinearForms> body_motions_along_tree(const graph::TreeWalk& walk, const LinearForms& contracted, int bodies,
                                                 int d, Index primaries, bool exact) {
  std::vector<LinearForms> body_motion(static_cast<std::size_t>(bodies), zero_forms(d, primaries, exact));
  for (int body : walk.order) {
    const int e = walk.parent_edge[static_cast<std::size_t>(body)];
    if (e < 0) continue;
    body_motion[static_cast<std::size_t>(body)] =
        combine(body_motion[static_cast<std::size_t>(walk.parent_body[static_cast<std::size_t>(body)])],
                block_rows(contracted, static_cast<Index>(e) * d, d), walk.sign[static_cast<std::size_t>(body)]);
  }
  return body_motion;
}

// Stage 4 (analysis frame): the primary variables, the magnitudes and contracted matrices of
// all four methods, each body's motion relative to the ground and every pair's fij and cij
// with the primaries that appear in it. Only the pair systems' linear forms are left for the
// user's frame.
struct NetworkBasesStage {
  NetworkRanksStage ranks;  ///< circulation and cutset_law with the chosen free variables
  std::vector<int> primary_motion, primary_action;
  LinearForms M_i, A_ii, M_iii, A_iv;  ///< [M]d,e and [A]d,e by each method, coupling-major
  bool motion_methods_agree = false, action_methods_agree = false;
  std::vector<PairSystem> pairs;  ///< decided; motion_system and action_system still empty
};

// The user's primary variables (`options.primary`, else the model's), split into motions and
// actions, made the free variables of the circulation and cutset laws. Throws ModelError naming
// the first that is not a magnitude or not independent.
void choose_primaries(const Model& model, const ConditionedNetworkStage& c, const AnalysisOptions& options, NetworkBasesStage& s) {
  const std::vector<std::string> requested = options.primary ? *options.primary : model.primary;
  std::vector<std::string> requested_motion, requested_action;
  std::vector<std::size_t> motion_request_index, action_request_index;
  for (std::size_t i = 0; i < requested.size(); ++i) {
    const auto is = [&](const std::vector<Magnitude>& list) {
      return std::any_of(list.begin(), list.end(), [&](const Magnitude& m) { return m.name == requested[i]; });
    };
    if (is(c.motions)) {
      requested_motion.push_back(requested[i]);
      motion_request_index.push_back(i);
    } else if (is(c.actions)) {
      requested_action.push_back(requested[i]);
      action_request_index.push_back(i);
    } else {
      std::vector<std::string> motion_names, action_names;
      for (const auto& m : c.motions) motion_names.push_back(m.name);
      for (const auto& a : c.actions) action_names.push_back(a.name);
      throw ModelError("primary", static_cast<int>(i),
                       fmt::format("'{}' is not a motion or action magnitude of this model (motions: {}; actions: {})",
                                   requested[i], fmt::join(motion_names, ", "), fmt::join(action_names, ", ")));
    }
  }
  auto apply_choice = [&](linalg::HomogeneousSolution& solution, const std::vector<std::string>& names,
                          const std::vector<std::size_t>& request_index, const std::vector<Magnitude>& magnitudes,
                          const char* kind, const char* total) {
    if (names.empty()) return;
    const auto chosen = chosen_primaries(names, magnitudes, request_index, solution.nullity(), kind, total);
    try {
      solution = linalg::with_free_variables(solution, chosen, options.tolerances.free_variable);
    } catch (const linalg::DependentFreeVariable& error) {
      const auto it = std::find(chosen.begin(), chosen.end(), error.variable());
      const std::size_t at = it == chosen.end() ? 0 : static_cast<std::size_t>(it - chosen.begin());
      throw ModelError("primary", static_cast<int>(request_index[at]),
                       fmt::format("'{}' cannot be a primary variable together with the others: the {} primaries must be "
                                   "independent ({} is determined by them or is always zero)",
                                   names[at], kind, names[at]));
    }
  };
  apply_choice(s.ranks.circulation, requested_motion, motion_request_index, c.motions, "motion", "FN");
  apply_choice(s.ranks.cutset_law, requested_action, action_request_index, c.actions, "action", "CN");
}

// Motion of every body relative to the ground, then of every pair (seed 000, section 2.7): fij
// of each pair, cij of each direct coupling, and the primaries that appear in them.
void decide_pairs(const Model& model, const NetworkTopologyStage& topology, const ConditionedNetworkStage& c,
                  const AnalysisOptions& options, NetworkBasesStage& s) {
  const int d = model.space.dimension();
  const int bodies = static_cast<int>(model.bodies.size());
  const auto FN = static_cast<Index>(s.primary_motion.size());
  const std::vector<LinearForms> body_motion = body_motions_along_tree(topology.walk, s.M_i, bodies, d, FN, c.exact);
  const double motion_scale = s.M_i.values.norm(), action_scale = s.A_ii.values.norm();
  // A primary appears when its column is nonzero: exactly, or in floating point above the
  // same absolute threshold that forms_rank uses, so rounding noise does not add primaries.
  const double pair_relative = options.tolerances.pair_rank;
  auto appearing = [pair_relative](const LinearForms& f, double reference) {
    std::vector<int> used;
    for (Index p = 0; p < f.values.cols(); ++p) {
      const bool nonzero = f.exact ? !f.exact->block(0, p, f.exact->rows(), 1).is_zero()
                                   : f.values.col(p).cwiseAbs().maxCoeff() > pair_relative * reference;
      if (nonzero) used.push_back(static_cast<int>(p));
    }
    return used;
  };
  std::vector<std::vector<std::vector<int>>> couplings_of_pair(static_cast<std::size_t>(bodies));
  for (auto& row : couplings_of_pair) row.resize(static_cast<std::size_t>(bodies));
  for (std::size_t e = 0; e < model.couplings.size(); ++e) {
    const int i = std::min(model.couplings[e].from, model.couplings[e].to);
    const int j = std::max(model.couplings[e].from, model.couplings[e].to);
    couplings_of_pair[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)].push_back(static_cast<int>(e));
  }
  for (int i = 0; i < bodies; ++i)
    for (int j = i + 1; j < bodies; ++j) {
      const auto& direct = couplings_of_pair[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      if (direct.empty() && !options.all_pairs) continue;
      PairSystem pair;
      pair.body_i = i;
      pair.body_j = j;
      const LinearForms relative = combine(body_motion[static_cast<std::size_t>(j)], body_motion[static_cast<std::size_t>(i)], -1);
      pair.motion_rank = forms_rank(relative, motion_scale, pair_relative);
      pair.fij = static_cast<int>(pair.motion_rank.rank);
      pair.motion_primaries = appearing(relative, motion_scale);
      if (direct.empty()) {
        pair.f = d;
        s.pairs.push_back(pair);
        continue;
      }
      for (int e : direct) {
        PairSystem row = pair;
        row.coupling = e;
        row.f = c.user.first_motion[static_cast<std::size_t>(e) + 1] - c.user.first_motion[static_cast<std::size_t>(e)];
        row.c = d - row.f;
        const LinearForms action = block_rows(s.A_ii, static_cast<Index>(e) * d, d);
        row.action_rank = forms_rank(action, action_scale, pair_relative);
        row.cij = static_cast<int>(row.action_rank.rank);
        row.action_primaries = appearing(action, action_scale);
        s.pairs.push_back(row);
      }
    }
}

NetworkBasesStage choose_network_bases_stage(const Model& model, const NetworkTopologyStage& topology,
                                             const ConditionedNetworkStage& c, NetworkRanksStage ranks,
                                             const AnalysisOptions& options) {
  const int d = model.space.dimension();
  NetworkBasesStage s;
  s.ranks = std::move(ranks);

  // Primary variables: the user's, or the earliest that can be free.
  choose_primaries(model, c, options, s);
  for (Index v : s.ranks.circulation.free_variables) s.primary_motion.push_back(static_cast<int>(v));
  for (Index v : s.ranks.cutset_law.free_variables) s.primary_action.push_back(static_cast<int>(v));

  // Contracted matrices [M]d,e and [A]d,e by both methods each.
  const LinearForms K_motion = solution_forms(s.ranks.circulation);
  const LinearForms K_action = solution_forms(s.ranks.cutset_law);
  s.M_i = contract_couplings(c.solved.MD, c.solved.first_motion, K_motion, d, c.exact);
  s.A_ii = contract_couplings(c.solved.AD, c.solved.first_action, K_action, d, c.exact);
  s.M_iii = contract_graph(solution_forms(s.ranks.cutset_motion), topology.Q, d, c.exact);
  s.A_iv = contract_graph(solution_forms(s.ranks.circuit_action), topology.B, d, c.exact);
  s.motion_methods_agree = same_span(s.M_i, s.M_iii, options.tolerances.pair_rank);
  s.action_methods_agree = same_span(s.A_ii, s.A_iv, options.tolerances.pair_rank);

  decide_pairs(model, topology, c, options, s);
  return s;
}

// The body motions (along the tree, from the user's contracted motions) and the pairs' motion
// and action systems in the user's frame.
void pair_systems_in_user_frame(const NetworkTopologyStage& topology, std::vector<PairSystem> pairs, double pair_relative,
                                NetworkResult& r) {
  const int d = r.d;
  r.body_motions = body_motions_along_tree(topology.walk, r.circulation.contracted, r.bodies, d, r.FN, r.exact);
  r.pairs = std::move(pairs);
  // In floating point, what the difference of two body motions leaves below the threshold the
  // pair decisions use (pair_relative of the whole network's forms) is rounding, and is shown
  // as zero: a welded pair's motions print as 0, not as 1e-16 * s_R1 + ...
  const double pair_noise = r.exact ? 0.0 : pair_relative * r.circulation.contracted.values.norm();
  for (PairSystem& pair : r.pairs) {
    pair.motion_system = combine(r.body_motions[static_cast<std::size_t>(pair.body_j)],
                                 r.body_motions[static_cast<std::size_t>(pair.body_i)], -1);
    if (!pair.motion_system.exact)
      pair.motion_system.values = pair.motion_system.values.unaryExpr([pair_noise](double x) { return std::abs(x) <= pair_noise ? 0.0 : x; });
    pair.action_system = pair.coupling ? block_rows(r.cutset_law.contracted, static_cast<Index>(*pair.coupling) * d, d)
                                       : zero_forms(d, r.CN, r.exact);
  }
}

// Stage 5, the one boundary back to the user's frame: everything decided above, with the
// magnitudes, contracted matrices, body motions and pair systems in the user's frame, length
// unit and primaries. The redundant rows of floating-point M^N and A^N are the one choice made
// here, on the user's matrices: the conditioned frame mixes the d rows of each circuit
// (cutset), so the rows that are redundant there are not the user's.
NetworkResult network_in_user_frame(const Model& model, NetworkTopologyStage topology, ConditionedNetworkStage c,
                                    NetworkBasesStage b, double pair_relative) {
  NetworkResult r;
  r.model_name = model.name;
  r.d = model.space.dimension();
  const int d = r.d;
  r.bodies = static_cast<int>(model.bodies.size());
  r.e = static_cast<int>(model.couplings.size());
  r.ground = model.ground.value_or(0);
  r.branches = std::move(topology.tree.branches);
  r.chords = std::move(topology.tree.chords);
  r.B = std::move(topology.B);
  r.Q = std::move(topology.Q);
  r.l = static_cast<int>(r.B.rows());
  r.k = static_cast<int>(r.Q.rows());
  r.exact = c.exact;
  r.arithmetic_reason = std::move(c.arithmetic_reason);
  r.length_scale = c.frame.scale.get_d();
  r.F = static_cast<int>(c.user.MD.cols());
  r.C = static_cast<int>(c.user.AD.cols());
  r.motions = std::move(c.motions);
  r.actions = std::move(c.actions);

  r.circulation.solution = std::move(b.ranks.circulation);
  r.cutset_law.solution = std::move(b.ranks.cutset_law);
  r.cutset_motion.solution = std::move(b.ranks.cutset_motion);
  r.circuit_action.solution = std::move(b.ranks.circuit_action);
  r.modular_check = b.ranks.modular_check;
  if (!r.exact) {
    r.circulation.solution.redundant_rows = linalg::redundant_rows(c.user.MN.to_double(), r.circulation.solution.rank.rank);
    r.cutset_law.solution.redundant_rows = linalg::redundant_rows(c.user.AN.to_double(), r.cutset_law.solution.rank.rank);
  }
  r.m = static_cast<int>(r.circulation.solution.rank.rank);
  r.a = static_cast<int>(r.cutset_law.solution.rank.rank);
  r.FN = r.F - r.m;
  r.CN = r.C - r.a;
  r.classification = classify(r.FN, r.CN);
  r.identities_hold = r.FN - r.CN == r.F - d * r.l && r.CN - r.FN == r.C - d * r.k && r.FN == d * r.k - r.a &&
                      r.CN == d * r.l - r.m && r.cutset_motion.solution.nullity() == r.FN &&
                      r.circuit_action.solution.nullity() == r.CN;
  r.primary_motion = std::move(b.primary_motion);
  r.primary_action = std::move(b.primary_action);

  // Unit translations and torques built in the analysis frame are L times those of the user's
  // frame, so their magnitudes are 1/L of the user's: map coefficients back exactly.
  r.motion_magnitudes = to_user_magnitudes(solution_forms(r.circulation.solution), r.motions, r.primary_motion, c.frame.scale);
  r.action_magnitudes = to_user_magnitudes(solution_forms(r.cutset_law.solution), r.actions, r.primary_action, c.frame.scale);
  r.circulation.solution.coefficients = r.motion_magnitudes.values;
  r.circulation.solution.exact_coefficients = r.motion_magnitudes.exact;
  r.cutset_law.solution.coefficients = r.action_magnitudes.values;
  r.cutset_law.solution.exact_coefficients = r.action_magnitudes.exact;

  // Contracted matrices: (i) and (ii) from the user's unit matrices and magnitudes, (iii) and
  // (iv) moved block by block.
  const AnalysisFrame& frame = c.frame;
  const auto motion_to_user = [&](const std::vector<Rational>& v) { return frame.motion_to_user(v, model.space); };
  const auto action_to_user = [&](const std::vector<Rational>& v) { return frame.action_to_user(v, model.space); };
  r.motion_methods_agree = b.motion_methods_agree;
  r.action_methods_agree = b.action_methods_agree;
  r.circulation.contracted = contract_couplings(c.user.MD, c.user.first_motion, r.motion_magnitudes, d, r.exact);
  r.cutset_law.contracted = contract_couplings(c.user.AD, c.user.first_action, r.action_magnitudes, d, r.exact);
  r.cutset_motion.contracted = blocks_to_user(b.M_iii, d, motion_to_user);
  r.circuit_action.contracted = blocks_to_user(b.A_iv, d, action_to_user);
  r.BM = std::move(c.user.BM);
  r.QA = std::move(c.user.QA);
  r.MD = std::move(c.user.MD);
  r.AD = std::move(c.user.AD);
  r.MN = std::move(c.user.MN);
  r.AN = std::move(c.user.AN);

  // Body motions and pair systems.
  pair_systems_in_user_frame(topology, std::move(b.pairs), pair_relative, r);
  return r;
}

// Stage 6 (user frame): numeric magnitudes and coupling screws from the values of the
// primaries given in the model or the options.
struct NetworkValuesStage {
  std::optional<Eigen::VectorXd> motion_values, action_values;
  std::vector<std::string> missing_motion_values, missing_action_values;
  std::optional<Eigen::MatrixXd> coupling_motion_values, coupling_action_values;
};

NetworkValuesStage network_values_stage(const Model& model, const NetworkResult& r, const AnalysisOptions& options) {
  const int d = r.d;
  NetworkValuesStage s;
  std::vector<std::pair<std::string, Rational>> values = model.values;
  for (const auto& v : options.values) {
    auto it = std::find_if(values.begin(), values.end(), [&](const auto& x) { return x.first == v.first; });
    if (it != values.end()) it->second = v.second; else values.push_back(v);
  }
  // The primaries' values, NaN for those without one; empty when none of this kind has one.
  auto value_vector = [&](const std::vector<int>& primaries, const std::vector<Magnitude>& magnitudes,
                          std::vector<std::string>& missing) {
    std::optional<Eigen::VectorXd> vector = Eigen::VectorXd(static_cast<Index>(primaries.size()));
    bool any = false;
    for (std::size_t p = 0; p < primaries.size(); ++p) {
      const std::string& name = magnitudes[static_cast<std::size_t>(primaries[p])].name;
      auto it = std::find_if(values.begin(), values.end(), [&](const auto& x) { return x.first == name; });
      if (it == values.end()) {
        missing.push_back(name);
        (*vector)(static_cast<Index>(p)) = std::numeric_limits<double>::quiet_NaN();
      } else {
        any = true;
        (*vector)(static_cast<Index>(p)) = it->second.get_d();
      }
    }
    if (!any) missing.clear();
    return any ? vector : std::optional<Eigen::VectorXd>{};
  };
  // forms * v where a row is evaluated only when it does not involve a primary without a value
  // (0 * NaN would otherwise spoil every row).
  auto evaluate = [](const Eigen::MatrixXd& forms, const Eigen::VectorXd& v) {
    Eigen::VectorXd out(forms.rows());
    for (Index i = 0; i < forms.rows(); ++i) {
      double sum = 0.0;
      for (Index j = 0; j < forms.cols(); ++j)
        if (forms(i, j) != 0.0) sum += forms(i, j) * v(j);
      out(i) = sum;
    }
    return out;
  };
  for (std::size_t v = 0; v < values.size(); ++v) {
    const auto is_primary = [&](const std::vector<int>& primaries, const std::vector<Magnitude>& magnitudes) {
      return std::any_of(primaries.begin(), primaries.end(),
                         [&](int p) { return magnitudes[static_cast<std::size_t>(p)].name == values[v].first; });
    };
    if (!is_primary(r.primary_motion, r.motions) && !is_primary(r.primary_action, r.actions))
      throw ModelError("values", static_cast<int>(v),
                       fmt::format("'{}' is not a primary variable; values can be given for the primaries only", values[v].first));
  }
  // Coupling screws from the contracted forms: block e (d rows) times the primary values.
  auto coupling_screws = [&](const LinearForms& contracted, const Eigen::VectorXd& v) {
    Eigen::MatrixXd screws(d, r.e);
    for (int e = 0; e < r.e; ++e) screws.col(e) = evaluate(contracted.values.middleRows(static_cast<Index>(e) * d, d), v);
    return screws;
  };
  if (auto v = value_vector(r.primary_motion, r.motions, s.missing_motion_values); v && r.FN > 0) {
    s.motion_values = evaluate(r.motion_magnitudes.values, *v);
    s.coupling_motion_values = coupling_screws(r.circulation.contracted, *v);
  }
  if (auto v = value_vector(r.primary_action, r.actions, s.missing_action_values); v && r.CN > 0) {
    s.action_values = evaluate(r.action_magnitudes.values, *v);
    s.coupling_action_values = coupling_screws(r.cutset_law.contracted, *v);
  }
  return s;
}

// Stage 7 (exact analyses only): the evidence of a floating-point SVD of the same matrices in
// the conditioned frame (placement- and unit-free), how near the design is to another rank;
// and, for long literals, the floating-point FN and CN when they differ (exact arithmetic then
// analyses the rounded geometry, floating point tolerates the rounding).
struct ExactEvidenceStage {
  Eigen::VectorXd motion_values, action_values;  ///< singular values of M^N and A^N, conditioned frame
  std::optional<std::pair<int, int>> floating_point_disagreement;
};

ExactEvidenceStage exact_evidence_stage(const Model& model, const NetworkResult& r, const Tolerances& tol) {
  ExactEvidenceStage s;
  const AnalysisFrame conditioned = AnalysisFrame::of(model);
  std::vector<screw::CouplingBasis> bases;
  for (const auto& c : model.couplings) bases.push_back(screw::coupling_basis(c.type, conditioned.to_frame(c.geometry, model.space), model.space));
  const UnitMatrices u = unit_matrices(bases, r.d, r.B, r.Q);
  const Eigen::MatrixXd mn = u.MN.to_double(), an = u.AN.to_double();
  s.motion_values = linalg::singular_values(mn);
  s.action_values = linalg::singular_values(an);
  if (model.max_significant_digits > kExactMaxSignificantDigits) {
    const linalg::RankTolerance rounded{tol.rank, input_rounding(model, conditioned)};
    const int fn = r.F - static_cast<int>(linalg::decide_rank(s.motion_values, mn.rows(), mn.cols(), rounded).rank);
    const int cn = r.C - static_cast<int>(linalg::decide_rank(s.action_values, an.rows(), an.cols(), rounded).rank);
    if (fn != r.FN || cn != r.CN) s.floating_point_disagreement = std::make_pair(fn, cn);
  }
  return s;
}

}  // namespace

NetworkResult analyse_network(const Model& model, const AnalysisOptions& options) {
  if (model.couplings.empty()) throw ModelError("couplings", -1, "the model has no couplings");
  const int ground = model.ground.value_or(0);
  NetworkTopologyStage topology = network_topology_stage(model, ground);
  options.stop.throw_if_requested();
  ConditionedNetworkStage conditioned = condition_network_stage(model, topology, options);
  options.stop.throw_if_requested();
  NetworkRanksStage ranks = decide_network_ranks_stage(conditioned, model.space.dimension(), options.tolerances);
  options.stop.throw_if_requested();
  NetworkBasesStage bases = choose_network_bases_stage(model, topology, conditioned, std::move(ranks), options);
  options.stop.throw_if_requested();
  NetworkResult r =
      network_in_user_frame(model, std::move(topology), std::move(conditioned), std::move(bases), options.tolerances.pair_rank);
  options.stop.throw_if_requested();

  NetworkValuesStage values = network_values_stage(model, r, options);
  r.motion_values = std::move(values.motion_values);
  r.action_values = std::move(values.action_values);
  r.missing_motion_values = std::move(values.missing_motion_values);
  r.missing_action_values = std::move(values.missing_action_values);
  r.coupling_motion_values = std::move(values.coupling_motion_values);
  r.coupling_action_values = std::move(values.coupling_action_values);

  if (r.exact) {
    const ExactEvidenceStage evidence = exact_evidence_stage(model, r, options.tolerances);
    linalg::add_floating_evidence(r.circulation.solution.rank, evidence.motion_values);
    linalg::add_floating_evidence(r.circuit_action.solution.rank, evidence.motion_values);
    linalg::add_floating_evidence(r.cutset_law.solution.rank, evidence.action_values);
    linalg::add_floating_evidence(r.cutset_motion.solution.rank, evidence.action_values);
    r.floating_point_disagreement = evidence.floating_point_disagreement;
  }
  return r;
}

}  // namespace kinestat::network
