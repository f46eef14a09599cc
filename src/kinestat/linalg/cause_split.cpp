// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/cause_split.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <numeric>

namespace kinestat::linalg {

std::string cause_name(Cause cause) { return cause == Cause::topology ? "topology" : "geometry"; }

CauseSplit split_by_count(Eigen::Index count, Eigen::Index persisting) {
  CauseSplit split;
  for (Eigen::Index i = 0; i < count; ++i) split.causes.push_back(i < persisting ? Cause::topology : Cause::geometry);
  return split;
}

CauseSplit split_by_subspace(const Eigen::MatrixXd& states, const Eigen::MatrixXd& persisting_states) {
  const Eigen::Index count = states.cols();
  const Eigen::Index persisting = std::min(persisting_states.cols(), count);
  CauseSplit split = split_by_count(count, 0);
  if (persisting == 0) return split;
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(persisting_states).householderQ() *
                            Eigen::MatrixXd::Identity(persisting_states.rows(), persisting);
  std::vector<double> residual(static_cast<std::size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i) {
    const Eigen::VectorXd x = states.col(i);
    const double norm = x.norm();
    residual[static_cast<std::size_t>(i)] = norm == 0.0 ? 1.0 : (x - q * (q.transpose() * x)).norm() / norm;
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return residual[static_cast<std::size_t>(a)] < residual[static_cast<std::size_t>(b)]; });
  for (Eigen::Index k = 0; k < persisting; ++k) {
    const auto i = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
    split.causes[i] = Cause::topology;
    split.residual = std::max(split.residual, residual[i]);
  }
  return split;
}

}  // namespace kinestat::linalg
