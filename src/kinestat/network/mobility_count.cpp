// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/mobility_count.hpp"

#include "kinestat/linalg/rational_matrix.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

MobilityCount count_mobility(int bodies, const std::vector<graph::Edge>& edges,
                             const std::vector<const screw::CouplingBasis*>& bases, int d, bool exact,
                             const Tolerances& tolerances, double input_rounding) {
  const graph::CouplingGraph graph(bodies, edges);
  const graph::SpanningTree tree = graph.breadth_first_tree(0);
  if (static_cast<int>(tree.branches.size()) != bodies - 1)
    throw graph::TreeError("the couplings do not connect every body");
  const Eigen::MatrixXi B = graph.circuit_matrix(tree);

  MobilityCount count;
  count.l = static_cast<int>(B.rows());
  std::vector<int> first{0};  // column of coupling e's first motion
  for (const auto* basis : bases) first.push_back(first.back() + static_cast<int>(basis->motions.size()));
  count.F = first.back();
  // M^N = [M^D Diag(row i of B^M)] stacked over the circuits (seed 000, eq. 5a), in only the
  // arithmetic the rank is taken in.
  const auto rows = static_cast<Eigen::Index>(d) * count.l;
  linalg::RationalMatrix exact_mn(exact ? rows : 0, exact ? count.F : 0);
  Eigen::MatrixXd mn = Eigen::MatrixXd::Zero(exact ? 0 : rows, exact ? 0 : count.F);
  for (Eigen::Index i = 0; i < B.rows(); ++i)
    for (std::size_t e = 0; e < bases.size(); ++e) {
      const int sign = B(i, static_cast<Eigen::Index>(e));
      if (sign == 0) continue;
      for (std::size_t j = 0; j < bases[e]->motions.size(); ++j) {
        const auto& screw = bases[e]->motions[j].coordinates;
        const Eigen::Index column = first[e] + static_cast<int>(j);
        for (int r = 0; r < d; ++r) {
          const auto& x = screw[static_cast<std::size_t>(r)];
          if (exact) exact_mn(i * d + r, column) = sign > 0 ? x : linalg::Rational(-x);
          else mn(i * d + r, column) = sign * x.get_d();
        }
      }
    }
  count.m = static_cast<int>(rows == 0 || count.F == 0 ? 0
                             : exact ? linalg::exact_rank(exact_mn)
                                     : linalg::numerical_rank(mn, {tolerances.rank, input_rounding}).rank);
  count.FN = count.F - count.m;
  count.CN = d * count.l - count.m;
  return count;
}

}  // namespace kinestat::network
