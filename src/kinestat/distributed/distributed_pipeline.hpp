// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The pipeline of the distributed path (`kinestat analyze --backend petsc`, issue 36's "one
// result shape per kind for every path"): rank 0 reads the model and builds the matrix the
// serial sparse path builds (D(c) of a framework, K of a coupling network), the rank is decided
// by decomposed_rank (which sends the other processes their rows), and the result is the serial sparse path's own type in
// the user frame, so that the serial report writers format it. It lives beside the backend
// (kinestat_petsc) rather than in pipeline/, because it calls MPI. Counts and rank evidence
// only: the method gives no null vectors, so modes, stress states, supports and pair freedoms
// are not computed (DistributedAnalysis::not_computed names them for the report).

#include <string>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/distributed/decomposed_rank.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::pipeline {

/// What the distributed path reports besides the serial result.
struct DistributedAnalysis {
  distributed::DecomposedRank backend;
  /// What the serial sparse path would also report and this one does not compute (in the
  /// report's words), empty when nothing is missing.
  std::vector<std::string> not_computed;
};

/// A framework analysed by the distributed path.
struct DistributedFrameworkAnalysis : DistributedAnalysis {
  /// As framework::analyse_framework's sparse counts: m, n, rank, mechanisms, self_stresses,
  /// the decision with its evidence (`method` sparse_qr, `vectors` false); on every process.
  framework::FrameworkResult result;
  design::Verdict verdict;  ///< design::framework_verdict of the counts (rank 0 only)
};

/// A coupling network analysed by the distributed path.
struct DistributedNetworkAnalysis : DistributedAnalysis {
  /// As network::analyse_network_sparse without vectors: FN, CN, the class, rank K with its
  /// evidence, in the user frame; `stressed` and `moving` stay empty (not computed). Every process.
  network::SparseNetworkResult result;
  design::Verdict verdict;  ///< design::sparse_network_verdict of the counts (rank 0 only)
};

/// Collective over MPI_COMM_WORLD: the model and options of rank 0 are the ones decided (other
/// processes may call this with the same model, as the tests do, or take part through
/// distributed::decomposed_rank with an empty matrix, as the command does, without reading the
/// model); `options.tolerances.rank` is the user's relative tolerance (unset: the serial sparse
/// rule). The counts are on every process that called this. Throws as decomposed_rank.
DistributedFrameworkAnalysis analyse_framework_distributed(const framework::FrameworkModel& model,
                                                           const framework::AnalysisOptions& options);

/// Collective over MPI_COMM_WORLD, as above; throws network::ModelError as
/// network::build_body_twist_system does, before any collective call (rank 0 then calls
/// distributed::cancel_decomposed_rank so that the other processes return).
DistributedNetworkAnalysis analyse_network_distributed(const network::Model& model, const Tolerances& tolerances);

}  // namespace kinestat::pipeline
