// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A coupling network's counts decided by the distributed backend: K (C × d(n − 1), body-twist
// form, conditioned analysis frame) and its threshold built on rank 0 exactly as the serial
// sparse path builds them (network::build_body_twist_system), rank K from distributed_rank,
// FN = d(n − 1) − rank K and CN = C − rank K, and the couplings that carry a self-stress and
// that move from one generic null vector of K and of Kᵀ (the serial path's supports,
// network::record_motion_support and record_stress_support).

#include "kinestat/distributed/distributed_rank.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/sparse_network.hpp"

namespace kinestat::distributed {

/// The network's analysis in the serial sparse form and what the backend reports.
struct DistributedNetworkResult {
  /// Complete on rank 0: counts, class, rank decision, supports, K; with
  /// DistributedRankOptions::vectors = k > 0 also motion_basis and stress_basis (the first k
  /// orthonormal null vectors of K and Kᵀ from the backend; primaries: each vector's largest
  /// entry) and basis_residual (the largest of the backend's per-vector residuals).
  network::SparseNetworkResult analysis;
  DistributedRank backend;
};

/// Collective over PETSC_COMM_WORLD. On rank 0, `model` is the network and `system` what
/// network::build_body_twist_system returned for it (built by the caller, so that a bad model
/// is refused before any collective call; moved from); both may be null elsewhere. `options`
/// vectors: how many basis vectors of each null space to return (0: counts and supports only).
/// With `pair_vectors`, also analysis.generic_motions and generic_stresses (d generic null
/// vectors of K and of Kᵀ from the backend, unit norm; zero when that space is empty), for
/// network::sparse_pair_freedoms, as analyse_network_sparse gives them with its `pair_vectors`.
DistributedNetworkResult analyse_network_distributed(const network::Model* model, network::SparseNetworkResult* system,
                                                     const Tolerances& tolerances, DistributedRankOptions options = {},
                                                     bool pair_vectors = false);

}  // namespace kinestat::distributed
