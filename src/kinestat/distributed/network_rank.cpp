// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/network_rank.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace kinestat::distributed {

namespace {

// The index of the largest-magnitude entry of each column (the first on a tie): the entry the
// sparse verdict scales to 1, as the serial path's dead column.
std::vector<Eigen::Index> network_largest_entries(const Eigen::MatrixXd& basis) {
  std::vector<Eigen::Index> primaries;
  for (Eigen::Index j = 0; j < basis.cols(); ++j) {
    Eigen::Index at = 0;
    basis.col(j).cwiseAbs().maxCoeff(&at);
    primaries.push_back(at);
  }
  return primaries;
}

}  // namespace

DistributedNetworkResult analyse_network_distributed(const network::Model* model, network::SparseNetworkResult* system,
                                                     const Tolerances& tolerances, DistributedRankOptions options,
                                                     bool pair_vectors) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  DistributedNetworkResult out;
  network::SparseNetworkResult& r = out.analysis;
  if (rank == 0) r = std::move(*system);
  // One generic vector of each space for the supports; d for the pair freedoms, as the serial
  // path (the first of them is the same vector).
  int d = rank == 0 ? r.d : 0;
  MPI_Bcast(&d, 1, MPI_INT, 0, MPI_COMM_WORLD);
  options.generic_vectors = pair_vectors ? d : 1;
  out.backend = distributed_rank(rank == 0 ? &r.K : nullptr, r.rank, options);
  if (rank != 0) return out;
  const Eigen::SparseMatrix<double>& k = r.K;
  if (k.rows() == 0 || k.cols() == 0) {
    // Nothing was factored (no actions, or only the ground): the serial path's answer, which
    // factors nothing either.
    r = network::analyse_network_sparse(*model, tolerances, options.vectors, pair_vectors);
    return out;
  }
  r.rank = out.backend.decision;  // the threshold, σ_max and rounding levels are the serial rule's
  r.motion_factor_rank = r.rank;
  std::vector<bool> stressed(static_cast<std::size_t>(r.e), false), moving(static_cast<std::size_t>(r.e), false);
  const Eigen::MatrixXd& motions = out.backend.generic_mechanisms;
  const Eigen::MatrixXd& stresses = out.backend.generic_self_stresses;
  bool supported = false;  // a support was recorded, so r.residual was computed
  if (k.cols() > r.rank.rank && motions.cols() > 0) {
    network::record_motion_support(*model, k, motions.col(0), r, moving);
    supported = true;
  }
  if (k.rows() > r.rank.rank && stresses.cols() > 0) {
    const Eigen::SparseMatrix<double> kt = k.transpose();
    network::record_stress_support(kt, stresses.col(0), r, stressed);
    supported = true;
  }
  if (pair_vectors) {
    // As the serial path's: zero when that null space is empty.
    r.generic_motions = Eigen::MatrixXd::Zero(k.cols(), d);
    r.generic_stresses = Eigen::MatrixXd::Zero(k.rows(), d);
    if (k.cols() > r.rank.rank) r.generic_motions.leftCols(motions.cols()) = motions;
    if (k.rows() > r.rank.rank) r.generic_stresses.leftCols(stresses.cols()) = stresses;
  }
  r.motion_basis = out.backend.mechanisms;
  r.stress_basis = out.backend.self_stresses;
  r.motion_primaries = network_largest_entries(r.motion_basis);
  r.stress_primaries = network_largest_entries(r.stress_basis);
  for (double residual : out.backend.mechanism_residuals) r.basis_residual = std::max(r.basis_residual, residual);
  for (double residual : out.backend.self_stress_residuals) r.basis_residual = std::max(r.basis_residual, residual);
  // Reported as the backend's own residuals (repeatable on P ≥ 2 processes).
  if (supported) r.residual = distributed_report_bound(r.residual, out.backend.report_floor);
  network::finish_sparse_network(r, stressed, moving);
  network::sparse_network_in_user_frame(model->space, r);  // one frame for every path
  return out;
}

}  // namespace kinestat::distributed
