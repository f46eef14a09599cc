// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The refusal of a matrix with an infinite or NaN entry before it reaches LAPACK: dgesdd's QR
// iteration (dbdsqr) never returned on a 13 × 6 matrix with infinite entries (found by
// fuzz_model_file: a network with a 120-digit coordinate, whose exact numbers exceed the range of
// doubles once converted). Such entries come from model numbers too large for floating point,
// so the error is the input's (exit code 2), not an internal one.

#include <Eigen/Core>

#include "kinestat/error.hpp"

namespace kinestat::linalg {

/// A floating-point decomposition was asked of a matrix with an infinite or NaN entry.
class NonFiniteMatrix : public Error {
 public:
  NonFiniteMatrix();
};

/// Throws NonFiniteMatrix unless every entry of `a` is finite.
void require_finite(const Eigen::MatrixXd& a);

}  // namespace kinestat::linalg
