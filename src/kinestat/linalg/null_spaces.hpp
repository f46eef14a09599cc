// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Rank and both null spaces of a dense matrix, for analyses that need the null vectors but not
// the other singular vectors (a framework's modes and self-stress states).
//
// A tall matrix of full column rank (rows > cols: more constraints than coordinates, no
// mechanism), the common case of an overconstrained structure, needs no SVD with vectors: its
// singular values are those of R in A = Q R (LAPACK's Householder QR, dgeqrf), its null space is
// empty, and its left null space is spanned by Q's last rows − cols columns. Completing U of the
// SVD costs several times the QR (the 1,121-bar lattice: 1,121 × 760).

#include <Eigen/Core>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

struct NullSpaces {
  Eigen::VectorXd singular_values;  ///< min(rows, cols) values, decreasing
  RankDecision rank;
  Eigen::MatrixXd null_space;       ///< cols × (cols − rank), orthonormal columns
  Eigen::MatrixXd left_null_space;  ///< rows × (rows − rank), orthonormal columns
  bool used_jacobi = false;         ///< the SVD's divide-and-conquer result failed its check
  bool from_qr = false;             ///< tall and of full column rank: from the Householder QR
};

/// Numerical rank of `a` (decide_rank on its singular values, the same rule as analyse_svd) and
/// orthonormal bases of the null spaces of `a` and of `aᵀ`. A tall `a` whose R factor has full
/// rank by that rule takes the QR route (singular values of R by singular_values, without
/// vectors, the left null space from Q, checked on probe vectors: ‖aᵀ N x‖ and NᵀN − I); every
/// other matrix, and a QR route that fails its check, the checked full SVD (analyse_svd).
/// The bases differ from the SVD's by an orthogonal change of basis within the same space.
NullSpaces analyse_null_spaces(const Eigen::MatrixXd& a, const RankTolerance& tolerance = {});

}  // namespace kinestat::linalg
