// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/structure/structural_diagram.hpp"

#include <algorithm>

namespace kinestat::structure {

StructuralDiagram structural_diagram(const StructureResult& decomposition) {
  StructuralDiagram diagram;
  diagram.nodes.push_back({0, 0, 0, 0, 0});
  std::vector<int> used;  // nodes per layer so far
  used.push_back(1);
  for (const StructuralGroup& g : decomposition.groups) {
    if (static_cast<int>(used.size()) <= g.stage) used.resize(g.stage + 1, 0);
    diagram.nodes.push_back({g.number, g.Nm, g.nc, g.stage, used[g.stage]++});
    for (int from : g.after) diagram.arrows.push_back({from, g.number});
  }
  diagram.layers = static_cast<int>(used.size());
  diagram.widest_layer = *std::max_element(used.begin(), used.end());
  return diagram;
}

}  // namespace kinestat::structure
