// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/distributed_pipeline.hpp"

#include <algorithm>
#include <utility>

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/distributed/mpi_session.hpp"

namespace kinestat::pipeline {

namespace {

// The node of each column of D(c), the serial counts' column groups (framework_analysis.cpp).
std::vector<Eigen::Index> framework_column_nodes(const framework::FrameworkResult& result) {
  std::vector<Eigen::Index> nodes;
  nodes.reserve(result.partition.dependent_coordinates.size());
  for (const Eigen::Index coordinate : result.partition.dependent_coordinates)
    nodes.push_back(static_cast<Eigen::Index>(result.indexing.coordinates[static_cast<std::size_t>(coordinate)].node));
  return nodes;
}

// The serial framework rule's tolerance: the user's, or the default with the rounding of the
// coordinates as written (framework_analysis.cpp's rank_tolerance).
linalg::RankTolerance framework_rank_tolerance(const framework::FrameworkModel& model, double length,
                                               const Tolerances& tolerances) {
  double largest = 0.0;
  for (const framework::Node& node : model.nodes) largest = std::max(largest, node.position.cwiseAbs().maxCoeff());
  return {tolerances.rank, linalg::input_rounding_level(largest, length)};
}

}  // namespace

DistributedFrameworkAnalysis analyse_framework_distributed(const framework::FrameworkModel& model,
                                                           const framework::AnalysisOptions& options) {
  DistributedFrameworkAnalysis out;
  framework::FrameworkResult& result = out.result;
  Eigen::SparseMatrix<double> jacobian = framework::prepare_analysis(model, result);
  out.backend = distributed::decomposed_rank(std::move(jacobian), framework_rank_tolerance(model, result.length, options.tolerances),
                                             framework_column_nodes(result));
  result.method = framework::RankMethod::sparse_qr;  // the compact report of the serial sparse counts
  result.decision = out.backend.decision;
  result.rank = result.decision.rank;
  result.mechanisms = result.n - result.rank;
  result.self_stresses = result.m - result.rank;
  result.factor_memory = out.backend.factor_memory.empty() ? 0 : *std::max_element(out.backend.factor_memory.begin(),
                                                                                    out.backend.factor_memory.end());
  out.not_computed = {"modes and stress states", "release proposal"};
  if (distributed::world_rank() == 0) {
    framework::AnalysisOptions verdict_options = options;
    verdict_options.vectors = false;
    out.verdict = design::framework_verdict(model, result, verdict_options);
  }
  return out;
}

DistributedNetworkAnalysis analyse_network_distributed(const network::Model& model, const Tolerances& tolerances) {
  DistributedNetworkAnalysis out;
  network::SparseNetworkResult& r = out.result;
  r = network::build_body_twist_system(model, tolerances);
  // The serial rule: the threshold of K (its σ_max and the input's rounding), rank K decided by
  // the QR of Kᵀ. K stays in the result (the counts and the verdict read it): a copy is passed.
  out.backend = distributed::decomposed_rank(Eigen::SparseMatrix<double>(r.K), {tolerances.rank, r.rank.input_rounding}, {},
                                             distributed::FactoredSide::transposed);
  r.rank = out.backend.decision;
  r.motion_factor_rank = r.rank;
  const std::vector<bool> unknown(static_cast<std::size_t>(r.e), false);
  network::finish_sparse_network(r, unknown, unknown);
  network::sparse_network_in_user_frame(model.space, r);  // one frame for every path
  out.not_computed = {"motions and self-stresses (basis vectors)", "couplings that carry a self-stress and that move",
                      "pair freedoms"};
  if (distributed::world_rank() != 0) return out;
  out.verdict = design::sparse_network_verdict(model, r, tolerances);
  // The sparse verdict's note says where the redundancy is named; here nothing is.
  out.verdict.note = "the distributed path decides the counts only: no states, no couplings named under 'where', no change "
                     "set; run the serial path (kinestat analyze without --backend) for them";
  return out;
}

}  // namespace kinestat::pipeline
