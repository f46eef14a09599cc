#pragma once
// Coupling networks too large for Davies' dense matrices, in body-twist form: the twists of the
// n − 1 bodies other than the ground are the unknowns, and each of the C unit actions a of a
// coupling from body i to body j gives one equation a · (T_j − T_i) = 0 (the action does no
// work on the relative motion). One sparse C × d(n − 1) matrix K; its null space is the
// network's motions, the null space of Kᵀ its self-stresses, so
//   FN = d(n − 1) − rank K,   CN = C − rank K
// (FN − CN = F − d·l, seed 000 eq 7). Ranks from the sparse QR with the same relative rule as
// the dense path, in the conditioned analysis frame.

#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"

namespace kinestat::network {

struct SparseNetworkResult {
  int d = 6;
  int bodies = 0, e = 0, l = 0;
  int F = 0, C = 0, FN = 0, CN = 0;
  int ground = 0;
  NetworkClass classification = NetworkClass::simply_stiff;
  linalg::RankDecision rank;  ///< of K (C × d(n − 1))
  /// Couplings that carry some self-stress (redundant couplings: each lies on a self-stress
  /// and could be relaxed) and couplings that move in some motion of the network, by index.
  std::vector<int> stressed, moving;
  /// Largest ‖K x‖ / (σ_max ‖x‖) of the two combined null vectors used for the supports.
  double residual = 0.0;
};

/// Couplings above which the `analyze` command takes the sparse path.
inline constexpr int kDenseNetworkLimit = 300;

/// FN, CN and the couplings that carry self-stress and that move, from two sparse QR
/// factorisations (K and Kᵀ). A coupling belongs to a support when its entries in a fixed
/// pseudo-random combination of the null vectors exceed kSupportZero of the largest: a
/// generic combination vanishes only where every null vector does. Throws ModelError.
SparseNetworkResult analyse_network_sparse(const Model& model, const linalg::RankTolerance& tolerance = {});

/// Relative size below which a component of a combined null vector counts as zero.
inline constexpr double kSupportZero = 1e-9;

}  // namespace kinestat::network
