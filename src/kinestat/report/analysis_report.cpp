// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/analysis_report.hpp"

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/generic_network.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/network_report.hpp"

namespace kinestat::report {

namespace {

// As src/cli/framework_command.cpp with its default options.
nlohmann::ordered_json framework_json(const framework::FrameworkModel& model, std::optional<double> tolerance) {
  framework::AnalysisOptions options;
  options.tolerances = Tolerances::with_rank(tolerance);
  std::optional<framework::GenericFramework> generic;
  const framework::FrameworkResult analysis = framework::analyse_framework_as_reported(model, options, &generic);
  design::Verdict verdict = design::framework_verdict(model, analysis, options);
  if (generic) verdict.generic = framework_generic_sentences(model, analysis, *generic);
  return framework_report_json(model, analysis, &verdict, generic ? &*generic : nullptr);
}

// As src/cli/network_command.cpp with its default options.
nlohmann::ordered_json network_json(const io::LoadedNetwork& loaded, const std::string& path, std::optional<double> tolerance) {
  network::AnalysisOptions options;
  options.tolerances = Tolerances::with_rank(tolerance);
  try {
    if (static_cast<int>(loaded.model.couplings.size()) > network::kDenseNetworkLimit) {
      const SparseNetworkAnalysis sparse = analyse_sparse_network_as_reported(loaded.model, options.tolerances);
      return sparse_network_report_json(loaded.model, sparse.result, &sparse.verdict, nullptr);
    }
    const NetworkAnalysis analysis = analyse_network_as_reported(loaded.model, options);
    return network_report_json(loaded.model, analysis.result, analysis.report_options());
  } catch (const network::ModelError& error) {
    throw io::locate(error, loaded, path);
  }
}

}  // namespace

NetworkReportOptions NetworkAnalysis::report_options() const {
  NetworkReportOptions options;
  options.verdict = &verdict;
  if (generic) options.generic = &*generic;
  if (second_order) options.second_order = &*second_order;
  return options;
}

NetworkAnalysis analyse_network_as_reported(const network::Model& model, const network::AnalysisOptions& options,
                                            const NetworkAnalysisParts& parts) {
  NetworkAnalysis a;
  a.result = network::analyse_network(model, options);
  if (parts.check) parts.check(a.result);
  a.verdict = design::network_verdict(model, a.result, options);
  a.generic = network::generic_network(model, a.result);
  if (a.generic) a.verdict.generic = network_generic_sentences(model, a.result, *a.generic);
  if (parts.second_order) {
    // Motions that pass second order are traced with the analysis's rank rule (`--tolerance`).
    network::NetworkSecondOrderOptions second_order_options;
    second_order_options.tracing.tolerance = network::rank_rule_of(model, options.tolerances.rank);
    a.second_order = network::classify_network_motions(model, a.result, second_order_options);
  }
  return a;
}

SparseNetworkAnalysis analyse_sparse_network_as_reported(const network::Model& model, const Tolerances& tolerances,
                                                         const std::vector<std::pair<int, int>>& chosen,
                                                         bool coupled_pairs) {
  SparseNetworkAnalysis a;
  a.listed_pairs = !chosen.empty() || coupled_pairs;
  // The idle spins need only K: they are found while K's factor may still be running.
  std::vector<design::IdleMotion> idle_spins;
  a.result = network::analyse_network_sparse(model, tolerances, design::kSparseVerdictStates, a.listed_pairs,
                                              [&](const network::SparseNetworkResult& system) {
                                                idle_spins = design::sparse_idle_spins(model, system, tolerances);
                                              });
  if (a.listed_pairs) a.pairs = network::sparse_pair_freedoms(model, a.result, chosen, coupled_pairs, tolerances);
  a.verdict = design::sparse_network_verdict(model, a.result, idle_spins);
  return a;
}

nlohmann::ordered_json analysis_report_json(const io::ModelFile& model, std::optional<double> tolerance) {
  if (model.framework) return framework_json(*model.framework, tolerance);
  if (model.network) return network_json(*model.network, model.path, tolerance);
  throw io::InputError({model.path, 1, 1}, "a model of kind 'structure' is analysed with 'kinestat structure', not here");
}

}  // namespace kinestat::report
