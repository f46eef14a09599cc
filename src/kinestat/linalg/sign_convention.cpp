// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/sign_convention.hpp"

#include <cmath>

namespace kinestat::linalg {

void orient_unit_vector(Eigen::Ref<Eigen::VectorXd> v, double zero) {
  const double norm = v.norm();
  if (norm == 0.0) return;
  v /= norm;
  const double largest = v.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (std::abs(v(i)) >= largest - zero) {
      if (v(i) < 0) v = -v;
      break;
    }
  }
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (std::abs(v(i)) < zero) v(i) = 0.0;
}

}  // namespace kinestat::linalg
