// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The generic answer of a coupling network: FN and CN for the same bodies, couplings and
// coupling types at a random realisation of their geometry (random points, axes, normals and
// pitches), beside the answer at the given geometry. What the given geometry adds on top of the
// generic answer — Bennett's mobility, the planar four-bar's out-of-plane self-stresses when it
// is analysed in space — exists only because of special geometry (parallel or intersecting
// axes, particular proportions) and disappears with any change of it; what the generic answer
// already has comes from the topology and the coupling types and stays.

#include <optional>
#include <string>
#include <vector>

#include "kinestat/linalg/cause_split.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"

namespace kinestat::network {

using linalg::Cause;
using linalg::cause_name;

struct GenericNetwork {
  int FN = 0, CN = 0;   ///< at a random realisation
  int m = 0;            ///< rank of the network unit motion matrix there (FN = F − m, CN = d·l − m)
  int realisations = 0; ///< random realisations ranked (the largest rank is kept)
  int primes = 0;       ///< primes each was ranked modulo (linalg::kModularPrimes)
  /// One per primary motion (primary action) of the given result, in its order: the
  /// `generic FN` primaries whose motions are closest to the motions that persist under a small
  /// random change of the geometry are `topology`, the others `geometry` (see docs/network.md).
  std::vector<Cause> motion_causes, action_causes;
  /// Largest relative distance of a `topology` primary from the persisting subspace (0 when the
  /// causes follow from the counts alone): near 0 when the split is clean, larger when the
  /// primaries mix persisting and special states.
  double split_residual = 0.0;
  /// Couplings whose geometry alone, replaced by a random one, removes a special motion or
  /// self-stress (exact analyses only; empty when the given answer is generic).
  std::optional<std::vector<int>> special_couplings;
};

/// Relative size of the change of geometry (in the analysis frame, lengths over the model's
/// extent) whose motions and self-stresses decide the causes of a mixed basis.
inline constexpr double kCausePerturbation = 1e-6;
/// Each coupling's part in the special geometry takes one modular elimination of M^N per
/// coupling; it is found only when e · rows · columns · min(rows, columns) stays below this
/// (about a second).
inline constexpr double kSpecialCouplingWork = 2e9;

/// The generic answer for `model` beside `given`, its analysis. Returns nothing for screw
/// spaces other than spatial and planar (a random realisation there is not defined).
std::optional<GenericNetwork> generic_network(const Model& model, const NetworkResult& given);

}  // namespace kinestat::network
