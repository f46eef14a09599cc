// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/network_pipeline.hpp"

#include <fmt/format.h>

#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/network/analysis_frame.hpp"

namespace kinestat::pipeline {

namespace {

template <typename Derived>
bool all_finite(const Eigen::DenseBase<Derived>& m) {
  return m.allFinite();
}

// Values of magnitudes: NaN marks a magnitude that partial values leave undetermined (issue 10),
// so only an infinity is an overflow there.
template <typename Derived>
bool no_infinity(const Eigen::DenseBase<Derived>& m) {
  return !m.derived().array().isInf().any();
}

}  // namespace

std::optional<std::string> first_non_finite_result(const network::NetworkResult& result) {
  if (result.motion_values && !no_infinity(*result.motion_values)) return "a motion magnitude";
  if (result.action_values && !no_infinity(*result.action_values)) return "an action magnitude";
  if (result.coupling_motion_values && !no_infinity(*result.coupling_motion_values)) return "a coupling motion";
  if (result.coupling_action_values && !no_infinity(*result.coupling_action_values)) return "a coupling action";
  if (!all_finite(result.motion_magnitudes.values)) return "a coefficient of the motion magnitudes";
  if (!all_finite(result.action_magnitudes.values)) return "a coefficient of the action magnitudes";
  for (const auto& pair : result.pairs) {
    if (!all_finite(pair.motion_system.values) || !all_finite(pair.action_system.values))
      return std::string("a coefficient of a pair system");
  }
  return std::nullopt;
}

bool needs_dense_path(const NetworkRequest& request) {
  const network::AnalysisOptions& o = request.options;
  return request.path == NetworkRequest::Path::dense || request.matrices || o.arithmetic == network::Arithmetic::exact ||
         (o.primary && !o.primary->empty()) || !o.values.empty();
}

NetworkPath network_path(const network::Model& model, const NetworkRequest& request) {
  if (request.path == NetworkRequest::Path::sparse) return NetworkPath::sparse;
  if (needs_dense_path(request)) return NetworkPath::dense;
  return static_cast<int>(model.couplings.size()) > network::kDenseNetworkLimit ? NetworkPath::sparse : NetworkPath::dense;
}

report::NetworkReportOptions NetworkAnalysis::report_options() const {
  report::NetworkReportOptions options;
  options.verdict = &verdict;
  if (generic) options.generic = &*generic;
  if (second_order) options.second_order = &*second_order;
  return options;
}

NetworkAnalysis analyse_dense_network(const network::Model& model, const network::AnalysisOptions& options,
                                      bool second_order) {
  NetworkAnalysis a;
  a.result = network::analyse_network(model, options);
  // Results that overflow a double are refused before anything is derived from them.
  if (const auto overflowing = first_non_finite_result(a.result)) {
    throw network::ModelError("values", -1,
                              fmt::format("{} overflows a double (beyond about 1e308): the values or coordinates are too "
                                          "large; scale them down (units do not change the counts)",
                                          *overflowing));
  }
  options.stop.throw_if_requested();
  a.verdict = design::network_verdict(model, a.result, options);
  options.stop.throw_if_requested();
  a.generic = network::generic_network(model, a.result);
  if (a.generic) a.verdict.generic = report::network_generic_sentences(model, a.result, *a.generic);
  if (second_order) {
    // Motions that pass second order are traced with the analysis's rank rule (`--tolerance`).
    network::NetworkSecondOrderOptions second_order_options;
    second_order_options.tracing.tolerance = network::rank_rule_of(model, options.tolerances.rank);
    a.second_order = network::classify_network_motions(model, a.result, second_order_options);
  }
  return a;
}

SparseNetworkAnalysis analyse_sparse_network(const network::Model& model, const Tolerances& tolerances,
                                             const std::vector<std::pair<int, int>>& chosen, bool coupled_pairs,
                                             linalg::MemoryLimit memory_limit) {
  SparseNetworkAnalysis a;
  a.listed_pairs = !chosen.empty() || coupled_pairs;
  // The analysis, then the verdict's idle spins (which need only K): one after the other, no
  // callback between the factorisations (issue 36: running them beside K's factor saved nothing).
  a.result = network::analyse_network_sparse(model, tolerances, design::kSparseVerdictStates, a.listed_pairs, memory_limit);
  const std::vector<design::IdleMotion> idle_spins = design::sparse_idle_spins(model, a.result, tolerances);
  if (a.listed_pairs) a.pairs = network::sparse_pair_freedoms(model, a.result, chosen, coupled_pairs, tolerances);
  a.verdict = design::sparse_network_verdict(model, a.result, idle_spins);
  return a;
}

NetworkAnalyses analyse_network(const network::Model& model, const NetworkRequest& request) {
  NetworkAnalyses analyses;
  if (network_path(model, request) == NetworkPath::sparse) {
    analyses.sparse = analyse_sparse_network(model, request.options.tolerances, request.pairs, request.coupled_pairs,
                                             request.options.memory_limit);
    request.options.stop.throw_if_requested();
  } else {
    analyses.dense = analyse_dense_network(model, request.options, request.second_order);
  }
  return analyses;
}

}  // namespace kinestat::pipeline
