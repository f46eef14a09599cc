// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Laman's count for planar bar frameworks by the (2, 3) pebble game (Jacobs and Hendrickson,
// J. Comput. Phys. 137, 1997): which bars are independent at a generic realisation of the same
// graph, and the rigid components. A combinatorial check, independent of any matrix, of the
// generic rank of a planar truss framework.

#include <cstddef>
#include <utility>
#include <vector>

namespace kinestat::framework {

struct PebbleGame {
  std::size_t independent = 0;          ///< bars independent at a generic realisation
  std::vector<std::size_t> redundant;   ///< bars (indices into the input) dependent on earlier ones
  /// Rigid components with at least one bar, each a sorted list of vertices; components
  /// listed by their smallest vertex.
  std::vector<std::vector<std::size_t>> rigid_components;
};

/// Plays the (2, 3) pebble game on `vertices` vertices and the bars `bars` (pairs of vertex
/// indices, no loops), inserted in order.
PebbleGame pebble_game(std::size_t vertices, const std::vector<std::pair<std::size_t, std::size_t>>& bars);

}  // namespace kinestat::framework
