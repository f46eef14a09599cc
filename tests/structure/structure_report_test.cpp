// SPDX-License-Identifier: BSD-3-Clause
// Reports of the structural analysis: JSON keys and values, determinism, DOT and SVG.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "kinestat/report/structure_report.hpp"
#include "kinestat/structure/structural_diagram.hpp"
#include "test_support.hpp"

namespace kinestat::report {
namespace {

TEST(StructureReport, GroupNamesAreRomanLikeTheSeed) {
  EXPECT_EQ(group_name(1), "SG-I");
  EXPECT_EQ(group_name(4), "SG-IV");
  EXPECT_EQ(group_name(14), "SG-XIV");
}

TEST(StructureReport, JsonCarriesGroupsOrderMatrixAndTransformations) {
  const auto model = structure::testing::load_example("saura-eq2.yaml");
  const auto d = structure::analyse_structure(model);
  const auto t = structure::structural_transformations(model);
  const std::string text = structure_report_json({model, d, &t});
  EXPECT_EQ(text, structure_report_json({model, d, &t}));  // deterministic
  const auto j = nlohmann::json::parse(text);
  ASSERT_EQ(j["groups"].size(), 3u);
  EXPECT_EQ(j["groups"][0]["bodies"], nlohmann::json({2, 3}));
  EXPECT_EQ(j["groups"][0]["Nm"], 2);
  EXPECT_EQ(j["groups"][0]["nc"], 1);
  EXPECT_EQ(j["groups"][0]["P"], 3);
  EXPECT_EQ(j["groups"][0]["Sc"], 4);  // lower (1 3) + lower (2 3) + higher (1 2)
  EXPECT_EQ(j["order"], nlohmann::json({{2, 3}, {4}, {5}}));
  EXPECT_EQ(j["result_matrix"][3], nlohmann::json({1, 0, 2, 0, 0}));
  EXPECT_EQ(j["transformations"]["placements"], 17);
  EXPECT_EQ(j["transformations"]["ranked"].size(), 5u);
  EXPECT_TRUE(j["undecomposed"].is_null());
  EXPECT_TRUE(j["complete"].get<bool>());
}

TEST(StructureReport, DiagramOfTheFourBar) {
  // Fig. 2.g: 0 -> (1, 1), 0 -> (2, 0), (1, 1) -> (2, 0).
  const auto model = structure::testing::load_example("saura-four-bar.yaml");
  const auto d = structure::analyse_structure(model);
  const auto diagram = structure::structural_diagram(d);
  ASSERT_EQ(diagram.nodes.size(), 3u);
  EXPECT_EQ(diagram.nodes[1].Nm, 1);
  EXPECT_EQ(diagram.nodes[1].nc, 1);
  EXPECT_EQ(diagram.nodes[2].Nm, 2);
  EXPECT_EQ(diagram.nodes[2].nc, 0);
  ASSERT_EQ(diagram.arrows.size(), 3u);
  const std::string dot = structure_dot(model, d);
  EXPECT_NE(dot.find("g1 [label=\"(1, 1)\""), std::string::npos);
  EXPECT_NE(dot.find("g2 [label=\"(2, 0)\""), std::string::npos);
  EXPECT_NE(dot.find("g0 -> g1;"), std::string::npos);
  EXPECT_NE(dot.find("g0 -> g2;"), std::string::npos);
  EXPECT_NE(dot.find("g1 -> g2;"), std::string::npos);
  const std::string svg = structure_svg(model, d);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  std::size_t circles = 0;
  for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 3u);
  EXPECT_NE(svg.find(">(1, 1)<"), std::string::npos);
  EXPECT_NE(svg.find(">(2, 0)<"), std::string::npos);
}

TEST(StructureReport, TextNamesTheUndecomposedPart) {
  const auto model = structure::testing::load_example("four-bar-over-actuated.yaml");
  const auto d = structure::analyse_structure(model);
  const std::string text = structure_report_text({model, d, nullptr});
  EXPECT_NE(text.find("over-constrained: bodies {3}: 1 constraint(s) or input(s) too many"), std::string::npos) << text;
  EXPECT_NE(text.find("the redundancy can sit on any pair of the over-constrained part, bodies {2, 3, 4}"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace kinestat::report

namespace kinestat::report {
namespace {

TEST(StructureReport, DiagramOfFig4) {
  // Fig. 4.b-c: SG-I {2, 3} (2, 1) hangs on the frame; SG-II {4} (1, 0) on the frame (revolute)
  // and on SG-I (cam with arm 3); SG-III {5} (1, 1) on SG-II only.
  const auto model = structure::testing::load_example("saura-eq2.yaml");
  const auto diagram = structure::structural_diagram(structure::analyse_structure(model));
  ASSERT_EQ(diagram.nodes.size(), 4u);
  EXPECT_EQ(std::make_pair(diagram.nodes[1].Nm, diagram.nodes[1].nc), std::make_pair(2, 1));
  EXPECT_EQ(std::make_pair(diagram.nodes[2].Nm, diagram.nodes[2].nc), std::make_pair(1, 0));
  EXPECT_EQ(std::make_pair(diagram.nodes[3].Nm, diagram.nodes[3].nc), std::make_pair(1, 1));
  std::vector<std::pair<int, int>> arrows;
  for (const auto& a : diagram.arrows) arrows.emplace_back(a.from, a.to);
  EXPECT_EQ(arrows, (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}, {2, 3}}));
  EXPECT_EQ(diagram.layers, 4);  // frame, then one group per stage
}

}  // namespace
}  // namespace kinestat::report
