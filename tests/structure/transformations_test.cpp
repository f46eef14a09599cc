// SPDX-License-Identifier: BSD-3-Clause
// Structural transformations (the seed's AMPLIACION) of the mechanism of Fig. 4.
#include <gtest/gtest.h>

#include <random>

#include "support/mechanism_generator.hpp"
#include "kinestat/structure/transformations.hpp"
#include "test_support.hpp"

namespace kinestat::structure {
namespace {

using testing::numbered_groups;
using Groups = std::vector<std::vector<int>>;

// Inputs of a ranked placement as (body, body, count) with 1-based bodies.
std::vector<std::array<int, 3>> placement(const StructureModel& model, const Transformation& t) {
  std::vector<std::array<int, 3>> out;
  for (std::size_t k = 0; k < t.inputs.size(); ++k)
    if (t.inputs[k] > 0) out.push_back({model.pairs[k].a + 1, model.pairs[k].b + 1, t.inputs[k]});
  return out;
}

TEST(Transformations, Fig4PlacementsAreCountedAndRanked) {
  const StructureModel model = testing::load_example("saura-eq2.yaml");
  const TransformationSet set = structural_transformations(model);
  ASSERT_TRUE(set.enumerated);
  // Two inputs on six pairs, a higher pair holding up to two: C(6,2) + 2 = 17 placements.
  EXPECT_EQ(set.placements, 17u);
  // Body 5 hangs on the lower pair (4 5) alone, so that pair must carry one input; the other
  // goes on any of the five pairs of the loop {1..4}: five decomposable placements.
  ASSERT_EQ(set.ranked.size(), 5u);
  EXPECT_EQ(set.not_decomposable, 12u);
  // The seed: Result(2) (q1 on (1 3)) and Result(3) (q1 on (1 4)) have more, hence simpler,
  // groups than the given placement, and are equal to each other ("no improvement").
  using P = std::vector<std::array<int, 3>>;
  const P eq3{{1, 3, 1}, {4, 5, 1}}, eq4{{1, 4, 1}, {4, 5, 1}}, given{{1, 2, 1}, {4, 5, 1}};
  const std::vector<P> best_two = {placement(model, set.ranked[0]), placement(model, set.ranked[1])};
  EXPECT_TRUE((best_two == std::vector<P>{eq3, eq4}) || (best_two == std::vector<P>{eq4, eq3}));
  EXPECT_EQ(set.ranked[0].decomposition.groups.size(), 4u);
  EXPECT_EQ(set.ranked[1].decomposition.groups.size(), 4u);
  for (const auto& t : set.ranked) {
    if (placement(model, t) == eq3) {
      EXPECT_EQ(numbered_groups(t.decomposition), (Groups{{3}, {4}, {5}, {2}}));
      EXPECT_EQ(adjacency_of(with_inputs(model, t.inputs)),
                (std::vector<std::vector<int>>{{0, 2, 3, 1, 0}, {2, 0, 1, 0, 0}, {3, 1, 0, 2, 0}, {1, 0, 2, 0, 3}, {0, 0, 0, 3, 0}}));
    }
    if (placement(model, t) == eq4) {
      EXPECT_EQ(numbered_groups(t.decomposition), (Groups{{4}, {5}, {3}, {2}}));
    }
    if (placement(model, t) == given) EXPECT_TRUE(t.original);
    else EXPECT_FALSE(t.original);
  }
  // Ranking: never fewer groups further up.
  for (std::size_t i = 1; i < set.ranked.size(); ++i)
    EXPECT_GE(set.ranked[i - 1].decomposition.groups.size(), set.ranked[i].decomposition.groups.size());
}

TEST(Transformations, FourBarInputOnTheCouplerMakesOneGroup) {
  // Driving the four-bar at a floating pair leaves a single group of all three moving links.
  const StructureModel model = testing::load_example("saura-four-bar.yaml");
  const TransformationSet set = structural_transformations(model);
  ASSERT_EQ(set.ranked.size(), 4u);  // one input on any of the four revolutes
  EXPECT_EQ(set.ranked.front().decomposition.groups.size(), 2u);
  EXPECT_EQ(set.ranked.back().decomposition.groups.size(), 1u);
  EXPECT_EQ(set.ranked.back().largest_group, 3);
}

TEST(Transformations, LimitSkipsHugeEnumerations) {
  const StructureModel model = testing::load_example("saura-eq2.yaml");
  const TransformationSet set = structural_transformations(model, 10);
  EXPECT_FALSE(set.enumerated);
  EXPECT_TRUE(set.ranked.empty());
  EXPECT_GT(set.placements, 10u);
}

TEST(Transformations, PlacementCountsByBruteForce) {
  // Counts against enumerating every vector of per-pair inputs: random capacities 0..3 on up to
  // 7 pairs, 0..8 inputs, caps that do and do not bind.
  std::mt19937 rng(17);
  for (int trial = 0; trial < 500; ++trial) {
    const int pairs = 1 + static_cast<int>(rng() % 7), total = static_cast<int>(rng() % 9);
    std::vector<int> capacity;
    for (int k = 0; k < pairs; ++k) capacity.push_back(static_cast<int>(rng() % 4));
    std::uint64_t brute = 0;
    std::vector<int> x(static_cast<std::size_t>(pairs), 0);
    while (true) {
      int sum = 0;
      for (int v : x) sum += v;
      if (sum == total) ++brute;
      std::size_t k = 0;
      while (k < x.size() && x[k] == capacity[k]) x[k++] = 0;
      if (k == x.size()) break;
      ++x[k];
    }
    const std::uint64_t cap = 1 + rng() % 40;
    EXPECT_EQ(count_placements(capacity, total, cap), std::min(brute, cap)) << "trial " << trial;
  }
}

TEST(Transformations, HugeMechanismStopsCountingAtTheLimit) {
  // 100,000 bodies: far more than 1,000 placements, known after looking at a few pairs.
  const GeneratedMechanism generated = generate_group_chain(100000, 5);
  const TransformationSet set = structural_transformations(generated.model, 1000);
  EXPECT_FALSE(set.enumerated);
  EXPECT_EQ(set.placements, 1001u);
}

}  // namespace
}  // namespace kinestat::structure
