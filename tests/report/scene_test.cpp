// The scene carries the model and result data the pictures show.

#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
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

TEST(Scene, FixedFormatting) {
  EXPECT_EQ(report::fixed(1.0), "1");
  EXPECT_EQ(report::fixed(-0.0001), "0");
  EXPECT_EQ(report::fixed(0.28867513, 4), "0.2887");
  EXPECT_EQ(report::fixed(12.5, 2), "12.5");
  EXPECT_EQ(report::fixed(std::nan(""), 2), "0");
}

}  // namespace
