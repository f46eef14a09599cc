#pragma once
// Numerical rank of a large sparse matrix by SuiteSparseQR (multifrontal, column-pivoting
// heuristic), for models too large for a dense SVD. Counts only: no singular vectors.

#include <Eigen/SparseCore>

#include "kinestat/linalg/rank_decision.hpp"

namespace kinestat::linalg {

/// Rank of `a` from a sparse QR factorisation. The threshold is the same relative rule as the
/// SVD's (`tolerance`, default max(rows, cols)·eps) times an estimate of σ_max from power
/// iteration. The evidence reported is the R diagonal: `smallest_kept` is the smallest kept
/// |R_ii|; `largest_dropped` is 0 because SPQR drops columns without reporting them.
RankDecision sparse_numerical_rank(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance = {});

/// Estimate of the largest singular value of `a` (power iteration on aᵀa, 60 steps).
double estimate_largest_singular_value(const Eigen::SparseMatrix<double>& a);

}  // namespace kinestat::linalg
