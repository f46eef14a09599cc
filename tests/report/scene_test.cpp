// SPDX-License-Identifier: BSD-3-Clause
// The scene carries the model and result data the pictures show.

#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/report/scene.hpp"
#include "support/cli_run.hpp"

namespace {

using kinestat::testing::example_path;
namespace report = kinestat::report;

report::Scene example_scene(const std::string& example) {
  const auto file = kinestat::io::YamlFile::load(example_path(example));
  const auto model = kinestat::io::read_framework_model(file);
  return report::framework_scene(model, kinestat::framework::analyse_framework(model));
}

TEST(Scene, Truss12HasTwelveBarsOneModeAndOneSelfStressOfBothSigns) {
  const auto scene = example_scene("truss-12.yaml");
  ASSERT_EQ(scene.elements.size(), 12u);
  ASSERT_EQ(scene.modes.size(), 1u);
  ASSERT_EQ(scene.stresses.size(), 1u);
  int tension = 0, compression = 0;
  for (double v : scene.stresses[0].value) {
    EXPECT_NEAR(std::abs(v), std::sqrt(3.0) / 6, 1e-9);
    (v > 0 ? tension : compression)++;
  }
  EXPECT_EQ(tension, 6);
  EXPECT_EQ(compression, 6);
  // Supports A-D do not move; the top square E-H does, in the z = 1 plane.
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(scene.nodes[i].fixed);
    EXPECT_EQ(scene.modes[0].velocity[i].norm(), 0.0);
  }
  for (std::size_t i = 4; i < 8; ++i) {
    EXPECT_GT(scene.modes[0].velocity[i].norm(), 0.1);
    EXPECT_NEAR(scene.modes[0].velocity[i].z(), 0.0, 1e-9);
  }
}

TEST(Scene, FourBarModeMovesOnlyTheFreeJointsPerpendicularToTheirCranks) {
  const auto scene = example_scene("four-bar-linkage.yaml");
  ASSERT_EQ(scene.modes.size(), 1u);
  const auto& v = scene.modes[0].velocity;
  EXPECT_EQ(v[0].norm(), 0.0);  // A
  EXPECT_EQ(v[1].norm(), 0.0);  // B
  // D moves perpendicular to A-D (vertical bar): horizontally; likewise C.
  EXPECT_NEAR(v[3].y(), 0.0, 1e-9);
  EXPECT_NEAR(v[2].y(), 0.0, 1e-9);
  EXPECT_GT(std::abs(v[3].x()), 0.0);
  EXPECT_EQ(scene.dimension, 2);
}

TEST(Scene, DaviesNetworkHasGraphCircuitsCutsetsGlyphsAndModes) {
  const auto file = kinestat::io::YamlFile::load(example_path("davies-2-circuit.yaml"));
  const auto loaded = kinestat::io::read_network_model(file);
  const auto result = kinestat::network::analyse_network(loaded.model);
  const auto scene = report::network_scene(loaded.model, result);
  EXPECT_EQ(scene.bodies.size(), 4u);
  ASSERT_EQ(scene.edges.size(), 5u);
  EXPECT_EQ(scene.B.rows(), 2);
  EXPECT_EQ(scene.Q.rows(), 3);
  EXPECT_FALSE(scene.edges[1].branch);  // B is a chord
  EXPECT_FALSE(scene.edges[4].branch);  // E is a chord
  EXPECT_TRUE(scene.edges[0].branch);
  ASSERT_EQ(scene.glyphs.size(), 5u);
  EXPECT_EQ(scene.glyphs[0].type, "spherical");
  EXPECT_EQ(scene.glyphs[0].f, 3);
  EXPECT_EQ(scene.glyphs[0].c, 3);
  EXPECT_EQ(scene.modes.size(), 3u);  // FN = 3
  // Ground nodes never move.
  for (const auto& mode : scene.modes) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
      if (scene.nodes[i].body == scene.ground) {
        EXPECT_EQ(mode.velocity[i].norm(), 0.0);
      }
    }
  }
  // Mode vc: body 2 (cylindrical D along y from the ground) translates along y.
  const auto& vc = scene.modes[2];
  EXPECT_NEAR(vc.velocity[1].y(), 1.0, 1e-12);
  EXPECT_FALSE(scene.pairs.empty());
}

