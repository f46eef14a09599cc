// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The coupling-network pipeline: plan (dense or sparse), analyse, verdict, generic answer and,
// on the dense path, the second-order classification of the motions — composed once here for
// every caller (the commands, the Python module, the sweep, the pictures). Pure functions
// returning plain results: no files, no streams. Every screw of a dense or sparse result is in
// the user's frame and length unit (each analysis converts once, in its last stage).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/generic_network.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/network/sparse_pair_freedoms.hpp"
#include "kinestat/report/network_report.hpp"

namespace kinestat::pipeline {

/// Davies' dense matrices, or the sparse body-twist path (network/sparse_network.hpp).
enum class NetworkPath { dense, sparse };

/// What a caller asks of a network analysis.
struct NetworkRequest {
  /// Tolerances, arithmetic, primary variables, values, which pairs, the stop request.
  network::AnalysisOptions options;
  /// The path asked for; `automatic`: sparse above network::kDenseNetworkLimit couplings unless
  /// something only the dense path gives is asked for (exact arithmetic, primary variables,
  /// values, the matrices), since the dense matrices grow as the cube of the network.
  enum class Path { automatic, dense, sparse } path = Path::automatic;
  bool matrices = false;  ///< the report is to show the dense matrices (a dense-only output)
  /// Sparse path: fij and cij of these pairs (body indices) and, with `coupled_pairs`, of every
  /// coupled pair (network::sparse_pair_freedoms).
  std::vector<std::pair<int, int>> pairs;
  bool coupled_pairs = false;
  /// Dense path: classify the motions at second order and trace those that pass (the reports
  /// do; the pictures do not need it).
  bool second_order = true;
};

/// True when `request` asks for something only Davies' dense matrices give.
bool needs_dense_path(const NetworkRequest& request);

/// The one choice of path for `model` under `request` (see NetworkRequest::path).
NetworkPath network_path(const network::Model& model, const NetworkRequest& request);

/// A coupling network analysed on the dense path as every command reports it: the analysis
/// (network::analyse_network, in stages, docs/network.md), the design verdict with the generic
/// answer's sentences, the generic answer and the second-order classification of the motions.
/// Every screw in it is in the user's frame and length unit.
struct NetworkAnalysis {
  network::NetworkResult result;
  design::Verdict verdict;
  std::optional<network::GenericNetwork> generic;  ///< none for screw spaces other than spatial and planar
  std::optional<network::NetworkSecondOrder> second_order;  ///< when NetworkRequest::second_order
  /// The report options of this analysis (pointers into it: it must outlive them).
  report::NetworkReportOptions report_options() const;
};

/// The sparse path as reported: the counts, supports and the verdict's basis vectors
/// (network::analyse_network_sparse, in the user's frame, supports by coupling index), the
/// verdict, and the pairs asked for.
struct SparseNetworkAnalysis {
  network::SparseNetworkResult result;
  design::Verdict verdict;
  std::vector<network::SparsePairFreedom> pairs;  ///< when asked for (listed_pairs)
  bool listed_pairs = false;
  /// The pairs to list in a report: null when none were asked for.
  const std::vector<network::SparsePairFreedom>* listed() const { return listed_pairs ? &pairs : nullptr; }
};

/// The dense path with `options` (second order when `second_order`). Throws network::ModelError
/// for problems the analysis finds in the model — also (field "values") when a result
/// overflows a double, before anything is derived from it; the caller locates them
/// (io::locate).
NetworkAnalysis analyse_dense_network(const network::Model& model, const network::AnalysisOptions& options,
                                      bool second_order = true);

/// The sparse path: relative rank tolerances from `tolerances`; with `chosen` pairs (body
/// indices) or `coupled_pairs`, also fij and cij of those pairs; each factorisation within
/// `memory_limit` (linalg::FactorisationTooLarge beyond it). Throws network::ModelError.
SparseNetworkAnalysis analyse_sparse_network(const network::Model& model, const Tolerances& tolerances,
                                             const std::vector<std::pair<int, int>>& chosen = {},
                                             bool coupled_pairs = false, linalg::MemoryLimit memory_limit = {});

/// A network analysed on the path network_path chose: exactly one of the two is set.
struct NetworkAnalyses {
  std::optional<NetworkAnalysis> dense;
  std::optional<SparseNetworkAnalysis> sparse;
  const design::Verdict& verdict() const { return dense ? dense->verdict : sparse->verdict; }
};

/// The network pipeline for `model` under `request`. Throws network::ModelError (unlocated).
NetworkAnalyses analyse_network(const network::Model& model, const NetworkRequest& request);

/// The name of the first numeric result of a dense analysis that is not finite (the values
/// given, or the model's geometry, overflowed a double), or nothing when all are finite.
std::optional<std::string> first_non_finite_result(const network::NetworkResult& result);

}  // namespace kinestat::pipeline
