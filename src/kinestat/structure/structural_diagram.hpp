// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The structural diagram of seed 004 (Fig. 2.g, Fig. 4.c) as data: one node per structural
// group labelled (N_m, n_c), the frame as node 0, and an arrow from every group to each group
// that received DOF from it. Nodes are placed in layers by solution stage so that drawings
// are deterministic and read top-down in the order of solution.

#include <vector>

#include "kinestat/structure/decomposition.hpp"

namespace kinestat::structure {

struct DiagramNode {
  int group = 0;  ///< 0 = frame
  int Nm = 0;
  int nc = 0;
  int layer = 0;  ///< the group's stage (frame: 0)
  int slot = 0;   ///< position within its layer, by order of formation
};

struct DiagramArrow {
  int from = 0;  ///< group numbers, 0 = frame
  int to = 0;
};

struct StructuralDiagram {
  std::vector<DiagramNode> nodes;    ///< frame first, then groups in order of formation
  std::vector<DiagramArrow> arrows;  ///< sorted by (to, from)
  int layers = 1;
  int widest_layer = 1;
};

/// Builds the diagram of a decomposition.
StructuralDiagram structural_diagram(const StructureResult& decomposition);

}  // namespace kinestat::structure