// k parallel links L_i, each hinged to the ground at (i + 0.5, 0) and to the top bar at
// (i + 0.5, 10), moved far from the origin and given in a small length unit (the picture must not
// depend on either): a parallelogram mechanism. By hand: FN = 1 (the top translates along x, every
// link turns about its ground hinge), CN = 2k − 3(k + 1) + FN = k − 2 (FN − CN = 3(n − 1) − 2e);
// each self-stress is carried by the links alone, as vertical forces f_i that hold the top in
// equilibrium: Σ f_i = 0 and Σ x_i f_i = 0.
TEST(Scene, SparseNetworkParallelLinksTranslateTheTopAndStressesBalanceIt) {
  namespace network = kinestat::network;
  constexpr int k = 160;  // 320 couplings: above network::kDenseNetworkLimit
  static_assert(2 * k > network::kDenseNetworkLimit);
  const double shift = 1000.0, unit = 1.0 / 1024;  // exact in binary
  network::Model model;
  model.name = "parallel links";
  model.space = kinestat::screw::ScrewSpace::planar();
  model.bodies = {"ground", "top"};
  model.ground = 0;
  const auto x_of = [&](int i) { return (shift + i + 0.5) * unit; };
  for (int i = 0; i < k; ++i) {
    model.bodies.push_back("L" + std::to_string(i));
    const int link = static_cast<int>(model.bodies.size()) - 1;
    for (int end = 0; end < 2; ++end) {
      network::Coupling c;
      c.name = (end == 0 ? "A" : "B") + std::to_string(i);
      c.type = kinestat::screw::CouplingType::revolute;
      c.from = end == 0 ? 0 : link;
      c.to = end == 0 ? link : 1;
      c.geometry.point = {kinestat::screw::Rational(x_of(i)), kinestat::screw::Rational((shift + 10.0 * end) * unit), 0};
      model.couplings.push_back(c);
    }
  }
  const auto result = network::analyse_network_sparse(model, {}, 8);
  ASSERT_EQ(result.FN, 1);
  ASSERT_EQ(result.CN, k - 2);
  const auto scene = report::sparse_network_scene(model, result);
  EXPECT_TRUE(scene.sparse);
  EXPECT_EQ(scene.mode_total, 1u);
  EXPECT_EQ(scene.stress_total, static_cast<std::size_t>(k - 2));
  ASSERT_EQ(scene.modes.size(), 1u);
  ASSERT_EQ(scene.stresses.size(), 8u);
  EXPECT_TRUE(scene.B.size() == 0 && scene.Q.size() == 0);
  // Tree from the ground (breadth first): of the k links' 2k hinges, k + 1 are branches.
  int branches = 0;
  for (const auto& edge : scene.edges) branches += edge.branch ? 1 : 0;
  EXPECT_EQ(branches, k + 1);
  for (const auto& glyph : scene.glyphs) {
    EXPECT_EQ(glyph.f, 1);
    EXPECT_EQ(glyph.c, 2);
  }

  // The mode: ground nodes at rest, every top node with one velocity along x, every link's
  // ground hinge at rest and its top hinge moving with the top.
  const auto& velocity = scene.modes[0].velocity;
  const Eigen::Vector3d top = velocity[1];
  ASSERT_GT(top.norm(), 0.0);
  EXPECT_NEAR(top.y() / top.norm(), 0.0, 1e-9);
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    const auto& node = scene.nodes[i];
    if (node.body == 0) {
      EXPECT_EQ(velocity[i].norm(), 0.0) << node.name;
    }
    if (node.body == 1) {
      EXPECT_NEAR((velocity[i] - top).norm() / top.norm(), 0.0, 1e-9) << node.name;
    }
    if (node.body >= 2 && node.name[0] == 'A') {
      EXPECT_NEAR(velocity[i].norm() / top.norm(), 0.0, 1e-9) << node.name;
    }
    if (node.body >= 2 && node.name[0] == 'B') {
      EXPECT_NEAR((velocity[i] - top).norm() / top.norm(), 0.0, 1e-9) << node.name;
    }
  }
  EXPECT_EQ(scene.modes[0].moving.size(), static_cast<std::size_t>(2 * k));  // every hinge turns

  // Each self-stress: forces on vertical lines through the links; the top in equilibrium.
  for (const auto& stress : scene.stresses) {
    ASSERT_FALSE(stress.wrenches.empty());
    double force = 0.0, moment = 0.0, largest = 0.0;
    for (const auto& w : stress.wrenches) {
      ASSERT_FALSE(w.pure) << w.name;
      EXPECT_NEAR(std::abs(w.direction.y()), 1.0, 1e-9) << w.name;
      const int i = std::stoi(w.name.substr(1));
      EXPECT_NEAR(w.point.x(), x_of(i), 1e-9 * x_of(i)) << w.name;
      largest = std::max(largest, w.magnitude);
      if (w.name[0] != 'B') continue;
      const double f = w.magnitude * w.direction.y();
      force += f;
      moment += f * x_of(i);
    }
    EXPECT_NEAR(force / largest, 0.0, 1e-9) << stress.label;
    EXPECT_NEAR(moment / (largest * x_of(k)), 0.0, 1e-9) << stress.label;
  }
}

TEST(Scene, FixedFormatting) {
  EXPECT_EQ(report::fixed(1.0), "1");
  EXPECT_EQ(report::fixed(-0.0001), "0");
  EXPECT_EQ(report::fixed(0.28867513, 4), "0.2887");
  EXPECT_EQ(report::fixed(12.5, 2), "12.5");
  EXPECT_EQ(report::fixed(std::nan(""), 2), "0");
}

}  // namespace
