// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Coupling networks too large for Davies' dense matrices, in body-twist form: the twists of the
// n − 1 bodies other than the ground are the unknowns, and each of the C unit actions a of a
// coupling from body i to body j gives one equation a · (T_j − T_i) = 0 (the action does no
// work on the relative motion). One sparse C × d(n − 1) matrix K; its null space is the
// network's motions, the null space of Kᵀ its self-stresses, so
//   FN = d(n − 1) − rank K,   CN = C − rank K
// (FN − CN = F − d·l, seed 000 eq 7). Ranks from the sparse QR with the same relative rule as
// the dense path, decided in the conditioned analysis frame; the result is converted to the
// user's frame once, in the last stage (docs/network.md, "The sparse path in stages"), so no
// consumer converts.

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "kinestat/linalg/factorisation_memory.hpp"
#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/screw/rounded_coupling_basis.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

/// The conditioned analysis frame of the sparse path (the dense path's AnalysisFrame, in
/// doubles): origin at the centroid of the coupling points, lengths over their extent. K and
/// every rank decision live in it; sizes measured in it do not change with the placement or the
/// length unit of the model, so the verdict and the pictures measure shares in it.
struct SparseAnalysisFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< in the user's frame
  double scale = 1.0;                                ///< characteristic length, user units

  /// A twist (axis formation, the d coordinates of `space`) of this frame in the user's frame:
  /// (ω; v') -> (ω; s v' + o × ω), the same power against every action (m; f) as
  /// ((m − o × f) / s; f) has against (ω; v').
  Eigen::VectorXd twist_to_user(const Eigen::Ref<const Eigen::VectorXd>& twist, const screw::ScrewSpace& space) const;
  /// A twist of the user's frame in this frame, (ω; (v − o × ω) / s): for placement- and unit-free
  /// sizes of the result's twists.
  Eigen::VectorXd twist_to_frame(const Eigen::Ref<const Eigen::VectorXd>& twist, const screw::ScrewSpace& space) const;
};

/// The sparse path's result. Everything a consumer reads is in the user's frame and length unit
/// (the row actions, the basis vectors); only K, the generic vectors of the pair ranks and the
/// rank evidence are of the conditioned system, on which the decisions are made (as the dense
/// path's rank evidence is).
struct SparseNetworkResult {
  int d = 6;
  int bodies = 0, e = 0, l = 0;
  int F = 0, C = 0, FN = 0, CN = 0;
  int ground = 0;
  NetworkClass classification = NetworkClass::simply_stiff;
  /// Of K (C × d(n − 1)), decided by the QR of Kᵀ. When the QR of K gives the same rank and
  /// its live block is better conditioned (larger factor_smallest), the evidence (smallest kept
  /// |R_ii| and σ_min(R11)) is that factor's: either factor's kept columns span the range.
  linalg::RankDecision rank;
  /// Couplings that carry some self-stress (redundant couplings: each lies on a self-stress
  /// and could be relaxed) and couplings that move in some motion of the network, by index.
  std::vector<int> stressed, moving;
  /// Largest ‖K x‖ / (σ_max ‖x‖) of the two combined null vectors used for the supports.
  double residual = 0.0;
  /// Entries of the generic motion (self-stress) at or below this fraction of its largest do not
  /// count for the supports: support_zero of the factor that gave the vector.
  double motion_support_zero = kSupportZero, stress_support_zero = kSupportZero;
  /// Bodies (indices, the ground never) that move in some motion of the network.
  std::vector<int> moving_bodies;
  /// Coupling of each row of K (each unit action, in the order of the coupling's action basis).
  std::vector<int> row_coupling;
  /// The unit action of each row of K in the user's frame and length unit (ray formation, the
  /// model's d coordinates), from screw::rounded_coupling_basis: each coupling's basis is built
  /// once, in doubles, and kept for the verdict.
  std::vector<screw::RoundedUnitScrew> row_actions;
  /// K itself (C × d(n − 1), conditioned analysis frame `frame`): column block
  /// d·(b − [b > ground]) is body b's twist, so that block's nonzero rows are the unit actions of
  /// b's own couplings.
  Eigen::SparseMatrix<double> K;

  /// Null-space bases on request (`vectors` > 0), from the rank-revealing QR factors: for dead
  /// column k, x = [−R11⁻¹ R12 e_k; e_k], per unit of the entry of the dead column (its
  /// "primary", in the conditioned frame), as the dense path's body motions are per unit of
  /// their primary. (The distributed backend's primary is the largest entry; its motions are
  /// scaled by the primary's size, so that entry is ±1 and the direction stays the backend's.)
  /// Body twists in axis formation (ω; v), v the velocity of the point at the user's origin, in
  /// the user's frame and length unit (block of body b as in K), from the QR of K: d(n − 1) × k.
  Eigen::MatrixXd motion_basis;
  /// Action magnitudes, one per row of K (times row_actions: the wrench in the user's frame;
  /// magnitudes do not depend on the frame), from the QR of Kᵀ: C × k.
  Eigen::MatrixXd stress_basis;
  std::vector<Eigen::Index> motion_primaries;  ///< the dead column of K of each motion_basis vector
  std::vector<Eigen::Index> stress_primaries;  ///< the dead row of K of each stress_basis vector
  /// Rank of the QR of K (the motion vectors' factor; rank K above is from the QR of Kᵀ): the
  /// two factorisations decide independently, both are reported.
  linalg::RankDecision motion_factor_rank;
  /// Largest ‖K x‖ / (σ_max ‖x‖) (motions) or ‖Kᵀ y‖ / (σ_max ‖y‖) (stresses) of the basis
  /// vectors, in the conditioned frame.
  double basis_residual = 0.0;
  /// On request (`pair_vectors`), d generic motions and d generic self-stresses for the pair
  /// freedoms (network::sparse_pair_freedoms): fixed pseudo-random vectors projected onto the
  /// null space of K (body twists, conditioned frame) and of Kᵀ (action magnitudes, one per row
  /// of K), one least-squares solve each with the factors already computed; zero when FN
  /// (CN) is zero.
  Eigen::MatrixXd generic_motions;   ///< d(n − 1) × d
  Eigen::MatrixXd generic_stresses;  ///< C × d
  SparseAnalysisFrame frame;  ///< the conditioned analysis frame of K and of the rank decisions
};

