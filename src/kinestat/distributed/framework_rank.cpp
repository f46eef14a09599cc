#include "kinestat/distributed/framework_rank.hpp"

#include <mpi.h>

#include <algorithm>

#include "kinestat/linalg/sparse_rank.hpp"

namespace kinestat::distributed {

DistributedFrameworkResult analyse_framework_distributed(const framework::FrameworkModel* model,
                                                         const Tolerances& tolerances,
                                                         const DistributedRankOptions& options) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  DistributedFrameworkResult out;
  framework::FrameworkResult& result = out.analysis;
  Eigen::SparseMatrix<double> jacobian;
  linalg::RankDecision threshold;
  if (rank == 0) {
    jacobian = framework::prepare_analysis(*model, result);
    // The tolerance of framework_analysis.cpp's rank_tolerance: the user's, or the default
    // rule with the rounding of the coordinates as written (placement-aware).
    double largest = 0.0;
    for (const framework::Node& node : model->nodes) largest = std::max(largest, node.position.cwiseAbs().maxCoeff());
    const linalg::RankTolerance tolerance{tolerances.rank, linalg::input_rounding_level(largest, result.length)};
    threshold = linalg::sparse_rank_threshold(jacobian, tolerance);
  }
  out.backend = distributed_rank(rank == 0 ? &jacobian : nullptr, threshold, options);
  result.method = framework::RankMethod::sparse_qr;  // the compact (counts-only) report of the sparse path
  result.decision = out.backend.decision;
  result.m = result.decision.rows;
  result.n = result.decision.cols;
  result.rank = result.decision.rank;
  result.mechanisms = result.n - result.rank;
  result.self_stresses = result.m - result.rank;
  result.factor_memory = static_cast<std::size_t>(out.backend.factor_megabytes_total) * 1000000;
  return out;
}

}  // namespace kinestat::distributed
