// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every rank kinestat reports carries its evidence: how far the smallest kept singular value
// (or exact pivot) is from the largest dropped one, so a user sees how close the design is
// to a different answer.

#include <Eigen/Core>

#include <algorithm>
#include <optional>
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

/// Relative rank tolerance. When unset, the LAPACK/NumPy/MATLAB rule applies:
/// tol = max(rows, cols) * machine epsilon * sigma_max.
/// `input_rounding` (relative): how precisely the input fixes the matrix — ε × the largest input
/// coordinate magnitude / the model's size (`input_rounding_level`); 0 for matrices not built
/// from coordinates. The default rule becomes max(rows, cols) · max(ε, kInputRoundingFactor ·
/// input_rounding).
struct RankTolerance {
  std::optional<double> relative;  ///< threshold as a fraction of sigma_max, overriding the default rule
  double input_rounding = 0.0;     ///< relative rounding level of the input coordinates (see above)
};

/// The default relative tolerance: `max(rows, cols) * eps` (the LAPACK rule), raised to
/// `max(rows, cols) * kInputRoundingFactor * input_rounding` when the input is coarser.
double default_relative_tolerance(Eigen::Index rows, Eigen::Index cols, double input_rounding = 0.0);

/// ε × (largest coordinate magnitude) / `size`: the relative error of coordinates written at full
/// double precision, against the model's size (both in the user's unit and frame).
double input_rounding_level(double largest_coordinate, double size);

/// What a rank decision rests on (docs/architecture.md, "Rank decisions: exact, certain, close").
enum class RankStatus {
  exact,     ///< rational arithmetic: no rounding, no tolerance
  certain,   ///< floating point: the gap exceeds the proven error bound of the computed singular values
  close,     ///< floating point: rounding (or a loose tolerance) could give another rank
  unproven,  ///< sparse QR: a clear gap in |R_ii|, but R's diagonal bounds no singular value
};

/// "exact", "certain", "close" or "unproven", as in reports.
const char* rank_status_name(RankStatus status);

/// Proven bound on |σ̂_i − σ_i| for the singular values of a backward-stable SVD of an m × n
/// matrix whose largest singular value is `largest` and whose entries come from coordinates of
/// relative rounding `input_rounding` (RankTolerance): (m·n·ε + kInputRoundingFactor·max(m, n)·ρ)·σ_max.
/// The SVD part is Weyl's theorem applied to the backward error ‖E‖₂ ≤ p(m, n)·ε·‖A‖₂ of the
/// Householder bidiagonalisation (Golub & Van Loan, Matrix Computations, 4th ed., §8.6.1 and
/// Cor. 8.6.2; LAPACK Users' Guide §4.9.1) with p(m, n) = m·n (Higham's γ_mn growth, Accuracy
/// and Stability of Numerical Algorithms, 2nd ed., Thm 19.4); the input part is the perturbation
/// the rounding of the coordinates makes (the model of the default rank threshold). Absolute.
double singular_value_error_bound(Eigen::Index rows, Eigen::Index cols, double input_rounding, double largest);

/// Outcome of one rank decision.
struct RankDecision {
  Eigen::Index rank = 0;
  bool exact = false;              ///< decided by exact rational elimination (no tolerance involved)
  double largest = 0.0;            ///< sigma_max (exact decisions: of the floating-point copy, 0 when none was made)
  double threshold = 0.0;          ///< absolute threshold used: values above it are kept
  double smallest_kept = 0.0;      ///< smallest singular value counted in the rank (0 if rank = 0)
  double largest_dropped = 0.0;    ///< largest singular value below the threshold (0 if none)
  double rounding_level = 0.0;     ///< default_relative_tolerance * sigma_max: what rounding alone produces
  double input_rounding = 0.0;     ///< relative rounding level of the input coordinates (0: not from coordinates)
  Eigen::Index rows = 0, cols = 0; ///< size of the matrix ranked
  bool sparse = false;             ///< decided by a sparse QR: smallest_kept is the smallest kept |R_ii|
  double error_bound = 0.0;        ///< singular_value_error_bound of the floating-point values (0: none)
  /// Sparse decisions, when `factor_estimated`: σ_min(R11) of the factor's live block
  /// (SparseQr::smallest_singular_estimate), at most smallest_kept. Below the threshold it shows
  /// that the kept columns are nearly dependent, so the rank may be too high.
  double factor_smallest = 0.0;
  bool factor_estimated = false;

  /// Ratio smallest_kept / largest_dropped: large means a clear decision; infinite for exact
  /// decisions or when nothing was dropped.
  double gap() const;
  /// exact; certain when the smallest kept value is at least kCertainMargin × error_bound and
  /// every dropped value is within error_bound; unproven for a sparse decision whose smallest
  /// kept |R_ii| (and factor_smallest, when estimated) is at least kCertainMargin × the
  /// threshold; close otherwise.
  RankStatus status() const;
  /// True when status() is close: rounding or the tolerance decides between two answers.
  bool close() const;
  /// smallest_kept / largest: the relative size of the smallest change of the matrix that lowers
  /// the rank (Eckart–Young), of the floating-point copy for exact decisions; for a sparse
  /// decision with factor_estimated, min(smallest_kept, factor_smallest) / largest. Empty when the
  /// rank is 0 or no singular values are known.
  std::optional<double> distance() const;
  /// largest_dropped / largest: how far the matrix is from one of the rank decided. Empty when no
  /// singular values are known.
  std::optional<double> relative_dropped() const;
  /// min(rows, cols): the largest rank the matrix could have.
  Eigen::Index full_rank() const { return std::min(rows, cols); }
};


/// Decides the rank from singular values sorted in decreasing order.
RankDecision decide_rank(const Eigen::VectorXd& singular_values, Eigen::Index rows, Eigen::Index cols,
                         const RankTolerance& tolerance);

/// Adds to an exact decision the evidence of a floating-point factorisation of the same matrix
/// (`singular_values` decreasing, of a conditioned floating-point copy): largest, smallest kept
/// and largest dropped at the exact rank, so distance() tells how near the design is to another
/// rank. The status stays exact.
void add_floating_evidence(RankDecision& decision, const Eigen::VectorXd& singular_values);

}  // namespace kinestat::linalg
