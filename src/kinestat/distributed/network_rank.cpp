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
                                                     const Tolerances& tolerances, DistributedRankOptions options) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  DistributedNetworkResult out;
  network::SparseNetworkResult& r = out.analysis;
  if (rank == 0) r = std::move(*system);
  options.generic_vectors = true;
  out.backend = distributed_rank(rank == 0 ? &r.K : nullptr, r.rank, options);
  if (rank != 0) return out;
  const Eigen::SparseMatrix<double>& k = r.K;
  if (k.rows() == 0 || k.cols() == 0) {
    // Nothing was factored (no actions, or only the ground): the serial path's answer, which
    // factors nothing either.
    r = network::analyse_network_sparse(*model, tolerances, options.vectors);
    return out;
  }
  r.rank = out.backend.decision;  // the threshold, σ_max and rounding levels are the serial rule's
  r.motion_factor_rank = r.rank;
  std::vector<bool> stressed(static_cast<std::size_t>(r.e), false), moving(static_cast<std::size_t>(r.e), false);
  if (k.cols() > r.rank.rank && out.backend.generic_mechanism.size() > 0)
    network::record_motion_support(*model, k, out.backend.generic_mechanism, r, moving);
  if (k.rows() > r.rank.rank && out.backend.generic_self_stress.size() > 0) {
    const Eigen::SparseMatrix<double> kt = k.transpose();
    network::record_stress_support(kt, out.backend.generic_self_stress, r, stressed);
  }
  r.motion_basis = out.backend.mechanisms;
  r.stress_basis = out.backend.self_stresses;
  r.motion_primaries = network_largest_entries(r.motion_basis);
  r.stress_primaries = network_largest_entries(r.stress_basis);
  for (double residual : out.backend.mechanism_residuals) r.basis_residual = std::max(r.basis_residual, residual);
  for (double residual : out.backend.self_stress_residuals) r.basis_residual = std::max(r.basis_residual, residual);
  // Rounded up to a power of ten, as the backend's own residuals (repeatable on P ≥ 2 processes).
  if (r.residual > 0.0) r.residual = std::pow(10.0, std::ceil(std::log10(r.residual)));
  network::finish_sparse_network(r, stressed, moving);
  return out;
}

}  // namespace kinestat::distributed
