// SPDX-License-Identifier: BSD-3-Clause
// The single-rank count of FN and CN used to screen design changes. Expected values are hand
// derived from the geometry (Grubler-Kutzbach where it holds, the parallel-axis argument where
// it does not); the every-example case checks the count against the full analysis.
#include <gtest/gtest.h>

#include <filesystem>

#include "kinestat/io/model_file.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/mobility_count.hpp"

namespace kinestat::network {
namespace {

using screw::CouplingType;
using screw::Rational;
using screw::Vec3;

struct Built {
  std::vector<graph::Edge> edges;
  std::vector<screw::CouplingBasis> bases;
  std::vector<const screw::CouplingBasis*> pointers() const {
    std::vector<const screw::CouplingBasis*> p;
    for (const auto& b : bases) p.push_back(&b);
    return p;
  }
};

// Revolutes with axis `axis` through `points`, joining body i to body i + 1 (mod n): a ring.
Built revolute_ring(const std::vector<Vec3>& points, const Vec3& axis, const screw::ScrewSpace& space) {
  Built b;
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    screw::CouplingGeometry g;
    g.point = points[static_cast<std::size_t>(i)];
    g.axis = axis;
    b.edges.push_back({i, (i + 1) % n});
    b.bases.push_back(screw::coupling_basis(CouplingType::revolute, g, space));
  }
  return b;
}

const std::vector<Vec3> kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(MobilityCount, PlanarFourBarHasOneFreedomAndNoRedundancy) {
  // Grubler: 3 (4 - 1) - 2 * 4 = 1; one circuit, d l = 3 equations of rank 3.
  const auto b = revolute_ring(kSquare, {0, 0, 1}, screw::ScrewSpace::planar());
  for (bool exact : {true, false}) {
    const MobilityCount c = count_mobility(4, b.edges, b.pointers(), 3, exact, {});
    EXPECT_EQ(c.F, 4);
    EXPECT_EQ(c.l, 1);
    EXPECT_EQ(c.m, 3);
    EXPECT_EQ(c.FN, 1);
    EXPECT_EQ(c.CN, 0);
  }
}

TEST(MobilityCount, SpatialFourBarWithParallelAxesIsThreeTimesOverconstrained) {
  // Parallel revolute axes span only the planar motions (rotation about z, translation in x, y):
  // rank 3 of 6 circuit equations, so FN = 4 - 3 = 1 and CN = 6 - 3 = 3 (Kutzbach says -2).
  const auto b = revolute_ring(kSquare, {0, 0, 1}, screw::ScrewSpace::spatial());
  for (bool exact : {true, false}) {
    const MobilityCount c = count_mobility(4, b.edges, b.pointers(), 6, exact, {});
    EXPECT_EQ(c.FN, 1);
    EXPECT_EQ(c.CN, 3);
  }
}

TEST(MobilityCount, TwoCoaxialRevolutesBetweenTwoBodies) {
  // Both allow the same rotation: one freedom, five redundant constraints of one circuit.
  const auto b = revolute_ring({{0, 0, 0}, {0, 0, 2}}, {0, 0, 1}, screw::ScrewSpace::spatial());
  const MobilityCount c = count_mobility(2, b.edges, b.pointers(), 6, true, {});
  EXPECT_EQ(c.l, 1);
  EXPECT_EQ(c.FN, 1);
  EXPECT_EQ(c.CN, 5);
}

TEST(MobilityCount, FarFromTheOriginInTheAnalysisFrameIsTheSameCount) {
  // The parallel-axis four-bar placed 10^7 units away: in the analysis frame the numerical rank
  // is that of the exact one (3), as the placement must not change the answer.
  Model model;
  model.bodies = {"0", "1", "2", "3"};
  const Rational far(10'000'000);
  for (int i = 0; i < 4; ++i) {
    Coupling c;
    c.name = "R" + std::to_string(i);
    c.type = CouplingType::revolute;
    c.from = i;
    c.to = (i + 1) % 4;
    c.geometry.point = {kSquare[static_cast<std::size_t>(i)][0] + far, kSquare[static_cast<std::size_t>(i)][1] - far, far};
    c.geometry.axis = Vec3{0, 0, 1};
    model.couplings.push_back(c);
  }
  const AnalysisFrame frame = AnalysisFrame::of(model);
  Built b;
  for (const auto& c : model.couplings) {
    b.edges.push_back({c.from, c.to});
    b.bases.push_back(screw::coupling_basis(c.type, frame.to_frame(c.geometry, model.space), model.space));
  }
  const MobilityCount c = count_mobility(4, b.edges, b.pointers(), 6, false, {});
  EXPECT_EQ(c.FN, 1);
  EXPECT_EQ(c.CN, 3);
}

TEST(MobilityCount, DisconnectedBodiesAreRefused) {
  auto b = revolute_ring(kSquare, {0, 0, 1}, screw::ScrewSpace::spatial());
  EXPECT_THROW(count_mobility(5, b.edges, b.pointers(), 6, true, {}), graph::TreeError);
}

TEST(MobilityCount, AgreesWithTheFullAnalysisOnEveryNetworkExample) {
  int networks = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const io::ModelFile file = io::read_model_file(entry.path().string());
    if (!file.network) continue;
    const Model& model = file.network->model;
    const NetworkResult full = analyse_network(model);
    Built b;
    for (const auto& c : model.couplings) {
      b.edges.push_back({c.from, c.to});
      b.bases.push_back(screw::coupling_basis(c.type, c.geometry, model.space));
    }
    const MobilityCount c = count_mobility(static_cast<int>(model.bodies.size()), b.edges, b.pointers(), full.d, true, {});
    EXPECT_EQ(c.FN, full.FN) << entry.path();
    EXPECT_EQ(c.CN, full.CN) << entry.path();
    ++networks;
  }
  EXPECT_GE(networks, 10);
}

}  // namespace
}  // namespace kinestat::network
