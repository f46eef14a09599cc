// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Numerical rank of a large sparse matrix by SuiteSparseQR (multifrontal, nested-dissection
// ordering, Heath's column-norm rank rule), for models too large for a dense SVD.

#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/linalg/sparse_qr.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

/// Rank of `a` from a sparse QR factorisation. The threshold is `tolerance` (default
/// kSparseToleranceFactor·(rows + cols)·eps) times an estimate of σ_max (Lanczos). The evidence reported is the R diagonal: `smallest_kept` is the smallest kept
/// |R_ii|; `largest_dropped` is 0 because SPQR drops columns without reporting them.
/// `peak_memory`, when given, receives the factorisation's peak memory in bytes.
/// `column_groups`, when not empty, names a group ≥ 0 for every column of `a` (for a framework's
/// D(c), the node of each coordinate): a matrix at least as tall as wide is then factored in the
/// grouped_nested_dissection_order of those groups instead of METIS on the columns of AᵀA,
/// provided the group graph keeps at least 0.4 of the column couplings (see that function; the
/// same rank wherever the gap at the threshold is clear, a cheaper ordering of a graph with a
/// fraction of the vertices). Otherwise, and for a wider matrix (factored as Aᵀ), METIS.
/// `memory_limit`: as SparseQr's (FactorisationTooLarge beyond it).
RankDecision sparse_numerical_rank(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance = {},
                                   std::size_t* peak_memory = nullptr, const std::vector<Eigen::Index>& column_groups = {},
                                   MemoryLimit memory_limit = {});


/// The absolute threshold of the rank rule for `a`, with σ_max estimated: `decision.largest`,
/// `decision.threshold` and `decision.rounding_level` are set (and `sparse`: its status is close
/// or unproven, never certain), the rank is left to the caller.
RankDecision sparse_rank_threshold(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance);

/// Fills the rank and its evidence (smallest kept |R_ii|) of `decision` from `qr`.
void record_rank(RankDecision& decision, const SparseQr& qr);
/// The same from a factorisation that kept only its counts (sparse_qr_rank).
void record_rank(RankDecision& decision, const SparseRankCount& count);
/// Adds σ_min(R11) of `qr` (SparseQr::smallest_singular_estimate, 0 when the rank is 0) to
/// `decision` as `factor_smallest`: a few more triangular solves, for decisions whose factor is
/// also used to solve (null vectors, least-squares residuals), whose accuracy it bounds.
void record_factor_smallest(RankDecision& decision, const SparseQr& qr);

/// Estimate of the largest singular value of `a`, from below: Lanczos on aᵀa (at most 60
/// steps, each one product with a and one with aᵀ; stops when the estimate settles to ~10⁻¹⁰).
double estimate_largest_singular_value(const Eigen::SparseMatrix<double>& a);

}  // namespace kinestat::linalg
