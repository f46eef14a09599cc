// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A framework's counts decided by the distributed backend: D(c) built and scaled on rank 0
// exactly as the serial path builds it (framework::prepare_analysis), the threshold of the
// serial sparse rule, the rank from distributed_rank.

#include "kinestat/distributed/distributed_rank.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"

namespace kinestat::distributed {

/// The framework's analysis (as the serial sparse path: rank, mechanisms, self-stresses and the
/// decision with its evidence; with DistributedRankOptions::vectors = k > 0 also the first k
/// modes and stress states, `vectors` set, but no release proposal) and what the backend reports.
struct DistributedFrameworkResult {
  framework::FrameworkResult analysis;  ///< complete on rank 0; rank and counts on every process
  DistributedRank backend;
};

/// Collective over PETSC_COMM_WORLD. `model` is read on rank 0 only (may be null elsewhere);
/// `tolerances.rank` is the user's relative tolerance (unset: the serial sparse rule,
/// kSparseToleranceFactor · (m + n) · ε raised to the input's rounding, times σ_max).
DistributedFrameworkResult analyse_framework_distributed(const framework::FrameworkModel* model,
                                                         const Tolerances& tolerances,
                                                         const DistributedRankOptions& options = {});

}  // namespace kinestat::distributed
