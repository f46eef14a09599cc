// SPDX-License-Identifier: BSD-3-Clause
// Deriving a structure model from a coupling list (what a coupling-network model provides).
#include <gtest/gtest.h>

#include "kinestat/error.hpp"

#include "kinestat/structure/decomposition.hpp"

namespace kinestat::structure {
namespace {

TEST(CouplingDerivation, CouplingTypesMapToGrades) {
  EXPECT_EQ(pair_kind_of_coupling_type("revolute"), PairKind::lower);
  EXPECT_EQ(pair_kind_of_coupling_type("prismatic"), PairKind::lower);
  EXPECT_EQ(pair_kind_of_coupling_type("spherical"), PairKind::lower);
  EXPECT_EQ(pair_kind_of_coupling_type("cam"), PairKind::higher);
  EXPECT_EQ(pair_kind_of_coupling_type("gear"), PairKind::higher);
  EXPECT_EQ(pair_kind_of_coupling_type("point_on_plane"), PairKind::higher);
  EXPECT_FALSE(pair_kind_of_coupling_type("teleporter").has_value());
}

TEST(CouplingDerivation, FourBarFromCouplingsMatchesFig2) {
  // Couplings in any order and orientation; the frame is body 0.
  const StructureModel model = model_from_couplings(
      {"ground", "crank", "coupler", "rocker"},
      {{1, 0, PairKind::lower, 1, {}}, {2, 1, PairKind::lower, 0, {}}, {3, 2, PairKind::lower, 0, {}}, {0, 3, PairKind::lower, 0, {}}});
  EXPECT_EQ(adjacency_of(model), (std::vector<std::vector<int>>{{0, 3, 0, 1}, {3, 0, 1, 0}, {0, 1, 0, 1}, {1, 0, 1, 0}}));
  const StructureResult d = analyse_structure(model);
  ASSERT_EQ(d.groups.size(), 2u);
  EXPECT_EQ(d.groups[0].bodies, std::vector<int>{1});
  EXPECT_EQ(d.groups[1].bodies, (std::vector<int>{2, 3}));
}

TEST(CouplingDerivation, SpatialFreedomsAndBadCouplings) {
  const StructureModel rsur = model_from_couplings(
      {"0", "1", "2", "3"},
      {{0, 1, PairKind::lower, 1, 1}, {1, 2, PairKind::lower, 0, 3}, {2, 3, PairKind::lower, 0, 2}, {3, 0, PairKind::lower, 0, 1}},
      6);
  EXPECT_EQ(rsur.mobility(), 1);
  EXPECT_TRUE(adjacency_of(rsur).empty());  // spatial: no Table-1 matrix
  EXPECT_TRUE(analyse_structure(rsur).complete());
  EXPECT_THROW(model_from_couplings({"0", "1"}, {{0, 2, PairKind::lower, 0, {}}}), kinestat::Error);
  EXPECT_THROW(model_from_couplings({"0", "1"}, {{1, 1, PairKind::lower, 0, {}}}), kinestat::Error);
  EXPECT_THROW(model_from_couplings({"0", "1"}, {{0, 1, PairKind::lower, 2, {}}}), kinestat::Error);
}

}  // namespace
}  // namespace kinestat::structure
