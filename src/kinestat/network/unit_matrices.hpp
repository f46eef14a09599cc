// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The matrices of seed 000, sections 2.3-2.4: circuit and cutset matrices of the motion and
// action graphs, the unit matrices of direct couplings, and the network unit matrices.

#include <Eigen/Core>

#include <vector>

#include "kinestat/linalg/rational_matrix.hpp"
#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::network {

struct UnitMatrices {
  Eigen::MatrixXi BM;            ///< l x F: each coupling's column of B repeated f times (eq. 4a)
  Eigen::MatrixXi QA;            ///< k x C: each coupling's column of Q repeated c times (eq. 4b)
  linalg::RationalMatrix MD;     ///< d x F unit motions of direct couplings
  linalg::RationalMatrix AD;     ///< d x C unit actions of direct couplings
  linalg::RationalMatrix MN;     ///< dl x F: [MD Diag(BM row i)] stacked over circuits (eq. 5a)
  linalg::RationalMatrix AN;     ///< dk x C: [AD Diag(QA row i)] stacked over cutsets (eq. 5b)
  std::vector<int> first_motion; ///< column of MD where each coupling's motions start (e + 1 entries)
  std::vector<int> first_action; ///< column of AD where each coupling's actions start (e + 1 entries)
};

/// Assembles all unit matrices from the couplings' bases (in coupling order) and the
/// circuit and cutset matrices of the coupling graph.
UnitMatrices unit_matrices(const std::vector<screw::CouplingBasis>& bases, int d, const Eigen::MatrixXi& B,
                           const Eigen::MatrixXi& Q);

}  // namespace kinestat::network
