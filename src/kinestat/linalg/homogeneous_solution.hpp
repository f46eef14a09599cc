// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The solution space of a homogeneous system A x = 0, expressed in terms of chosen free
// variables (Davies' "primary variables"), exactly or in floating point. This is the one
// piece of linear algebra that all four of Davies' methods share.

#include "kinestat/error.hpp"
#include <Eigen/Core>

#include <optional>
#include <stdexcept>
#include <vector>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/linalg/rational_matrix.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

/// x = coefficients * x_free spans every solution of A x = 0.
struct HomogeneousSolution {
  RankDecision rank;                              ///< rank of A with its evidence
  Eigen::VectorXd singular_values;                ///< of A, decreasing (floating-point solves only)
  std::vector<Eigen::Index> free_variables;       ///< indices into x, increasing; size = nullity
  Eigen::MatrixXd coefficients;                   ///< n x nullity, identity on the free variables
  std::optional<RationalMatrix> exact_coefficients;  ///< the same, exactly, when A was rational
  std::vector<Eigen::Index> redundant_rows;       ///< rows of A that depend on later rows

  Eigen::Index nullity() const { return static_cast<Eigen::Index>(free_variables.size()); }
};


/// Solves A x = 0 exactly. Free variables are the earliest variables that can be free
/// (elimination pivots from the last column backwards), which reproduces Davies' choice of
/// primary variables for the motions of the 2-circuit network; redundant rows are those
/// that depend on later rows.
HomogeneousSolution solve_homogeneous(const RationalMatrix& a);

/// Solves A x = 0 in floating point: rank from the SVD, null space from V, then the same
/// rules for free variables and redundant rows as the exact version, with named tolerances:
/// `free_variable` is the residual a variable's row of the null basis must keep to be chosen
/// free (Tolerances::free_variable).
HomogeneousSolution solve_homogeneous(const Eigen::MatrixXd& a, const RankTolerance& tolerance,
                                      double free_variable = kFreeVariableResidual);

/// The null-space basis with the earliest possible free variables (the floating-point rule of
/// solve_homogeneous) from any orthonormal basis `null_basis` (n × nullity) of it: columns are
/// identity on `free_variables` (set here, increasing). When fewer than nullity variables pass
/// `free_variable` (only right at the tolerance), the result has that many zero columns.
Eigen::MatrixXd echelon_null_basis(const Eigen::MatrixXd& null_basis, std::vector<Eigen::Index>& free_variables,
                                   double free_variable = kFreeVariableResidual);

/// Thrown when requested free variables cannot all be free together.
class DependentFreeVariable : public Error {
 public:
  DependentFreeVariable(Eigen::Index variable, const char* why) : Error(why), variable_(variable) {}
  /// The first requested variable that is determined by the ones before it (or by nothing).
  Eigen::Index variable() const { return variable_; }

 private:
  Eigen::Index variable_;
};

/// Re-expresses `solution` in terms of `chosen` (exactly nullity() distinct indices, any
/// order; the result lists them in increasing order). Throws DependentFreeVariable when they
/// are dependent to within `free_variable` (Tolerances::free_variable).
HomogeneousSolution with_free_variables(const HomogeneousSolution& solution, std::vector<Eigen::Index> chosen,
                                        double free_variable = kFreeVariableResidual);

/// Indices of the rows of `a` that depend on later rows (exact).
std::vector<Eigen::Index> redundant_rows(const RationalMatrix& a);

/// The same in floating point when the rank of `a` is already known (decided on a better
/// conditioned copy whose rows are mixed, e.g. a change of origin and length unit): rows are
/// scaled to unit length, which does not change which rows depend on which, and kept from the
/// bottom up while independent (residual above kFreeVariableResidual); rows beyond `rank` are
/// redundant. Falls back to column-pivoted QR if the greedy pass keeps a different number.
std::vector<Eigen::Index> redundant_rows(const Eigen::MatrixXd& a, Eigen::Index rank);

}  // namespace kinestat::linalg
