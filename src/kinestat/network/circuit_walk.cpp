// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/circuit_walk.hpp"

#include <algorithm>

namespace kinestat::network {

namespace {

// The factors of circuit `row` (see circuit_walks); empty if the walk fails.
std::vector<CircuitFactor> circuit_factors(const Model& model, const NetworkResult& r, Eigen::Index row,
                                           const std::vector<std::vector<int>>& magnitudes_of) {
  std::vector<int> members;
  for (Eigen::Index e = 0; e < r.B.cols(); ++e)
    if (r.B(row, e) != 0) members.push_back(static_cast<int>(e));
  if (members.empty() || static_cast<std::size_t>(row) >= r.chords.size()) return {};
  const int chord = r.chords[static_cast<std::size_t>(row)];
  std::vector<char> used(model.couplings.size(), 0);
  std::vector<CircuitFactor> factors;
  const auto& first = model.couplings[static_cast<std::size_t>(chord)];
  const int start = first.from;
  int body = start, coupling = chord;
  for (std::size_t step = 0; step < members.size(); ++step) {
    const auto& c = model.couplings[static_cast<std::size_t>(coupling)];
    const double sign = c.from == body ? 1.0 : -1.0;
    used[static_cast<std::size_t>(coupling)] = 1;
    std::vector<int> order = magnitudes_of[static_cast<std::size_t>(coupling)];
    if (sign < 0) std::reverse(order.begin(), order.end());
    for (int i : order) factors.push_back({i, sign});
    body = sign > 0 ? c.to : c.from;
    if (step + 1 == members.size()) break;
    coupling = -1;
    for (int e : members)
      if (!used[static_cast<std::size_t>(e)]) {
        const auto& next = model.couplings[static_cast<std::size_t>(e)];
        if (next.from == body || next.to == body) {
          coupling = e;
          break;
        }
      }
    if (coupling < 0) return {};
  }
  if (body != start) return {};
  return factors;
}

}  // namespace

bool has_product_of_exponentials_model(screw::CouplingType type) {
  using screw::CouplingType;
  // Lower pairs whose motion is the product of the exponentials of their unit twists in the
  // order the basis lists them (universal: `axis` on the `from` side first); the others are
  // subgroups, where the order does not matter. Higher pairs need curvatures.
  return type != CouplingType::point_on_plane && type != CouplingType::point_on_line && type != CouplingType::custom;
}

std::vector<std::vector<CircuitFactor>> circuit_walks(const Model& model, const NetworkResult& r) {
  std::vector<std::vector<int>> magnitudes_of(model.couplings.size());
  for (std::size_t i = 0; i < r.motions.size(); ++i) {
    const auto coupling = static_cast<std::size_t>(r.motions[i].coupling);
    if (coupling < magnitudes_of.size()) magnitudes_of[coupling].push_back(static_cast<int>(i));
  }
  std::vector<std::vector<CircuitFactor>> walks;
  for (Eigen::Index row = 0; row < r.B.rows(); ++row) walks.push_back(circuit_factors(model, r, row, magnitudes_of));
  return walks;
}

}  // namespace kinestat::network
