// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One process's stage of the distributed rank decision: the rows that touch its interior
// columns, A_p = [A_I | A_Γ], reduced to the interior's rank and a small block on the interface
// columns with the same rank contribution (docs/scaling.md, "The distributed rank decision").

#include <Eigen/SparseCore>

#include <cstddef>

namespace kinestat::distributed {

/// What one process's rows contribute to rank(A).
struct InteriorReduction {
  /// rank(A_I) by SuiteSparseQR's rank rule (Heath's: a column whose remaining norm is at or
  /// below the threshold is dead), the rule of the serial sparse path.
  Eigen::Index rank = 0;
  /// Smallest kept |R_kk| of A_I's factor (0 when the rank is 0): the stage's evidence.
  double smallest_kept = 0.0;
  /// An upper-triangular block G (at most A_Γ's columns rows) with GᵀG = A_Γᵀ (I − Q₁Q₁ᵀ) A_Γ up to
  /// the threshold, Q₁ an orthonormal basis of range(A_I): the part of A_Γ that the interior
  /// does not span, compressed by a second sparse QR at the same threshold. Columns as A_Γ's.
  /// rank([A_I A_Γ]) = rank + rank(G) (in exact arithmetic, before the thresholds).
  Eigen::SparseMatrix<double> interface_block;
  std::size_t peak_memory = 0;  ///< SuiteSparse's own peak count of the factorisations (the largest), bytes
};

/// Factors `interior` (A_I) by SuiteSparseQR with METIS's order and `threshold` (absolute)
/// twice, one factorisation at a time and neither keeping R: counts only (the rank and its
/// smallest kept pivot, linalg::sparse_qr_rank), then applying Qᵀ to `interface` (A_Γ, the same
/// rows) as it goes; the rows of QᵀA_Γ beyond the rank are compressed into
/// InteriorReduction::interface_block. Throws std::bad_alloc when memory runs out and
/// std::runtime_error when SuiteSparseQR fails otherwise (or its two factorisations disagree on
/// the rank).
InteriorReduction reduce_interior(const Eigen::SparseMatrix<double>& interior, const Eigen::SparseMatrix<double>& interface,
                                  double threshold);

}  // namespace kinestat::distributed
