// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/non_finite_matrix.hpp"

namespace kinestat::linalg {

NonFiniteMatrix::NonFiniteMatrix()
    : Error("a floating-point decomposition met an infinite or NaN number: the model's numbers (or their products in "
            "the analysis) are beyond the range of double precision, about 1.8e308; give them in a smaller unit") {}

void require_finite(const Eigen::MatrixXd& a) {
  if (!a.allFinite()) throw NonFiniteMatrix();
}

}  // namespace kinestat::linalg
