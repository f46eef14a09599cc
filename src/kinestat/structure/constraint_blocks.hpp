// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The polynomial core of the structural analysis: the constraints of the pairs (and the
// inputs, which fix freedoms) are assigned to the freedoms of the bodies by a maximum flow,
// and the Dulmage-Mendelsohn decomposition of that assignment splits the mechanism into
//  - an over-constrained part (more constraints and inputs than freedoms),
//  - an under-constrained part (freedoms that no input drives),
//  - and the rest, whose strongly connected blocks are exactly the minimal chains that
//    satisfy Eq. 1 of seed 004 once the blocks they depend on are solved: the structural
//    groups. The dependency order between blocks is the order of DOF assignment.

#include <vector>

#include "kinestat/structure/structure_model.hpp"

namespace kinestat::structure {

/// Constraint units of a pair: it removes d - f freedoms and each input fixes one more.
int constraint_units(const Pair& pair, int dimension);

/// The decomposition of a model's constraint-to-freedom assignment.
struct ConstraintBlocks {
  /// Per body: index into `blocks`, or -1 for the frame and for bodies outside the
  /// well-constrained part.
  std::vector<int> block_of;
  /// Bodies of each block (ascending). Blocks are numbered in a topological order.
  std::vector<std::vector<int>> blocks;
  /// Per block: the blocks that must be solved before it (ascending, unique).
  std::vector<std::vector<int>> predecessors;
  /// Per block: true if it needs a body of the over-constrained part (directly or through
  /// its predecessors).
  std::vector<bool> needs_over_constrained;
  /// Per block: the over-constrained bodies it needs directly (ascending, unique).
  std::vector<std::vector<int>> over_predecessors;
  std::vector<int> over_constrained;   ///< bodies whose freedoms are over-determined
  int redundant_units = 0;             ///< constraints + inputs in excess (over-actuation)
  std::vector<int> under_constrained;  ///< bodies with freedoms no input drives
  int missing_units = 0;               ///< freedoms not driven (missing inputs)
};

/// Runs the maximum flow (Dinic, O(E sqrt(V)) on this unit-like network) and the
/// decomposition. Linear memory; no recursion, so 10^5 bodies are fine.
ConstraintBlocks find_constraint_blocks(const StructureModel& model);

}  // namespace kinestat::structure
