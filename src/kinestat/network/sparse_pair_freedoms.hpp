// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Pair freedoms of a network analysed on the sparse body-twist path (seed 000, section 2.7):
// fij, the nett degree of freedom of body j relative to body i, and cij, the nett degree of
// constraint of a direct coupling, for chosen pairs, at a cost per pair rather than per
// network. From d generic motions and d generic self-stresses of the analysis
// (SparseNetworkResult::generic_motions, generic_stresses): fij is the rank of the relative
// twists T_j − T_i over the generic motions, cij the rank of the coupling's action magnitudes
// over the generic self-stresses (its unit actions are independent, so that is the rank of the
// wrenches it transmits). A generic combination of the null vectors keeps every rank of at most d.

#include <optional>
#include <utility>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

/// One row of the pair table: a pair of bodies and one direct coupling between them (or none).
struct SparsePairFreedom {
  int body_i = 0, body_j = 0;   ///< i < j; motions are those of j relative to i
  std::optional<int> coupling;  ///< the direct coupling this row describes, if any
  int f = 0, c = 0;             ///< gross dof / doc of the direct coupling (f = d, c = 0 if absent)
  int fij = 0, cij = 0;         ///< nett dof of the pair, nett doc of the direct coupling
  linalg::RankDecision motion_rank, action_rank;
};

/// The rows for `pairs` (body indices, in either order; a pair of the same body is refused), in
/// the order given, then, with `coupled` set, one row for every coupling (its pair) not already
/// listed, in coupling order. Needs `result` from analyse_network_sparse with `pair_vectors`
/// set. Ranks relative to the size of the whole generic matrix (tolerances.pair_rank), as the
/// dense path relates pair ranks to the whole network's forms, or at the factor's attainable
/// accuracy (`result.motion_support_zero`, `result.stress_support_zero`) of the largest entry
/// when that is higher: the level at which the supports are decided, below which entries of the
/// generic vectors are rounding, not freedom. Throws ModelError.
std::vector<SparsePairFreedom> sparse_pair_freedoms(const Model& model, const SparseNetworkResult& result,
                                                    const std::vector<std::pair<int, int>>& pairs, bool coupled,
                                                    const Tolerances& tolerances = {});

}  // namespace kinestat::network
