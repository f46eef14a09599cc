// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/sparse_pair_freedoms.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/network/analyse_network.hpp"

namespace kinestat::network {

namespace {

using Index = Eigen::Index;

// The rank of `block` with singular values at or below `level` (absolute) dropped.
linalg::RankDecision block_rank(const Eigen::MatrixXd& block, double level) {
  linalg::RankDecision d;
  const double largest = block.norm();
  if (block.size() == 0 || largest <= level) {
    d.threshold = d.rounding_level = level;
    d.largest = d.largest_dropped = largest;
    return d;
  }
  linalg::RankTolerance tolerance;
  tolerance.relative = level / largest;
  return linalg::numerical_rank(block, tolerance);
}

// The level below which a pair block of the generic vectors `generic` decides nothing:
// `relative` of the whole matrix's size (as forms_rank decides pair ranks on the dense path), or
// the factor's attainable accuracy `support_zero` of its largest entry when that is larger (the
// level at which the supports of the same factor are decided; smaller entries are rounding).
double pair_level(const Eigen::MatrixXd& generic, double relative, double support_zero) {
  if (generic.size() == 0) return 0.0;
  return std::max(relative * generic.norm(), support_zero * generic.cwiseAbs().maxCoeff());
}

}  // namespace

std::vector<SparsePairFreedom> sparse_pair_freedoms(const Model& model, const SparseNetworkResult& r,
                                                    const std::vector<std::pair<int, int>>& pairs, bool coupled,
                                                    const Tolerances& tolerances) {
  const Index d = r.d;
  if (r.generic_motions.rows() != d * (r.bodies - 1) || r.generic_stresses.rows() != r.C)
    throw ModelError("pairs", -1, "pair freedoms need the analysis's generic motions and self-stresses (pair_vectors)");
  auto column = [&r, d](int body) -> Index { return body == r.ground ? -1 : (body < r.ground ? body : body - 1) * d; };
  // T_j − T_i over the generic motions (d × count).
  auto relative_twists = [&](int i, int j) {
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(d, r.generic_motions.cols());
    if (const Index cj = column(j); cj >= 0) t += r.generic_motions.middleRows(cj, d);
    if (const Index ci = column(i); ci >= 0) t -= r.generic_motions.middleRows(ci, d);
    return t;
  };
  std::vector<Index> first_row(model.couplings.size() + 1, static_cast<Index>(r.row_coupling.size()));
  for (std::size_t row = r.row_coupling.size(); row-- > 0;) first_row[static_cast<std::size_t>(r.row_coupling[row])] = static_cast<Index>(row);
  for (std::size_t e = model.couplings.size(); e-- > 0;) first_row[e] = std::min(first_row[e], first_row[e + 1]);
  std::map<std::pair<int, int>, std::vector<int>> direct;  // only for the pairs asked for
  std::vector<std::pair<int, int>> order;
  std::set<std::pair<int, int>> listed;
  for (auto [a, b] : pairs) {
    if (a < 0 || b < 0 || a >= r.bodies || b >= r.bodies) throw ModelError("pairs", -1, "a pair names a body that is not in the model");
    if (a == b) throw ModelError("pairs", -1, fmt::format("a pair needs two different bodies, not '{}' twice", model.bodies[static_cast<std::size_t>(a)]));
    const std::pair<int, int> p{std::min(a, b), std::max(a, b)};
    if (listed.insert(p).second) {
      order.push_back(p);
      direct[p];
    }
  }
  for (std::size_t e = 0; e < model.couplings.size(); ++e) {
    const auto& c = model.couplings[e];
    const std::pair<int, int> p{std::min(c.from, c.to), std::max(c.from, c.to)};
    auto it = direct.find(p);
    if (it == direct.end() && coupled) {
      order.push_back(p);
      it = direct.emplace(p, std::vector<int>{}).first;
    }
    if (it != direct.end()) it->second.push_back(static_cast<int>(e));
  }
  const double motion_level = pair_level(r.generic_motions, tolerances.pair_rank, r.motion_support_zero);
  const double action_level = pair_level(r.generic_stresses, tolerances.pair_rank, r.stress_support_zero);
  std::vector<SparsePairFreedom> rows;
  for (const auto& p : order) {
    SparsePairFreedom pair;
    pair.body_i = p.first;
    pair.body_j = p.second;
    pair.motion_rank = block_rank(relative_twists(p.first, p.second), motion_level);
    pair.fij = static_cast<int>(pair.motion_rank.rank);
    const auto& couplings = direct[p];
    if (couplings.empty()) {
      pair.f = static_cast<int>(d);
      rows.push_back(pair);
      continue;
    }
    for (int e : couplings) {
      SparsePairFreedom row = pair;
      row.coupling = e;
      const Index first = first_row[static_cast<std::size_t>(e)], count = first_row[static_cast<std::size_t>(e) + 1] - first;
      row.c = static_cast<int>(count);
      row.f = static_cast<int>(d - count);
      row.action_rank = block_rank(r.generic_stresses.middleRows(first, count), action_level);
      row.cij = static_cast<int>(row.action_rank.rank);
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace kinestat::network
