#pragma once
// Generated planar mechanisms for benchmarks and cross-checks: a crank driven from the
// frame, then structural groups attached to bodies already placed, so that the mechanism is
// well constrained by construction and its decomposition is known.

#include <cstdint>
#include <vector>

#include "kinestat/structure/structure_model.hpp"

namespace kinestat::structure {

/// Which groups the generator may attach.
struct GeneratorMix {
  int dyads = 6;            ///< RRR dyads (2 bodies, 3 lower pairs)
  int triads = 2;           ///< class-III groups (4 bodies: a ternary link and three binary links, 6 lower pairs)
  int followers = 1;        ///< single bodies with one lower and one higher pair (a cam follower)
  int cranks = 1;           ///< single bodies driven by an input on a lower pair
};

/// A generated mechanism and the structural groups it was built from (0-based bodies,
/// ascending), in generation order.
struct GeneratedMechanism {
  StructureModel model;
  std::vector<std::vector<int>> groups;
};

/// A mechanism with exactly `bodies` bodies (frame included, at least 2). Groups are drawn
/// with weights `mix` from a deterministic generator seeded with `seed`; each attaches to
/// distinct bodies already placed, so that groups are formed in generation order. With
/// `shuffle`, bodies 2..N are renumbered at random, which exercises the search order.
GeneratedMechanism generate_group_chain(int bodies, std::uint32_t seed, GeneratorMix mix = {}, bool shuffle = false);

}  // namespace kinestat::structure
