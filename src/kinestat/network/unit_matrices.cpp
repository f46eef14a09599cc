// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/unit_matrices.hpp"

namespace kinestat::network {

namespace {

// Columns of a graph matrix repeated once per unit screw of their coupling.
Eigen::MatrixXi expand_columns(const Eigen::MatrixXi& graph_matrix, const std::vector<int>& first) {
  Eigen::MatrixXi expanded = Eigen::MatrixXi::Zero(graph_matrix.rows(), first.back());
  for (Eigen::Index e = 0; e < graph_matrix.cols(); ++e)
    for (int column = first[static_cast<std::size_t>(e)]; column < first[static_cast<std::size_t>(e) + 1]; ++column)
      expanded.col(column) = graph_matrix.col(e);
  return expanded;
}

// [unit Diag(row i of expanded)] stacked for every row i.
linalg::RationalMatrix network_matrix(const linalg::RationalMatrix& unit, const Eigen::MatrixXi& expanded) {
  const Eigen::Index d = unit.rows();
  linalg::RationalMatrix network(d * expanded.rows(), unit.cols());
  for (Eigen::Index i = 0; i < expanded.rows(); ++i)
    for (Eigen::Index column = 0; column < unit.cols(); ++column) {
      const int sign = expanded(i, column);
      if (sign == 0) continue;
      for (Eigen::Index r = 0; r < d; ++r) network(i * d + r, column) = sign * unit(r, column);
    }
  return network;
}

}  // namespace

UnitMatrices unit_matrices(const std::vector<screw::CouplingBasis>& bases, int d, const Eigen::MatrixXi& B,
                           const Eigen::MatrixXi& Q) {
  UnitMatrices u;
  u.first_motion.push_back(0);
  u.first_action.push_back(0);
  for (const auto& basis : bases) {
    u.first_motion.push_back(u.first_motion.back() + static_cast<int>(basis.motions.size()));
    u.first_action.push_back(u.first_action.back() + static_cast<int>(basis.actions.size()));
  }
  u.MD = linalg::RationalMatrix(d, u.first_motion.back());
  u.AD = linalg::RationalMatrix(d, u.first_action.back());
  for (std::size_t e = 0; e < bases.size(); ++e) {
    for (std::size_t j = 0; j < bases[e].motions.size(); ++j)
      for (int r = 0; r < d; ++r)
        u.MD(r, u.first_motion[e] + static_cast<int>(j)) = bases[e].motions[j].coordinates[static_cast<std::size_t>(r)];
    for (std::size_t j = 0; j < bases[e].actions.size(); ++j)
      for (int r = 0; r < d; ++r)
        u.AD(r, u.first_action[e] + static_cast<int>(j)) = bases[e].actions[j].coordinates[static_cast<std::size_t>(r)];
  }
  u.BM = expand_columns(B, u.first_motion);
  u.QA = expand_columns(Q, u.first_action);
  u.MN = network_matrix(u.MD, u.BM);
  u.AN = network_matrix(u.AD, u.QA);
  return u;
}

}  // namespace kinestat::network
