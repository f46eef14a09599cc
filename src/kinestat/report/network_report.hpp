// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Text and JSON reports of a coupling-network analysis.

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/design/verdict.hpp"
#include "kinestat/network/generic_network.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/network/sparse_pair_freedoms.hpp"

namespace kinestat::report {

struct NetworkReportOptions {
  bool matrices = false;  ///< include B, Q, BM, QA, M^D, A^D, M^N, A^N
  const design::Verdict* verdict = nullptr;  ///< printed first when given (design::network_verdict)
  const network::GenericNetwork* generic = nullptr;  ///< the generic answer (network::generic_network), when computed
  const network::NetworkSecondOrder* second_order = nullptr;  ///< network::classify_network_motions, when computed
};

/// Human-readable report: summary with rank evidence, class, primaries, magnitudes,
/// contracted matrices, the pair table (seed 000, Table 1) and warnings.
std::string network_report_text(const network::Model& model, const network::NetworkResult& result,
                         const NetworkReportOptions& options = {});

/// Machine-readable report with keys in a fixed order, so the same input gives
/// byte-identical output.
nlohmann::ordered_json network_report_json(const network::Model& model, const network::NetworkResult& result,
                                    const NetworkReportOptions& options = {});

/// The generic answer in one sentence per count (FN, CN), raw names (not escaped).
std::vector<std::string> network_generic_sentences(const network::Model& model, const network::NetworkResult& result,
                                                   const network::GenericNetwork& generic);

/// Bounded report of the sparse path: the verdict first when given
/// (design::sparse_network_verdict), counts, class, rank evidence (also of the basis vectors the
/// verdict used), the couplings that carry a self-stress and those that move, and what was not
/// computed. With `pairs` (network::sparse_pair_freedoms) also the pair table (f, fij, c, cij
/// of the chosen pairs; JSON `pairs`, the dense path's keys without the linear forms).
std::string sparse_network_report_text(const network::Model& model, const network::SparseNetworkResult& result,
                                const design::Verdict* verdict = nullptr,
                                const std::vector<network::SparsePairFreedom>* pairs = nullptr);
nlohmann::ordered_json sparse_network_report_json(const network::Model& model, const network::SparseNetworkResult& result,
                                           const design::Verdict* verdict = nullptr,
                                           const std::vector<network::SparsePairFreedom>* pairs = nullptr);

}  // namespace kinestat::report
