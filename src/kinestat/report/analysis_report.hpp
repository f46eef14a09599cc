// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The JSON report of a framework or network model as `kinestat analyze --json MODEL` prints it
// with its default options: the analysis, the generic answer, the verdict and the report, in
// one pure function (the sweep runs it on every variant).

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/report/network_report.hpp"

namespace kinestat::report {

/// A coupling network as every command reports it (`analyze`, `report`, `draw`, the sweep and
/// the Python module): the analysis (network::analyse_network, in stages, docs/network.md), the
/// design verdict with the generic answer's sentences, the generic answer and the second-order
/// classification of the motions. Every screw in it is in the user's frame and length unit.
struct NetworkAnalysis {
  network::NetworkResult result;
  design::Verdict verdict;
  std::optional<network::GenericNetwork> generic;  ///< none for screw spaces other than spatial and planar
  std::optional<network::NetworkSecondOrder> second_order;  ///< when NetworkAnalysisParts::second_order
  /// The report options of this analysis (pointers into it: it must outlive them).
  NetworkReportOptions report_options() const;
};

struct NetworkAnalysisParts {
  /// Classify the motions at second order and trace those that pass, with the analysis's
  /// rank rule (network::rank_rule_of): the reports do, the pictures do not.
  bool second_order = true;
  /// Called on the analysis before anything is derived from it; may throw (the CLI refuses
  /// results that overflow a double here).
  std::function<void(const network::NetworkResult&)> check;
};

/// The one entry of the dense network pipeline: `model` analysed with `options`, then its
/// verdict, generic answer and (with parts.second_order) second-order classification. Throws
/// network::ModelError for problems the analysis finds in the model (the caller locates them).
NetworkAnalysis analyse_network_as_reported(const network::Model& model, const network::AnalysisOptions& options,
                                            const NetworkAnalysisParts& parts = {});

/// The sparse path as reported (networks above network::kDenseNetworkLimit couplings): the
/// counts, supports and the verdict's basis vectors (network::analyse_network_sparse, in the
/// conditioned analysis frame, supports by coupling index), and the verdict.
struct SparseNetworkAnalysis {
  network::SparseNetworkResult result;
  design::Verdict verdict;
  std::vector<network::SparsePairFreedom> pairs;  ///< when asked for (listed_pairs)
  bool listed_pairs = false;
};

/// The one entry of the sparse network pipeline. With `chosen` pairs (body indices) or
/// `coupled_pairs`, also fij and cij of those pairs (network::sparse_pair_freedoms); relative
/// rank tolerances from `tolerances`. Throws network::ModelError.
SparseNetworkAnalysis analyse_sparse_network_as_reported(const network::Model& model, const Tolerances& tolerances,
                                                         const std::vector<std::pair<int, int>>& chosen = {},
                                                         bool coupled_pairs = false);

/// The report of `model` (a framework or a network; a structure model is an InputError) with the
/// relative rank tolerance `tolerance` (default: the LAPACK rule, as `--tolerance`). Networks
/// above network::kDenseNetworkLimit couplings take the sparse path, as `analyze` does. A
/// problem the analysis finds in the model is an InputError at its place in `model.path`.
nlohmann::ordered_json analysis_report_json(const io::ModelFile& model, std::optional<double> tolerance = {});

}  // namespace kinestat::report
