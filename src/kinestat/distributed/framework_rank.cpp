// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/framework_rank.hpp"

#include <mpi.h>

#include <algorithm>

#include "kinestat/linalg/sign_convention.hpp"
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
  result.method = framework::RankMethod::sparse_qr;  // the compact report of the sparse path
  result.decision = out.backend.decision;
  result.m = result.decision.rows;
  result.n = result.decision.cols;
  result.rank = result.decision.rank;
  result.mechanisms = result.n - result.rank;
  result.self_stresses = result.m - result.rank;
  result.factor_memory = static_cast<std::size_t>(out.backend.factor_megabytes_total) * 1000000;
  if (rank == 0 && options.vectors > 0) {
    // The first k modes and stress states as the serial sparse path reports them: in D̂'s units
    // (the length scaling undone), unit norm, the one sign convention; the residual is that of
    // the orthonormal null vector of the scaled D(c).
    Eigen::MatrixXd modes = result.column_scale.asDiagonal() * out.backend.mechanisms;
    for (Eigen::Index j = 0; j < modes.cols(); ++j) linalg::orient_unit_vector(modes.col(j), kModeZero);
    framework::collect_modes(result, modes);
    Eigen::MatrixXd stresses = result.row_scale.asDiagonal() * out.backend.self_stresses;
    for (Eigen::Index j = 0; j < stresses.cols(); ++j) linalg::orient_unit_vector(stresses.col(j), kModeZero);
    framework::collect_stresses(result, stresses);
    result.vectors = true;
    result.vector_limit = options.vectors;
    for (double r : out.backend.mechanism_residuals) result.null_space_residual = std::max(result.null_space_residual, r);
    for (double r : out.backend.self_stress_residuals) result.null_space_residual = std::max(result.null_space_residual, r);
  }
  return out;
}

}  // namespace kinestat::distributed
