// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The most positive combination of symmetric quadratic forms: the search behind prestress
// stability (Connelly & Whiteley 1996), for frameworks (stress matrices of the self-stresses)
// and coupling networks (second-order loop-closure forms of the self-stresses).

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace kinestat::linalg {

/// Maximises λ_min(Σ c_k Q_k) over unit vectors c (forms: symmetric, all of one size, at least
/// one). Returns the largest λ_min found, in the forms' own units, and its c. The function is
/// concave and positively homogeneous: a deterministic scan of directions (exhaustive on a grid
/// for one to three forms, sampled for more) is refined by projected supergradient ascent.
std::pair<double, Eigen::VectorXd> most_positive_combination(const std::vector<Eigen::MatrixXd>& forms);

}  // namespace kinestat::linalg
