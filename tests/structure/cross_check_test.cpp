// SPDX-License-Identifier: BSD-3-Clause
// The polynomial method against the seed's own search (Algorithms 1-3), on generated
// mechanisms with shuffled body numbers and on random adjacency matrices: whenever the
// mechanism is well constrained, the two must give the same groups in the same order and
// the same result matrix.
#include <gtest/gtest.h>

#include <random>

#include "kinestat/structure/decomposition.hpp"
#include "support/mechanism_generator.hpp"

namespace kinestat::structure {
namespace {

void expect_same(const StructureResult& a, const StructureResult& b, const std::string& what) {
  ASSERT_EQ(a.groups.size(), b.groups.size()) << what;
  for (std::size_t i = 0; i < a.groups.size(); ++i) {
    EXPECT_EQ(a.groups[i].bodies, b.groups[i].bodies) << what << ", group " << i + 1;
    EXPECT_EQ(a.groups[i].P, b.groups[i].P) << what;
    EXPECT_EQ(a.groups[i].Sc, b.groups[i].Sc) << what;
    EXPECT_EQ(a.groups[i].nc, b.groups[i].nc) << what;
  }
  EXPECT_EQ(a.result_matrix(), b.result_matrix()) << what;
}

TEST(CrossCheck, GeneratedMechanismsAgreeAndRecoverTheirGroups) {
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    const int bodies = 4 + static_cast<int>(seed % 11);
    const GeneratedMechanism g = generate_group_chain(bodies, seed, {}, /*shuffle=*/true);
    const StructureResult fast = analyse_structure(g.model, SearchMethod::matching);
    const StructureResult seed_search = analyse_structure(g.model, SearchMethod::seed_search);
    const std::string what = "seed " + std::to_string(seed);
    ASSERT_TRUE(fast.complete()) << what;
    expect_same(fast, seed_search, what);
    // The groups found are exactly the groups the generator attached (in some valid order).
    std::vector<std::vector<int>> found;
    for (const auto& group : fast.groups) found.push_back(group.bodies);
    auto expected = g.groups;
    std::sort(found.begin(), found.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(found, expected) << what;
  }
}

TEST(CrossCheck, RandomMatricesAgreeWhereWellConstrained) {
  std::mt19937 rng(2024);
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 6);
    std::vector<std::vector<int>> m(n, std::vector<int>(n, 0));
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (rng() % 3 == 0) m[i][j] = m[j][i] = 1 + static_cast<int>(rng() % 5);
    const StructureModel model = model_from_adjacency(m);
    const StructureResult fast = analyse_structure(model, SearchMethod::matching);
    if (!fast.complete()) continue;
    ++compared;
    expect_same(fast, analyse_structure(model, SearchMethod::seed_search), "trial " + std::to_string(trial));
  }
  EXPECT_GT(compared, 50);  // enough well-constrained samples to mean something
}

TEST(CrossCheck, EveryBodyOfAGeneratedChainIsPlacedOnce) {
  const GeneratedMechanism g = generate_group_chain(2000, 7);
  const StructureResult d = analyse_structure(g.model);
  ASSERT_TRUE(d.complete());
  int total = 0;
  for (const auto& group : d.groups) total += group.Nm;
  EXPECT_EQ(total, 1999);
  EXPECT_EQ(d.groups.size(), g.groups.size());
  // Stages respect the order: a group comes after everything it receives DOF from.
  for (const auto& group : d.groups)
    for (int before : group.after) EXPECT_LT(before, group.number);
}

}  // namespace
}  // namespace kinestat::structure

namespace kinestat::structure {
namespace {

TEST(CrossCheck, LargeSingleGroupsAreOneGroup) {
  // Ring and ladder families: one crank, then one Assur group of all the other bodies.
  for (const auto& g : {generate_ring_group(8), generate_ladder_group(4)}) {
    for (const auto method : {SearchMethod::matching, SearchMethod::seed_search}) {
      const StructureResult d = analyse_structure(g.model, method);
      ASSERT_TRUE(d.complete()) << g.model.name;
      ASSERT_EQ(d.groups.size(), 2u) << g.model.name;
      EXPECT_EQ(d.groups[0].bodies, g.groups[0]);
      EXPECT_EQ(d.groups[1].bodies, g.groups[1]);
    }
  }
  const StructureResult big = analyse_structure(generate_ring_group(5000).model);
  EXPECT_EQ(big.groups.size(), 2u);
  EXPECT_EQ(big.groups[1].Nm, 5000);
}

}  // namespace
}  // namespace kinestat::structure

namespace kinestat::structure {
namespace {

TEST(CrossCheck, Eq1AloneAcceptsAChainThatStillMoves) {
  // Body 6 is driven from the frame. Body 3 has a higher pair with two inputs to the frame
  // (3 constraints) and a cam with 6 (1 more): 4 constraints on 3 freedoms, over-constrained.
  // Body 4 hangs on 3 by a revolute and can still turn. The chain {3, 4} satisfies Eq. 1 by
  // count (S_c 5 - n_c 2 = 3 (3 - 2)), so the seed's search takes it as a group; it is not
  // one. The matching method reports 3 as over-constrained and 2, 4, 5 as under-constrained.
  const StructureModel model = model_from_adjacency({{0, 0, 5, 0, 0, 3},
                                                     {0, 0, 0, 0, 0, 1},
                                                     {5, 0, 0, 1, 0, 2},
                                                     {0, 0, 1, 0, 2, 0},
                                                     {0, 0, 0, 2, 0, 0},
                                                     {3, 1, 2, 0, 0, 0}});
  const StructureResult fast = analyse_structure(model);
  ASSERT_EQ(fast.groups.size(), 1u);
  EXPECT_EQ(fast.groups[0].bodies, std::vector<int>{5});
  EXPECT_EQ(fast.undecomposed.over_constrained, std::vector<int>{2});
  EXPECT_EQ(fast.undecomposed.under_constrained, (std::vector<int>{1, 3, 4}));
  const StructureResult seed = analyse_structure(model, SearchMethod::seed_search);
  ASSERT_GE(seed.groups.size(), 2u);
  EXPECT_EQ(seed.groups[1].bodies, (std::vector<int>{2, 3}));
}

}  // namespace
}  // namespace kinestat::structure
