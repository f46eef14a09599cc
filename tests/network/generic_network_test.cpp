// SPDX-License-Identifier: BSD-3-Clause
// The generic answer of coupling networks (issue 12, item 3): FN and CN of the same couplings at
// a random realisation, and which motions and self-stresses exist only because of the geometry.
// Every expected number is derived by hand in the comments (screw systems of lines in general
// position and Grübler-Kutzbach counts, which are exact for generic geometry when no subchain
// is overconstrained).
#include <gtest/gtest.h>

#include <algorithm>

#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/generic_network.hpp"
#include "seed_fixture.hpp"

namespace kinestat::network {
namespace {

struct Answers {
  NetworkResult given;
  GenericNetwork generic;
};

Answers analyse(const io::LoadedNetwork& loaded) {
  Answers a{analyse_network(loaded.model), {}};
  const auto g = generic_network(loaded.model, a.given);
  EXPECT_TRUE(g.has_value());
  if (g) a.generic = *g;
  return a;
}

long count(const std::vector<Cause>& causes, Cause cause) { return std::count(causes.begin(), causes.end(), cause); }

std::vector<std::string> special_names(const io::LoadedNetwork& loaded, const GenericNetwork& g) {
  std::vector<std::string> names;
  if (g.special_couplings)
    for (int e : *g.special_couplings) names.push_back(loaded.model.couplings[static_cast<std::size_t>(e)].name);
  return names;
}

// Four revolutes with parallel axes analysed in space (d = 6, l = 1, F = 4): the twists lie in
// the planar 3-system, so FN = 1, CN = 6 - 3 = 3. Four lines in general position are linearly
// independent screws, so generically m = 4: FN = 0, CN = 6 - 4 = 2. Hence the mobility and one
// of the three self-stresses exist only because the axes are parallel; moving any one axis
// alone makes the four twists independent (three parallel twists span 3 dimensions of the
// planar system, a skew fourth leaves it), so all four couplings take part. (The issue's
// "generic CN = 0" is not right for d = 6: a single loop of four 1-freedom joints always keeps
// at least 6 - 4 = 2 self-stresses.)
TEST(GenericNetwork, PlanarFourBarAnalysedSpatially) {
  const auto loaded = testing::load_example("four-bar-spatial.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.given.FN, 1);
  EXPECT_EQ(a.given.CN, 3);
  EXPECT_EQ(a.generic.FN, 0);
  EXPECT_EQ(a.generic.CN, 2);
  EXPECT_EQ(count(a.generic.motion_causes, Cause::geometry), 1);
  EXPECT_EQ(count(a.generic.action_causes, Cause::topology), 2);
  EXPECT_EQ(count(a.generic.action_causes, Cause::geometry), 1);
  EXPECT_EQ(special_names(loaded, a.generic), (std::vector<std::string>{"A", "B", "C", "D"}));
}

// Bennett's 4R loop: FN = 1, CN = 3 from the file's derivation (the four twists form a
// 3-system). Generic 4R loop as above: FN = 0, CN = 2. Any one axis changed alone breaks
// a / sin(alpha) = b / sin(beta), so all four joints are special.
TEST(GenericNetwork, BennettMobilityComesFromGeometry) {
  const auto loaded = testing::load_example("bennett.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.given.FN, 1);
  EXPECT_EQ(a.generic.FN, 0);
  EXPECT_EQ(a.generic.CN, 2);
  ASSERT_EQ(a.generic.motion_causes.size(), 1U);
  EXPECT_EQ(a.generic.motion_causes[0], Cause::geometry);
  EXPECT_EQ(count(a.generic.action_causes, Cause::geometry), 1);
  EXPECT_EQ(special_names(loaded, a.generic), (std::vector<std::string>{"J1", "J2", "J3", "J4"}));
}

// Sarrus: one loop of six revolutes, F = 6 = d l. Six lines in general position are independent,
// so generically FN = 0, CN = 0: the translation (FN = 1) and its self-stress (CN = 1) need the
// two legs' parallel axes. Randomising one joint (say A1): leg 2 spans {s, u, w} (rotations
// about y-parallel lines), B1 = r + v - w and C1 = r + 2v are independent modulo it (rank 5),
// and a skew A1 adds the sixth dimension — likewise for every other joint.
TEST(GenericNetwork, SarrusIsSpecialEverywhere) {
  const auto loaded = testing::load_example("sarrus.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.given.FN, 1);
  EXPECT_EQ(a.given.CN, 1);
  EXPECT_EQ(a.generic.FN, 0);
  EXPECT_EQ(a.generic.CN, 0);
  EXPECT_EQ(a.generic.motion_causes, std::vector<Cause>{Cause::geometry});
  EXPECT_EQ(a.generic.action_causes, std::vector<Cause>{Cause::geometry});
  EXPECT_EQ(special_names(loaded, a.generic).size(), 6U);
}

// Parallelogram with a redundant crank (planar, d = 3, 5 bodies, 6 revolutes, l = 2): as a bar
// framework the ground and the coupler are triangles (three pins each) joined by the three
// cranks — two triangles joined by three bars in general position are rigid and isostatic, so
// generically FN = 0, CN = 0 (Grübler: 3(5 - 1) - 2 * 6 = 0). The translation of the coupler and
// the fight between the cranks both need the three cranks parallel and equal.
TEST(GenericNetwork, ParallelogramWithRedundantCrank) {
  const auto loaded = testing::load_example("parallelogram-redundant.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.given.FN, 1);
  EXPECT_EQ(a.given.CN, 1);
  EXPECT_EQ(a.generic.FN, 0);
  EXPECT_EQ(a.generic.CN, 0);
  EXPECT_EQ(a.generic.motion_causes, std::vector<Cause>{Cause::geometry});
  EXPECT_EQ(a.generic.action_causes, std::vector<Cause>{Cause::geometry});
  EXPECT_EQ(special_names(loaded, a.generic), (std::vector<std::string>{"A", "B", "C", "D", "E", "H"}));
}

// Stewart 6-UPS: F = 36, l = 5, m = 30 = d l at the given (irregular) geometry; no
// realisation can exceed d l, so the generic answer is the given one: FN = 6, CN = 0, all six
// motions topological.
TEST(GenericNetwork, StewartPlatformIsGeneric) {
  const auto loaded = testing::load_example("stewart-6ups.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.generic.FN, 6);
  EXPECT_EQ(a.generic.CN, 0);
  EXPECT_EQ(count(a.generic.motion_causes, Cause::topology), 6);
  EXPECT_TRUE(!a.generic.special_couplings || a.generic.special_couplings->empty());
}

// Davies' 2-circuit network: ground 1, body 4 on a planar pair C, bodies 2 and 3 each between a
// cylindrical pair (D, E) to the ground and a spherical pair (B, A) to body 4. Generically:
// body 4 has 3 freedoms, body 3 two; the centre of A must move alike on both (3 equations):
// 5 - 3 = 2; body 2 adds 2 freedoms and 3 equations at B: 2 + 2 - 3 = 1. So FN = 1 and, from
// FN - CN = F - d l = 13 - 12, CN = 0. At Davies' geometry the two idle spins (body 3 about E's
// axis, which passes through A's centre; body 4 about the line AB, normal to C's plane) are
// extra motions: FN = 3 = 1 + 2, CN = 2, both self-stresses special. The spins need A, B, C
// and E where they are; the primary vc (the mechanism's own motion) is the topological one.
TEST(GenericNetwork, DaviesTwoCircuitIdleSpinsAreGeometric) {
  const auto loaded = testing::load_example("davies-2-circuit.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.given.FN, 3);
  EXPECT_EQ(a.given.CN, 2);
  EXPECT_EQ(a.generic.FN, 1);
  EXPECT_EQ(a.generic.CN, 0);
  // Primary motions sa, ta, vc (the file's choice): sa and ta are the spins.
  EXPECT_EQ(a.generic.motion_causes, (std::vector<Cause>{Cause::geometry, Cause::geometry, Cause::topology}));
  EXPECT_EQ(a.generic.action_causes, (std::vector<Cause>{Cause::geometry, Cause::geometry}));
  const auto special = special_names(loaded, a.generic);
  for (const char* name : {"A", "B", "C", "E"}) EXPECT_NE(std::find(special.begin(), special.end(), name), special.end()) << name;
}

// A planar four-bar in the plane (d = 3): F = 4 = 3 l + 1, Grübler FN = 1, CN = 0 for any
// geometry — nothing is special.
TEST(GenericNetwork, PlanarFourBarIsGeneric) {
  const auto loaded = testing::load_example("four-bar-planar.yaml");
  const Answers a = analyse(loaded);
  EXPECT_EQ(a.generic.FN, 1);
  EXPECT_EQ(a.generic.CN, 0);
  EXPECT_EQ(a.generic.motion_causes, std::vector<Cause>{Cause::topology});
}

// The generic answer depends on the couplings, not on where the model sits or what it is
// called: moving every point by the same offset and renaming changes nothing.
TEST(GenericNetwork, SameAnswerWhenTranslatedAndRenamed) {
  auto loaded = testing::load_example("bennett.yaml");
  const Answers before = analyse(loaded);
  for (auto& c : loaded.model.couplings) {
    c.name = "moved_" + c.name;
    for (std::size_t i = 0; i < 3; ++i) c.geometry.point[i] += 1000;
  }
  const Answers after = analyse(loaded);
  EXPECT_EQ(after.generic.FN, before.generic.FN);
  EXPECT_EQ(after.generic.CN, before.generic.CN);
  EXPECT_EQ(after.generic.motion_causes, before.generic.motion_causes);
  ASSERT_TRUE(after.generic.special_couplings.has_value());
  EXPECT_EQ(after.generic.special_couplings->size(), 4U);
}

}  // namespace
}  // namespace kinestat::network

namespace kinestat::network {
namespace {

// A ladder of n + 1 bodies: revolutes b_i - b_{i+1} and spherical rungs b_i - b_{i+2}, every
// point and axis pseudo-random whole numbers (general position). Grübler: 6n - 5n - 3(n - 1) =
// 3 - 2n < 0 and, in general position, M^N has full column rank F = n + 3(n - 1): FN = 0 and
// CN = d l - F = 6(n - 1) - (4n - 3) = 2n - 3.
std::string ladder(int n) {
  std::uint64_t state = 12345;
  const auto next = [&state](int range) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(2 * range + 1)) - range;
  };
  std::string text = "kinestat: 1\nkind: network\nname: ladder\ndimension: spatial\nground: b0\ncouplings:\n";
  for (int i = 0; i < n; ++i) {
    int a[3] = {next(9), next(9), next(9)};
    if (a[0] == 0 && a[1] == 0 && a[2] == 0) a[0] = 1;
    text += "  - {name: R" + std::to_string(i) + ", type: revolute, between: [b" + std::to_string(i) + ", b" + std::to_string(i + 1) +
            "], point: [" + std::to_string(next(50)) + ", " + std::to_string(next(50)) + ", " + std::to_string(next(50)) +
            "], axis: [" + std::to_string(a[0]) + ", " + std::to_string(a[1]) + ", " + std::to_string(a[2]) + "]}\n";
    if (i + 2 <= n)
      text += "  - {name: S" + std::to_string(i) + ", type: spherical, between: [b" + std::to_string(i) + ", b" + std::to_string(i + 2) +
              "], point: [" + std::to_string(next(50)) + ", " + std::to_string(next(50)) + ", " + std::to_string(next(50)) + "]}\n";
  }
  return text;
}

// Issue 12, item 4: short decimals, but M^N (270 x 181: 8.8e6 > kExactEliminationWork) too large
// for exact elimination by default: floating point, checked by the rank modulo two primes.
TEST(ModularCheck, LargeRationalNetworkIsCheckedByModularRank) {
  const int n = 46;
  const auto loaded = testing::parse_network(ladder(n));
  const NetworkResult r = analyse_network(loaded.model);
  EXPECT_FALSE(r.exact);
  ASSERT_TRUE(r.modular_check.has_value());
  EXPECT_EQ(r.modular_check->rank, 4 * n - 3);
  EXPECT_EQ(r.modular_check->primes, 2);
  EXPECT_EQ(r.modular_check->agreeing, 2);
  EXPECT_FALSE(r.modular_check->followed);
  EXPECT_EQ(r.FN, 0);
  EXPECT_EQ(r.CN, 2 * n - 3);
  EXPECT_NE(r.arithmetic_reason.find("modular"), std::string::npos);
  // A small model keeps exact elimination and has no modular check.
  const NetworkResult small = analyse_network(testing::parse_network(ladder(5)).model);
  EXPECT_TRUE(small.exact);
  EXPECT_FALSE(small.modular_check.has_value());
  EXPECT_EQ(small.CN, 2 * 5 - 3);
}

}  // namespace
}  // namespace kinestat::network
