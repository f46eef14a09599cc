// SPDX-License-Identifier: BSD-3-Clause
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

/// One large structural group: a crank driven from the frame and a closed ring of
/// `ring_bodies` (even, at least 4) links joined by revolutes, every second link also
/// pinned to the frame or the crank. 3 m = 2 (m + m / 2): the ring is a single Assur group
/// of m bodies, the worst case for a search over chains of growing length.
GeneratedMechanism generate_ring_group(int ring_bodies);

/// One structural group shaped like a ladder: two rails of `rungs` links each, joined
/// rung by rung by revolutes, one end pinned to the frame and the other to a driven crank.
/// 3 (2 m) = 2 ((3 m - 2) + 2). Its connected subchains grow exponentially with m, which is
/// what makes the seed's search over chains exponential.
GeneratedMechanism generate_ladder_group(int rungs);

}  // namespace kinestat::structure
