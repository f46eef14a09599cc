// SPDX-License-Identifier: BSD-3-Clause
// The examples of seed 004 (Saura, Celdrán, Dopico, Cuadrado): the four-bar of Fig. 2 and
// the mechanism of Fig. 4 with the adjacency matrices and result matrices of Eqs. 2-4.
#include <gtest/gtest.h>

#include "kinestat/structure/decomposition.hpp"

namespace kinestat::structure {
namespace {

using Matrix = std::vector<std::vector<int>>;

std::vector<std::vector<int>> group_bodies(const StructureResult& d) {
  std::vector<std::vector<int>> out;
  for (const auto& g : d.groups) {
    std::vector<int> one;
    for (int b : g.bodies) one.push_back(b + 1);  // the paper numbers bodies from 1
    out.push_back(one);
  }
  return out;
}

// Fig. 2: four-bar, input q1 on the lower pair (1 2); pairs (2 3), (3 4), (1 4).
const Matrix kFourBar = {{0, 3, 0, 1}, {3, 0, 1, 0}, {0, 1, 0, 1}, {1, 0, 1, 0}};

// Eq. 2, Result(1).M: inputs on the gear pair (1 2) and on the lower pair (4 5).
const Matrix kEq2 = {{0, 4, 1, 1, 0}, {4, 0, 1, 0, 0}, {1, 1, 0, 2, 0}, {1, 0, 2, 0, 3}, {0, 0, 0, 3, 0}};
// Eq. 3, Result(2).M: q1 moved to the lower pair (1 3).
const Matrix kEq3 = {{0, 2, 3, 1, 0}, {2, 0, 1, 0, 0}, {3, 1, 0, 2, 0}, {1, 0, 2, 0, 3}, {0, 0, 0, 3, 0}};
// Eq. 4, Result(3).M: q1 moved to the lower pair (1 4).
const Matrix kEq4 = {{0, 2, 1, 3, 0}, {2, 0, 1, 0, 0}, {1, 1, 0, 2, 0}, {3, 0, 2, 0, 3}, {0, 0, 0, 3, 0}};

class BothMethods : public ::testing::TestWithParam<SearchMethod> {};

TEST_P(BothMethods, FourBarOfFig2) {
  const StructureResult d = analyse_structure(model_from_adjacency(kFourBar), GetParam());
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(group_bodies(d), (std::vector<std::vector<int>>{{2}, {3, 4}}));
  // Section 2, step 2: SG-I has P = 1, S_c = 1, n_c = 1, N_m = 1.
  EXPECT_EQ(d.groups[0].P, 1);
  EXPECT_EQ(d.groups[0].Sc, 1);
  EXPECT_EQ(d.groups[0].nc, 1);
  EXPECT_EQ(d.groups[0].Nm, 1);
  // Step 4: the chain 3-4 has S_c = 3, n_c = 0, N_m = 2, P = 3.
  EXPECT_EQ(d.groups[1].P, 3);
  EXPECT_EQ(d.groups[1].Sc, 3);
  EXPECT_EQ(d.groups[1].nc, 0);
  EXPECT_EQ(d.groups[1].Nm, 2);
  // Fig. 2.g: the frame feeds both groups, SG-I feeds SG-II.
  EXPECT_EQ(d.groups[1].after, (std::vector<int>{0, 1}));
}

TEST_P(BothMethods, Eq2ResultMatrix) {
  const StructureResult d = analyse_structure(model_from_adjacency(kEq2), GetParam());
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(group_bodies(d), (std::vector<std::vector<int>>{{2, 3}, {4}, {5}}));
  const Matrix printed = {{0, 1, 1, 2, 3}, {1, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, {1, 0, 2, 0, 0}, {0, 0, 0, 2, 0}};
  EXPECT_EQ(d.result_matrix(), printed);
}

TEST_P(BothMethods, Eq3ResultMatrix) {
  const StructureResult d = analyse_structure(model_from_adjacency(kEq3), GetParam());
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(group_bodies(d), (std::vector<std::vector<int>>{{3}, {4}, {5}, {2}}));
  // As printed, except element (3,3): the paper prints 2 there, but a body never assigns
  // DOF to itself (body 3 is a group of its own, like body 4 in Eq. 4 whose (4,4) is 0),
  // and rows 2 and 4 already record that body 3 gave its DOF to bodies 2 and 4.
  const Matrix printed = {{0, 4, 1, 2, 3}, {1, 0, 2, 0, 0}, {1, 0, 0, 0, 0}, {1, 0, 2, 0, 0}, {0, 0, 0, 3, 0}};
  EXPECT_EQ(d.result_matrix(), printed);
}

TEST_P(BothMethods, Eq4ResultMatrix) {
  const StructureResult d = analyse_structure(model_from_adjacency(kEq4), GetParam());
  ASSERT_TRUE(d.complete());
  EXPECT_EQ(group_bodies(d), (std::vector<std::vector<int>>{{4}, {5}, {3}, {2}}));
  const Matrix printed = {{0, 4, 3, 1, 2}, {1, 0, 3, 0, 0}, {1, 0, 0, 2, 0}, {1, 0, 0, 0, 0}, {0, 0, 0, 2, 0}};
  EXPECT_EQ(d.result_matrix(), printed);
}

std::string method_name(const ::testing::TestParamInfo<SearchMethod>& param) {
  return param.param == SearchMethod::matching ? "Matching" : "SeedSearch";
}

INSTANTIATE_TEST_SUITE_P(Structure, BothMethods, ::testing::Values(SearchMethod::matching, SearchMethod::seed_search),
                         method_name);

}  // namespace
}  // namespace kinestat::structure
