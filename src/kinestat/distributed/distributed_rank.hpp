// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The rank of a large sparse matrix A (m × n) decided on many processes. The symmetric
// Jordan–Wielandt matrix H = [[0, A], [Aᵀ, 0]] has eigenvalues ±σ_i(A) and zeros, so by
// Sylvester's law of inertia H + s·I has one negative eigenvalue per singular value above s:
// MUMPS's LDLᵀ factorisation of H + s·I (through PETSc; s = 100 × the serial rule's absolute
// threshold, see DistributedRank::shift) gives the rank as its count of negative pivots. The
// same count at 100·s shows the gap; SLEPc's Krylov–Schur on s·(H + s·I)⁻¹ − I finds the singular
// values in (t, s], which the serial rule at t keeps (they are added to the rank); inverse
// iteration with the factor gives null vectors of A (mechanisms) and of Aᵀ (self-stresses), and
// SLEPc the smallest kept singular value (docs/scaling.md, "The distributed rank decision").

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::distributed {


/// What the distributed decision computes besides the rank.
struct DistributedRankOptions {
  /// Null vectors wanted: the first `vectors` of A's null space (mechanisms) and of Aᵀ's
  /// (self-stresses); 0: none (counts and evidence only).
  Eigen::Index vectors = 0;
  /// When H's null space has at most this many vectors, all are computed: the largest dropped
  /// singular value is bounded by ‖H Q‖_F (Q an orthonormal basis of them: H then has that many
  /// eigenvalues within the bound), and SLEPc, with them deflated, finds the smallest kept one;
  /// above it, largest_dropped and smallest_kept stay 0 (not computed) and the inertia count
  /// at kCertainMargin × the shift is the evidence.
  Eigen::Index full_basis_limit = 64;
  /// Compute the smallest kept singular value with SLEPc (with the null space deflated when it
  /// is whole; otherwise from the window operator, below).
  bool smallest_kept = true;
  /// Search the window (t, s] for singular values with SLEPc (the window operator
  /// s·(H + s·I)⁻¹ − I, whose positive eigenvalues are σ/(s − σ) for σ < s) and count those
  /// above t in the rank, as the serial rule at t does; false: the rank is the inertia's count at s.
  bool window = true;
  /// Also keep this many generic null vectors of A and of Aᵀ (generic_mechanisms,
  /// generic_self_stresses): the first vectors inverse iteration gives from pseudo-random starts
  /// in that block, before orthogonalisation, so that a combination vanishes only where every
  /// null vector does (the first: the supports of network::record_motion_support and
  /// record_stress_support; d of them: network::sparse_pair_freedoms).
  Eigen::Index generic_vectors = 0;
};

/// Outcome of a distributed rank decision. Counts are the same on every process; vectors and
/// matrices are filled on rank 0 only.
struct DistributedRank {
  /// The decision in the serial form: rank (at t: the inertia's count at s plus window_kept),
  /// threshold, largest (σ_max, from the caller), smallest_kept (σ_r from SLEPc, rounded to the
  /// digits its residual guarantees, 0 when not computed or not verified), largest_dropped (the
  /// bound above as an upper bound at the report floor, 0 when not computed); `sparse` is true,
  /// so its status is close or unproven as for the serial sparse QR.
  linalg::RankDecision decision;
  /// H's eigenvalues below the threshold in magnitude, m + n − 2·rank (rank = the negative
  /// eigenvalues of H + s·I from the inertia of its LDLᵀ factorisation, plus window_kept).
  Eigen::Index null_pivots = 0;
  /// The shift s = kCertainMargin × the threshold t at which the rank is counted (absolute):
  /// an indefinite LDLᵀ does not resolve eigenvalues of H as small as t itself, so the count is
  /// the rank at t unless a singular value lies in (t, s]; those are searched with SLEPc
  /// (window_kept, distributed_rank.cpp).
  double shift = 0.0;
  /// Singular values found in the window (t, s] (included in decision.rank: the rank at t is
  /// the inertia's count at s plus these), each from an eigenpair of H checked on H itself.
  Eigen::Index window_kept = 0;
  /// The window was searched whole: a checked pair at or below t was found after those in it
  /// (the window operator orders them by σ, largest first). False when not searched (the rank at
  /// s is already min(m, n), or DistributedRankOptions::window is false) or when
  /// kDistributedWindowMostPairs pairs were all in the window.
  bool window_searched = false;
  /// Largest ‖H w − λ w‖ / σ_max of the window's pairs, as reported (distributed_report_bound;
  /// 0 when none was kept).
  double window_residual = 0.0;
  /// The same count at kCertainMargin·s: equal to the rank when no singular value lies in
  /// (s, kCertainMargin·s], the evidence the counts give without singular values.
  Eigen::Index rank_above_margin = 0;
  bool smallest_kept_verified = false;  ///< SLEPc's σ_r passed its residual check
  /// ‖H u − σ_r u‖ / (σ_max ‖u‖) of its pair u as reported (distributed_report_bound; 0 when not
  /// verified). decision.smallest_kept is rounded to the power of ten at or above this × σ_max.
  double smallest_kept_residual = 0.0;
  /// The floor of every reported residual and of the bound on the largest dropped value,
  /// relative to σ_max: the largest power of ten at or below kDistributedReportFloor × t / σ_max.
  double report_floor = 0.0;
  bool dropped_bounded = false;         ///< largest_dropped is the bound of the whole null space
  /// Orthonormal bases (rank 0): the first `vectors` null vectors of A (n rows) and of Aᵀ (m rows).
  Eigen::MatrixXd mechanisms, self_stresses;
  /// ‖A q‖ / (σ_max ‖q‖) of each column q of `mechanisms` and ‖Aᵀ q‖ / (σ_max ‖q‖) of each of
  /// `self_stresses` (rank 0; A as passed in), as reported (distributed_report_bound). The
  /// vectors' entries are rounded to kDistributedVectorGrid of their largest, so that a run on
  /// P ≥ 2 processes (whose MUMPS sums in message order) reports the same vectors and residuals
  /// but for entries on a rounding boundary (distributed_rank.cpp).
  std::vector<double> mechanism_residuals, self_stress_residuals;
  /// With DistributedRankOptions::generic_vectors = k (rank 0): k generic null vectors of A
  /// (n × k) and of Aᵀ (m × k), unit norm, entries rounded as the reported vectors'; no columns
  /// when that null space is empty.
  Eigen::MatrixXd generic_mechanisms, generic_self_stresses;
  /// Largest ‖H v‖ / (σ_max ‖v‖) over the null vectors of H computed, as reported
  /// (distributed_report_bound; 0 when none): the rounding level when the decision is sound.
  double null_vector_residual = 0.0;
  Eigen::Index null_vectors_computed = 0;  ///< null vectors of H computed by MUMPS
  /// The null vectors came from a third factorisation, of H + t·I (t the threshold), because a
  /// kept singular value lies in (t, kCertainMargin·s] (rank_above_margin ≠ rank): each step
  /// then shrinks a kept direction by kCertainMargin times more than the factor at s does.
  bool vectors_at_threshold = false;
  int processes = 1;
  /// Wall time, seconds: scattering and assembling H, the MUMPS analysis and factorisation,
  /// the null vectors, SLEPc's smallest kept value.
  double assembly_seconds = 0.0, factor_seconds = 0.0, vector_seconds = 0.0, evidence_seconds = 0.0;
  double window_seconds = 0.0;  ///< wall time of the window's search, seconds
  /// MUMPS's own memory count, megabytes: the largest of any process (INFOG(21)) and the sum
  /// over processes (INFOG(22)), as effectively used during the factorisation.
  long long factor_megabytes_max = 0, factor_megabytes_total = 0;
  /// Peak resident memory of each process, bytes (rank 0 only; index = MPI rank).
  std::vector<std::size_t> peak_memory;
};

/// A residual or bound `relative` to σ_max as the backend reports it, repeatable from run to run
/// at P ≥ 2: rounded up to a power of ten, and at least `floor` (DistributedRank::report_floor;
/// a residual of exactly 0 is reported as the floor too). An upper bound.
double distributed_report_bound(double relative, double floor);

/// Decides the rank of `a` on all processes of PETSC_COMM_WORLD (collective; a PetscSession
/// must be alive). `a` (non-dimensional and scaled as the serial path scales it) and
/// `threshold` (the serial rule's decision: linalg::sparse_rank_threshold) are read on rank 0
/// only, where `a` may be null elsewhere; rank 0 scatters the rows of H. Throws kinestat::Error
/// (exit 3) when PETSc or MUMPS fails, std::bad_alloc when memory runs out, and
/// kinestat::Error when MUMPS fails otherwise.
DistributedRank distributed_rank(const Eigen::SparseMatrix<double>* a, const linalg::RankDecision& threshold,
                                 const DistributedRankOptions& options = {});

}  // namespace kinestat::distributed
