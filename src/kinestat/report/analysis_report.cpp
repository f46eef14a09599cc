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
  if (static_cast<int>(loaded.model.couplings.size()) > network::kDenseNetworkLimit) {
    network::SparseNetworkResult sparse;
    try {
      sparse = network::analyse_network_sparse(loaded.model, options.tolerances, design::kSparseVerdictStates, false);
    } catch (const network::ModelError& error) {
      throw io::locate(error, loaded, path);
    }
    const design::Verdict verdict = design::sparse_network_verdict(loaded.model, sparse, options.tolerances);
    return sparse_network_report_json(loaded.model, sparse, &verdict, nullptr);
  }
  const network::NetworkResult result = io::analyse_network_file(loaded, path, options);
  design::Verdict verdict = design::network_verdict(loaded.model, result, options);
  NetworkReportOptions report_options;
  report_options.verdict = &verdict;
  const std::optional<network::GenericNetwork> generic = network::generic_network(loaded.model, result);
  if (generic) {
    report_options.generic = &*generic;
    verdict.generic = network_generic_sentences(loaded.model, result, *generic);
  }
  // As `kinestat analyze`: passing motions traced with the analysis's rank rule.
  network::NetworkSecondOrderOptions second_order_options;
  second_order_options.tracing.tolerance =
      network::rank_rule_of(loaded.model, options.tolerances.rank);
  const network::NetworkSecondOrder second_order = network::classify_network_motions(loaded.model, result, second_order_options);
  report_options.second_order = &second_order;
  return network_report_json(loaded.model, result, report_options);
}

}  // namespace

nlohmann::ordered_json analysis_report_json(const io::ModelFile& model, std::optional<double> tolerance) {
  if (model.framework) return framework_json(*model.framework, tolerance);
  if (model.network) return network_json(*model.network, model.path, tolerance);
  throw io::InputError({model.path, 1, 1}, "a model of kind 'structure' is analysed with 'kinestat structure', not here");
}

}  // namespace kinestat::report
