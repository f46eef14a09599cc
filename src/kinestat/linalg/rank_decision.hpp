#pragma once
// Every rank kinestat reports carries its evidence: how far the smallest kept singular value
// (or exact pivot) is from the largest dropped one, so a user sees how close the design is
// to a different answer.

#include <Eigen/Core>

#include <optional>
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

/// Relative rank tolerance. When unset, the LAPACK/NumPy/MATLAB rule applies:
/// tol = max(rows, cols) * machine epsilon * sigma_max.
struct RankTolerance {
  std::optional<double> relative;  ///< threshold as a fraction of sigma_max, overriding the default rule
};

/// The default relative tolerance factor `max(rows, cols) * eps` of the LAPACK rule.
double default_relative_tolerance(Eigen::Index rows, Eigen::Index cols);

/// Outcome of one rank decision.
struct RankDecision {
  Eigen::Index rank = 0;
  bool exact = false;              ///< decided by exact rational elimination (no tolerance involved)
  double largest = 0.0;            ///< sigma_max (0 for exact decisions)
  double threshold = 0.0;          ///< absolute threshold used: values above it are kept
  double smallest_kept = 0.0;      ///< smallest singular value counted in the rank (0 if rank = 0)
  double largest_dropped = 0.0;    ///< largest singular value below the threshold (0 if none)
  double rounding_level = 0.0;     ///< max(rows, cols) * eps * sigma_max: what rounding alone produces

  /// Ratio smallest_kept / largest_dropped: large means a clear decision; infinite for exact
  /// decisions or when nothing was dropped.
  double gap() const;
  /// True when the decision is close — the design is near one with a different answer: the gap
  /// is below `kCloseRankGap`, or a dropped value is over `kAboveRounding` times the rounding
  /// level (it was dropped by a loose tolerance, not because it is noise), or a kept value is
  /// below sqrt(eps) of the largest (nearly singular).
  bool close() const;
};


/// Decides the rank from singular values sorted in decreasing order.
RankDecision decide_rank(const Eigen::VectorXd& singular_values, Eigen::Index rows, Eigen::Index cols,
                         const RankTolerance& tolerance);

}  // namespace kinestat::linalg
