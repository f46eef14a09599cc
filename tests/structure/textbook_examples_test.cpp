// SPDX-License-Identifier: BSD-3-Clause
// Classic decompositions from textbooks, loaded from the shipped examples, and the seed's
// examples as files. The expected groups are the published ones cited in each example file.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace kinestat::structure {
namespace {

using testing::load_example;
using testing::numbered_groups;
using Groups = std::vector<std::vector<int>>;

// Every group must satisfy Eq. 1 with the seed's counting: S_c - n_c = d (P - N_m).
void expect_eq1(const StructureModel& model, const StructureResult& d) {
  for (const auto& g : d.groups) EXPECT_EQ(g.Sc - g.nc, model.dimension * (g.P - g.Nm)) << "group " << g.number;
}

TEST(TextbookExamples, StephensonSixBarIsCrankAndTwoDyads) {
  // Norton, Design of Machinery, sect. 2.10: a Stephenson six-bar is a four-bar with a dyad
  // added; solved as the driver, the four-bar's RRR dyad, then the added RRR dyad.
  const StructureModel model = load_example("stephenson-six-bar.yaml");
  const StructureResult d = analyse_structure(model);
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(numbered_groups(d), (Groups{{2}, {3, 4}, {5, 6}}));
  EXPECT_EQ(d.groups[2].after, (std::vector<int>{0, 2}));  // the second dyad hangs on the coupler and the frame
  expect_eq1(model, d);
}

TEST(TextbookExamples, WattSixBarIsCrankAndTwoDyads) {
  const StructureModel model = load_example("watt-six-bar.yaml");
  const StructureResult d = analyse_structure(model);
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(numbered_groups(d), (Groups{{2}, {3, 4}, {5, 6}}));
  for (const auto& g : d.groups) EXPECT_EQ(g.stage, g.number);  // a pure chain: no two groups in parallel
  expect_eq1(model, d);
}

TEST(TextbookExamples, SliderCrankIsCrankAndRRPDyad) {
  // Artobolevsky ch. 2; Uicker, Pennock & Shigley ch. 1: driver + dyad of the second kind.
  const StructureModel model = load_example("slider-crank.yaml");
  const StructureResult d = analyse_structure(model);
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(numbered_groups(d), (Groups{{2}, {3, 4}}));
  EXPECT_EQ(d.groups[1].P, 3);   // crank-rod revolute, rod-slider revolute, slider-frame prismatic
  EXPECT_EQ(d.groups[1].Sc, 3);
  expect_eq1(model, d);
}

TEST(TextbookExamples, ClassIIITriadIsOneGroupOfFourBodies) {
  // Mitsi et al. 2003; Artobolevsky: a ternary link with three binary links and six
  // revolutes, 3 * 4 = 2 * 6, is one class-III group: no dyad can be split off.
  const StructureModel model = load_example("class-iii-triad.yaml");
  for (const auto method : {SearchMethod::matching, SearchMethod::seed_search}) {
    const StructureResult d = analyse_structure(model, method);
    ASSERT_TRUE(d.complete());
    EXPECT_EQ(numbered_groups(d), (Groups{{2}, {3, 4, 5, 6}}));
    EXPECT_EQ(d.groups[1].P, 6);
    EXPECT_EQ(d.groups[1].Sc, 6);
    EXPECT_EQ(d.groups[1].Nm, 4);
    expect_eq1(model, d);
  }
}

TEST(TextbookExamples, SeedFilesGiveThePrintedGroups) {
  EXPECT_EQ(numbered_groups(analyse_structure(load_example("saura-four-bar.yaml"))), (Groups{{2}, {3, 4}}));
  EXPECT_EQ(numbered_groups(analyse_structure(load_example("saura-eq2.yaml"))), (Groups{{2, 3}, {4}, {5}}));
  EXPECT_EQ(numbered_groups(analyse_structure(load_example("saura-eq3.yaml"))), (Groups{{3}, {4}, {5}, {2}}));
  EXPECT_EQ(numbered_groups(analyse_structure(load_example("saura-eq4.yaml"))), (Groups{{4}, {5}, {3}, {2}}));
  // Eq. 2: the printed Result(1).Res, through the file reader.
  const std::vector<std::vector<int>> res = {
      {0, 1, 1, 2, 3}, {1, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, {1, 0, 2, 0, 0}, {0, 0, 0, 2, 0}};
  EXPECT_EQ(analyse_structure(load_example("saura-eq2.yaml")).result_matrix(), res);
}

TEST(TextbookExamples, SpatialRSURDecomposesWithSixInEq1) {
  const StructureModel model = load_example("spatial-rsur.yaml");
  EXPECT_EQ(model.dimension, 6);
  EXPECT_EQ(model.mobility(), 1);  // 6 * 3 - (5 + 3 + 4 + 5)
  const StructureResult d = analyse_structure(model);
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(numbered_groups(d), (Groups{{2}, {3, 4}}));
  EXPECT_EQ(d.groups[1].Sc, 6);  // spherical 3 + universal 2 + revolute 1
  EXPECT_EQ(d.groups[1].P, 3);
  expect_eq1(model, d);
  // The same topology with d = 3 would not be a group: the count depends on d.
  EXPECT_NE(d.groups[1].Sc - d.groups[1].nc, 3 * (d.groups[1].P - d.groups[1].Nm));
}

TEST(TextbookExamples, SpatialRSSRReportsTheIdleSpinAsAMissingInput) {
  const StructureModel model = load_example("spatial-rssr.yaml");
  EXPECT_EQ(model.mobility(), 2);  // 18 - 16: the coupler's spin about its own axis
  const StructureResult d = analyse_structure(model);
  EXPECT_FALSE(d.complete());
  EXPECT_EQ(numbered_groups(d), (Groups{{2}}));
  EXPECT_EQ(testing::numbered(d.undecomposed.under_constrained), (std::vector<int>{3, 4}));
  EXPECT_EQ(d.undecomposed.missing, 1);
  EXPECT_TRUE(d.undecomposed.over_constrained.empty());
}

TEST(TextbookExamples, OverActuatedFourBarIsReported) {
  // Both frame pairs driven: crank and rocker are each placed by their own input (Eq. 1 holds
  // for each alone); the coupler then meets two solved bodies, 2 + 2 constraints for 3
  // freedoms: one too many. Both methods agree.
  const StructureModel model = load_example("four-bar-over-actuated.yaml");
  for (const auto method : {SearchMethod::matching, SearchMethod::seed_search}) {
    const StructureResult d = analyse_structure(model, method);
    EXPECT_FALSE(d.complete());
    EXPECT_EQ(numbered_groups(d), (Groups{{4}, {2}}));  // decreasing body number
    EXPECT_EQ(testing::numbered(d.undecomposed.over_constrained), (std::vector<int>{3}));
    EXPECT_EQ(d.undecomposed.redundant, 1);  // two inputs, mobility one
    // 3 + 3 units on the driven frame pairs and 2 + 2 on the coupler's pairs: 10 for 9
    // freedoms, and the one too many can be blamed on any of the four pairs.
    EXPECT_EQ(testing::numbered(d.undecomposed.over_constrained_part), (std::vector<int>{2, 3, 4}));
  }
}

TEST(TextbookExamples, GroupsBehindAPlacedOverConstrainedBodyAreFound) {
  // The over-actuated four-bar with a dyad {5, 6} on the rocker (4) and the frame: the rocker
  // is placed by its input, so the dyad can be solved; only the coupler stays over-constrained.
  const StructureModel model = model_from_adjacency({{0, 3, 0, 3, 0, 1},
                                                     {3, 0, 1, 0, 0, 0},
                                                     {0, 1, 0, 1, 0, 0},
                                                     {3, 0, 1, 0, 1, 0},
                                                     {0, 0, 0, 1, 0, 1},
                                                     {1, 0, 0, 0, 1, 0}});
  for (const auto method : {SearchMethod::matching, SearchMethod::seed_search}) {
    const StructureResult d = analyse_structure(model, method);
    EXPECT_EQ(numbered_groups(d), (Groups{{4}, {2}, {5, 6}}));
    EXPECT_EQ(testing::numbered(d.undecomposed.over_constrained), (std::vector<int>{3}));
    // The dyad takes all the units of its pairs, so the redundancy cannot sit there.
    EXPECT_EQ(testing::numbered(d.undecomposed.over_constrained_part), (std::vector<int>{2, 3, 4}));
    EXPECT_TRUE(d.undecomposed.blocked.empty());
  }
}

TEST(TextbookExamples, FramePairsMayNameTheFrameSecond) {
  // A four-bar whose frame pairs are written (crank, frame) and (rocker, frame): the dyad
  // {coupler, rocker} must still be seen as attached to the frame (found by the property
  // tests: only pairs written (frame, x) counted before).
  StructureModel model;
  model.body_names = {"frame", "crank", "coupler", "rocker"};
  model.pairs = {pair_from_code(1, 0, 3), pair_from_code(1, 2, 1), pair_from_code(2, 3, 1), pair_from_code(3, 0, 1)};
  const StructureResult d = analyse_structure(model);
  EXPECT_TRUE(d.complete());
  EXPECT_EQ(numbered_groups(d), (Groups{{2}, {3, 4}}));
}

TEST(TextbookExamples, UnderActuatedFiveBarKeepsItsDrivenCrank) {
  // Five-bar (mobility 2) with one input: the driven crank is a group; the rest lacks one input.
  const StructureModel model = model_from_adjacency(
      {{0, 3, 0, 0, 1}, {3, 0, 1, 0, 0}, {0, 1, 0, 1, 0}, {0, 0, 1, 0, 1}, {1, 0, 0, 1, 0}});
  const StructureResult d = analyse_structure(model);
  EXPECT_EQ(numbered_groups(d), (Groups{{2}}));
  EXPECT_EQ(testing::numbered(d.undecomposed.under_constrained), (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(d.undecomposed.missing, 1);
}

TEST(TextbookExamples, BodiesBehindAnOverConstrainedPartAreBlocked) {
  // Over-actuated four-bar (bodies 2-4) and a dyad {5, 6} hanging on its coupler and the
  // frame: the coupler cannot be placed, so neither can the dyad.
  StructureModel model = model_from_adjacency({{0, 3, 0, 3, 0, 1},
                                               {3, 0, 1, 0, 0, 0},
                                               {0, 1, 0, 1, 1, 0},
                                               {3, 0, 1, 0, 0, 0},
                                               {0, 0, 1, 0, 0, 1},
                                               {1, 0, 0, 0, 1, 0}});
  const StructureResult d = analyse_structure(model);
  EXPECT_EQ(numbered_groups(d), (Groups{{4}, {2}}));
  EXPECT_EQ(testing::numbered(d.undecomposed.over_constrained), (std::vector<int>{3}));
  EXPECT_EQ(testing::numbered(d.undecomposed.blocked), (std::vector<int>{5, 6}));
}

}  // namespace
}  // namespace kinestat::structure
