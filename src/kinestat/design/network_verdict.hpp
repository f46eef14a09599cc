#pragma once
// Design help for coupling networks (seed 000): the verdict of an analysed network. Intended
// motions are the declared `inputs:` when the model has them, otherwise FN less the idle spins
// (a body that can move while every other body stands still, such as an S-S link turning about
// its own axis). Each self-stress is described by the action every coupling transmits in it;
// one minimal set of coupling changes (a freedom added along a locked action, a constraint
// added against an idle spin, or a coupling named redundant) is searched for and verified by
// re-analysing the changed copy of the model.

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

/// Idle spins of one body: motions it has while every other body stands still.
struct IdleMotion {
  int body = 0;
  int count = 0;                              ///< dimension of the body's idle motions
  std::vector<std::vector<double>> screws;    ///< a basis, d coordinates each (axis formation)
};

/// The idle motions of every body other than the ground that has at least two couplings:
/// the motions common to all its couplings' motion systems (the null space of their stacked
/// actions), exactly when `exact`, otherwise with `tolerances`.
std::vector<IdleMotion> idle_motions(const network::Model& model, bool exact, const Tolerances& tolerances);

/// The verdict for `model` analysed as `result` with `options` (used again for every
/// re-analysis of a changed copy).
Verdict network_verdict(const network::Model& model, const network::NetworkResult& result,
                        const network::AnalysisOptions& options = {});

}  // namespace kinestat::design
