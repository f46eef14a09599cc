// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The verdict of a coupling network analysed on the sparse body-twist path (networks of
// thousands of couplings): the same counts as network_verdict — intended motions are the
// declared `inputs:` or FN less the idle spins — and where the extra motions and the
// self-stresses sit, from basis vectors of the rank-revealing sparse QR factors (which bodies
// move, which couplings carry each self-stress and the wrench each transmits). No change set
// is searched at this size: each candidate change would cost a re-analysis of the whole network.

#include <Eigen/Core>

#include <vector>

#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/verdict.hpp"
#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

/// Basis vectors of each null space (motions, self-stresses) the sparse verdict lists as
/// states: pass it as `vectors` to network::analyse_network_sparse. Parts that take part only
/// in later basis vectors are still named under `where`, with participation 0.
inline constexpr Eigen::Index kSparseVerdictStates = 8;

/// The verdict for `model` analysed as `result` by network::analyse_network_sparse (with
/// `vectors` = kSparseVerdictStates for the states; with none the states hold the idle spins
/// only and `where` comes from the supports). Idle spins are found body by body with
/// `tolerances`, as on the dense path. `changes` stays empty; `note` says why and how to get one.
Verdict sparse_network_verdict(const network::Model& model, const network::SparseNetworkResult& result,
                               const Tolerances& tolerances = {});
/// The same with the idle spins already found (sparse_idle_spins of the same model and system,
/// with the tolerances of the analysis).
Verdict sparse_network_verdict(const network::Model& model, const network::SparseNetworkResult& result,
                               const std::vector<IdleMotion>& idle_spins);

/// The idle spins of the sparse verdict, body by body (axis formation, the user's frame and
/// length unit): each body whose own actions in K may leave a twist free is analysed alone with
/// its couplings, exactly as on the dense path with `tolerances`. Needs only what
/// network::build_body_twist_system sets (K, d, the ground, the frame, the rank rule's input
/// rounding): the system or the full analysis may be passed.
std::vector<IdleMotion> sparse_idle_spins(const network::Model& model, const network::SparseNetworkResult& system,
                                          const Tolerances& tolerances = {});

}  // namespace kinestat::design
