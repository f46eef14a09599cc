#pragma once
// Full singular value decomposition with a rank decision, for analyses that need the
// singular vectors themselves (kinematic modes from V, self-stress states from U).

#include <Eigen/Core>

#include "kinestat/linalg/rank_decision.hpp"

namespace kinestat::linalg {

struct SvdAnalysis {
  Eigen::MatrixXd u;                 ///< rows x rows, left singular vectors
  Eigen::MatrixXd v;                 ///< cols x cols, right singular vectors
  Eigen::VectorXd singular_values;   ///< min(rows, cols) values, decreasing
  RankDecision rank;

  /// Columns of V spanning the null space of A (cols x (cols - rank)).
  Eigen::MatrixXd null_space() const { return v.rightCols(v.cols() - rank.rank); }
  /// Columns of U spanning the null space of A^T (rows x (rows - rank)).
  Eigen::MatrixXd left_null_space() const { return u.rightCols(u.cols() - rank.rank); }
};

/// Full SVD of `a` (Eigen's divide-and-conquer BDCSVD) and its numerical rank.
SvdAnalysis analyse_svd(const Eigen::MatrixXd& a, const RankTolerance& tolerance = {});

/// Numerical rank of `a` with its evidence (singular values only).
RankDecision numerical_rank(const Eigen::MatrixXd& a, const RankTolerance& tolerance = {});

}  // namespace kinestat::linalg
