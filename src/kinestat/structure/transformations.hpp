// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Structural transformations (the seed's AMPLIACION): the same mechanism with its input
// movements placed on other pairs. Each placement is decomposed and the placements are
// ranked so that the analyst can pick the one that is easiest to solve.

#include <cstdint>
#include <vector>

#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::structure {

/// One placement of the inputs and its decomposition.
struct Transformation {
  std::vector<int> inputs;        ///< inputs on each pair of the model, same order as model.pairs
  bool original = false;          ///< the placement given by the user
  StructureResult decomposition;
  int largest_group = 0;          ///< bodies in the largest group
  int stages = 0;                 ///< solution stages (groups of one stage can be solved in parallel)
};

/// All decomposable placements, best first.
struct TransformationSet {
  std::vector<Transformation> ranked;
  std::uint64_t placements = 0;      ///< placements with the same number of inputs (saturated at limit + 1)
  std::uint64_t not_decomposable = 0;
  bool enumerated = false;           ///< false when `placements` exceeds the limit: nothing was analysed
};

/// The model with the inputs of each pair replaced by `inputs`.
StructureModel with_inputs(const StructureModel& model, const std::vector<int>& inputs);

/// Number of ways to place `total` inputs on pairs that take at most capacity[k] each,
/// saturated at `cap`: once the count is known to reach `cap` it stops, so a mechanism of a
/// million pairs costs one pass over them, not pairs × inputs.
std::uint64_t count_placements(const std::vector<int>& capacity, int total, std::uint64_t cap);

/// Enumerates every placement of the model's inputs on its pairs (a pair carries at most as
/// many inputs as it has freedoms), decomposes each, keeps the decomposable ones and ranks
/// them: more groups first, then a smaller largest group, then fewer stages, then the order
/// of enumeration (the user's placement first among equals). Nothing is analysed when there
/// are more than `limit` placements.
TransformationSet structural_transformations(const StructureModel& model, std::uint64_t limit = 1000);

}  // namespace kinestat::structure