/// Couplings above which the `analyze` command takes the sparse path.
inline constexpr int kDenseNetworkLimit = 300;

/// The first stage of analyse_network_sparse, without factoring: K (C × d(n − 1), conditioned
/// analysis frame, in `K`), the coupling and unit action (user frame) of each row, d, n, e, l,
/// F, C, the ground, the frame, and the rank rule's threshold and σ_max in `rank` (rank itself 0; the
/// threshold rises with the rounding of the coordinates as written). Throws ModelError (no
/// couplings, bodies not connected, a coupling's geometry).
SparseNetworkResult build_body_twist_system(const Model& model, const Tolerances& tolerances = {});

/// The fraction of its largest entry below which an entry of a vector solved with a sparse
/// factor is not told from zero: kSupportZero, or the factor's attainable relative accuracy
/// ε·σ_max / σ_min(R11) when that is larger (at most 1; `factor` with factor_estimated, else
/// kSupportZero). A least-squares residual or null vector computed through R11 carries errors of
/// about that size relative to its largest entry, and so does the null space itself under
/// rounding of K when σ_min(R11) is the gap: smaller entries may come from another ordering of
/// the same matrix, so they decide nothing.
double support_zero(const linalg::RankDecision& factor);

/// Marks the couplings (`moving`, one flag per coupling) and bodies (`r.moving_bodies`) that move
/// in the motion `twists` (body twists, the columns of `k` = K), and raises `r.residual` to
/// ‖K x‖ / (σ_max ‖x‖): entries above `relative_zero` of the largest count. `twists` should be a
/// generic null vector of K (a generic combination vanishes only where every null vector does).
void record_motion_support(const Model& model, const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& twists,
                           SparseNetworkResult& r, std::vector<bool>& moving, double relative_zero = kSupportZero);
/// Marks the couplings (`stressed`, one flag per coupling) with an entry of the self-stress
/// `actions` (one magnitude per row of K, a generic null vector of `kt` = Kᵀ) above
/// `relative_zero` of the largest, and raises `r.residual` to ‖Kᵀ λ‖ / (σ_max ‖λ‖).
void record_stress_support(const Eigen::SparseMatrix<double>& kt, const Eigen::VectorXd& actions, SparseNetworkResult& r,
                           std::vector<bool>& stressed, double relative_zero = kSupportZero);
/// FN = d(n − 1) − rank K and CN = C − rank K (from `r.K`'s size and `r.rank.rank`), the class,
/// and the lists `stressed` and `moving` from the flags.
void finish_sparse_network(SparseNetworkResult& r, const std::vector<bool>& stressed, const std::vector<bool>& moving);

/// Scales each basis vector per unit of its primary (motions: of its size) and converts the motion basis to the user's
/// frame (`r.frame`; axis formation, velocity of the point at the user's origin): the last stage
/// of every path that fills a SparseNetworkResult (this one, the distributed backend), so the
/// result has one frame whoever computed it.
void sparse_network_in_user_frame(const screw::ScrewSpace& space, SparseNetworkResult& r);

/// FN, CN and the couplings that carry self-stress and that move, from two sparse QR
/// factorisations (K and Kᵀ). A coupling belongs to a support when its entries in a fixed
/// pseudo-random combination of the null vectors exceed support_zero of the factor (kSupportZero
/// unless the factor's live block is ill-conditioned) of the largest: a generic combination
/// vanishes only where every null vector does. Both factors' σ_min(R11) are estimated
/// (`rank.factor_smallest`, `motion_factor_rank.factor_smallest`). Throws ModelError.
/// Stages (docs/network.md, "The sparse path in stages"): system (build_body_twist_system) ->
/// factor Kᵀ (rank, motions' support) -> factor K (self-stresses' support) -> merge -> convert
/// (sparse_network_in_user_frame). The two factorisations run one after the other on the
/// calling thread (the library starts no thread and sets no process state).
/// With `vectors` > 0 also the first `vectors` basis vectors of the motions and of the
/// self-stresses (motion_basis, stress_basis), at the cost of one triangular solve each. With
/// `pair_vectors` also generic_motions and generic_stresses (2d least-squares solves).
/// `memory_limit`: of each factorisation (linalg::FactorisationTooLarge beyond it).
SparseNetworkResult analyse_network_sparse(const Model& model, const Tolerances& tolerances = {},
                                           Eigen::Index vectors = 0, bool pair_vectors = false,
                                           linalg::MemoryLimit memory_limit = {});

}  // namespace kinestat::network
