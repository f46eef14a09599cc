// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact elimination by FLINT (fmpq_mat / fmpz_mat; Debian libflint-dev), for the exact path's
// ranks, null spaces and inverses (homogeneous_solution.cpp). FLINT clears the denominators of
// each row and eliminates fraction-free over the integers (multimodular for larger matrices),
// where GMP elimination on mpq_class normalises a fraction at every step: the same exact answers,
// several times sooner (bench/README.md, "The exact path: GMP against FLINT").
//
// FLINT is optional at configure time (CMake option KINESTAT_FLINT, on when found). Without it
// flint_available() is false, these functions throw std::logic_error, and the exact path keeps
// its own GMP elimination.

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "kinestat/linalg/rational_matrix.hpp"

namespace kinestat::linalg {

/// Whether this build eliminates with FLINT (KINESTAT_FLINT was on at configure time).
bool flint_available();

/// Installs (once per process; later calls do nothing) FLINT memory functions that throw
/// std::bad_alloc when an allocation fails, where FLINT's own abort(), so that exact
/// elimination of a model too large for the machine ends as a clean error; FLINT's temporaries
/// of the failing operation leak on the way out. Process-wide (FLINT has one set of memory
/// functions), so the library never calls it: the `kinestat` command does, beside
/// install_throwing_gmp_allocation, before any work. Other callers (the Python module, whose
/// process may hold the user's own FLINT) keep FLINT's default. Nothing without FLINT.
void install_throwing_flint_allocation();

/// Rank of `a` over the rationals (each row's denominators cleared, fmpz_mat_rank).
Eigen::Index flint_rank(const RationalMatrix& a);

/// The null space of `a` in reduced echelon form with pivots sought from the last column
/// backwards (the convention of solve_homogeneous: the earliest variables are the free ones).
struct RightPivotNullSpace {
  Eigen::Index rank = 0;
  std::vector<Eigen::Index> pivot_columns;   ///< the pivot of each echelon row, decreasing
  std::vector<Eigen::Index> free_variables;  ///< the other columns, increasing
  RationalMatrix null_basis;                 ///< cols × nullity, identity on the free variables
};

/// Rank and null space of `a` (fmpq_mat_rref of `a` with its columns reversed).
RightPivotNullSpace flint_right_pivot_null_space(const RationalMatrix& a);

/// Rows of `a` that depend on the rows after them (increasing): the rows left out when rows
/// are kept from the bottom up while independent (fmpq_mat_rref of aᵀ with its columns reversed).
std::vector<Eigen::Index> flint_redundant_rows(const RationalMatrix& a);

/// Inverse of the square matrix `a`, or nothing when it is singular (fmpq_mat_inv).
std::optional<RationalMatrix> flint_inverse(const RationalMatrix& a);

}  // namespace kinestat::linalg
