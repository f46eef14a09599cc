// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Singular value decomposition with a rank decision, for analyses that need the singular
// vectors themselves (kinematic modes from V, self-stress states from U).
//
// The SVD is LAPACK's divide and conquer (dgesdd) from the optimised LAPACK kinestat links
// (OpenBLAS). Divide-and-conquer SVDs can return wrong singular vectors for matrices with many
// equal singular values, which the 0/±1 matrices of coupling networks and frameworks have
// (seen with Eigen 3.4's BDCSVD: |A - U S V^T| = 0.76 for a 19 x 24 network matrix). Every SVD
// in kinestat is therefore checked: on generic probe vectors the factors must reconstruct A
// and be orthonormal, otherwise the slower but reliable one-sided Jacobi SVD is used. Singular
// values alone come from LAPACK's QR iteration on the bidiagonal form (no divide and conquer),
// checked by their order and Σσ² = ‖A‖²_F.

#include <Eigen/Core>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

struct SvdAnalysis {
  Eigen::MatrixXd u;                 ///< rows x rows, left singular vectors (empty if not asked for)
  Eigen::MatrixXd v;                 ///< cols x cols, right singular vectors
  Eigen::VectorXd singular_values;   ///< min(rows, cols) values, decreasing
  RankDecision rank;
  bool used_jacobi = false;          ///< the divide-and-conquer result failed its check

  /// Columns of V spanning the null space of A (cols x (cols - rank)).
  Eigen::MatrixXd null_space() const { return v.rightCols(v.cols() - rank.rank); }
  /// Columns of U spanning the null space of A^T (rows x (rows - rank)).
  Eigen::MatrixXd left_null_space() const { return u.rightCols(u.cols() - rank.rank); }
};


/// Which singular vectors to return, completed to full orthonormal bases.
enum class SvdVectors { both, right_only };

/// `count` fixed probe vectors of length `rows` (entries sin(1 + 0.7 i + 2.3 j) in [−1, 1]):
/// generic and deterministic, for the checks of factorisations on a few products.
Eigen::MatrixXd probe_vectors(Eigen::Index rows, Eigen::Index count);

/// Checked full SVD of `a` and its numerical rank. Each function here throws NonFiniteMatrix
/// (non_finite_matrix.hpp) when `a` has an infinite or NaN entry.
SvdAnalysis analyse_svd(const Eigen::MatrixXd& a, const RankTolerance& tolerance = {},
                        SvdVectors vectors = SvdVectors::both);

/// Singular values of `a`, decreasing: LAPACK's dgesdd without vectors (QR iteration on the
/// bidiagonal form), checked by order and Σσ² = ‖a‖²_F, else from the checked SVD.
Eigen::VectorXd singular_values(const Eigen::MatrixXd& a);

/// Numerical rank of `a` with its evidence (from singular_values).
RankDecision numerical_rank(const Eigen::MatrixXd& a, const RankTolerance& tolerance = {});

}  // namespace kinestat::linalg
