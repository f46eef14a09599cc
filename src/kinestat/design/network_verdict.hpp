// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Design help for coupling networks (seed 000): the verdict of an analysed network. Intended
// motions are the declared `inputs:` when the model has them, otherwise FN less the idle motions
// (a body that can move while every other body stands still: an S-S link turning about its own
// axis, a body hanging on one coupling). Each self-stress is described by the action every
// coupling transmits in it. Minimal sets of coupling changes are searched for — other coupling
// types first (revolute -> spherical or universal, prismatic -> cylindrical, ...), then removals
// and welds — and each is verified by re-analysing the changed copy of the model: CN = 0, no
// extra motion, no body free on its own, and the bodies that carry the intended motion keep the
// same pair freedoms fij with the ground and the same motion screws. Sets that fail are not
// proposed; the verdict lists them.

#include "kinestat/design/verdict.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

/// Networks with more couplings than this get the verdict's counts and participants but no
/// searched change set (each candidate costs one re-analysis).
inline constexpr int kNetworkDesignSearchCouplings = 60;
/// Largest number of changed copies the change search may screen.
inline constexpr int kNetworkDesignSearchAnalyses = 800;
/// Largest elimination work the change search may spend, as the sum over screened copies of
/// rows x columns x min(rows, columns) of their M^N: a deterministic bound on its time (the
/// Delta robot's search, 30 x 21 per copy, spends about 1.5 10^7; a 60-coupling network with 30
/// circuits stops after a few dozen copies).
inline constexpr double kNetworkDesignSearchWork = 5e7;
/// When no single change helps, pairs of changes are tried among this many couplings (those
/// taking the largest part).
inline constexpr std::size_t kNetworkDesignPairCouplings = 4;

/// Idle motions of one body: motions it has while every other body stands still (an S-S link's
/// spin about its own axis, or a body that hangs on one coupling and swings freely).
struct IdleMotion {
  int body = 0;
  int count = 0;                              ///< dimension of the body's idle motions
  std::vector<std::vector<double>> screws;    ///< a basis, d coordinates each (axis formation)
  int holding_coupling = -1;                  ///< the body's only coupling, when it has one; -1 otherwise
};

/// The idle motions of every body other than the ground: the motions common to all its
/// couplings' motion systems (the null space of their stacked actions), exactly when `exact`,
/// otherwise with `tolerances`. A body held by one coupling is free on its own with all that
/// coupling's freedoms, unless the coupling is named in `inputs:` (then its motion is driven) or
/// the network has no circuit (an open chain or tree: every joint motion is taken as intended).
std::vector<IdleMotion> idle_motions(const network::Model& model, bool exact, const Tolerances& tolerances);

/// "idle spin of body 'b': <motion>" or "body 'rod' hangs on coupling L alone and moves freely:
/// <motion>", `motion` being the words of one of the idle motion's screws.
std::string idle_description(const network::Model& model, const IdleMotion& idle, const std::string& motion);

/// The verdict for `model` analysed as `result` with `options` (used again for every
/// re-analysis of a changed copy).
Verdict network_verdict(const network::Model& model, const network::NetworkResult& result,
                        const network::AnalysisOptions& options = {});

}  // namespace kinestat::design
