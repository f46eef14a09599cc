// SPDX-License-Identifier: BSD-3-Clause
// Every self-stress and mode is visible (issue 10, items 4 and 5): the folded-sheet guide's
// self-stress colours every sheet, Davies' network draws both self-stresses as coupling
// wrenches and its three modes as body twists, and the structural diagram of saura-eq2 routes
// no arrow under a circle it does not end at (checked geometrically on the SVG).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/svg_writer.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "support/cli_run.hpp"

namespace {

namespace report = kinestat::report;
using kinestat::testing::example_path;

report::Scene framework_scene_of(const std::string& example) {
  const auto file = kinestat::io::YamlFile::load(example_path(example));
  const auto model = kinestat::io::read_framework_model(file);
  return report::framework_scene(model, kinestat::framework::analyse_framework(model));
}

report::Scene network_scene_of(const std::string& example) {
  const auto file = kinestat::io::YamlFile::load(example_path(example));
  const auto loaded = kinestat::io::read_network_model(file);
  return report::network_scene(loaded.model, kinestat::network::analyse_network(loaded.model));
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(Pictures, FoldedSheetGuideSelfStressColoursEverySheet) {
  // Seed 002, Fig. 6: one self-stress "with in-plane bending in all sheets" (12 sheet beams).
  const auto scene = framework_scene_of("folded-sheet-guide-6.yaml");
  ASSERT_EQ(scene.stresses.size(), 1u);
  const std::string with = report::mechanism_svg(scene, {0, 1});
  const std::string without = report::mechanism_svg(scene, {0, 0});
  EXPECT_NE(with, without);
  const std::regex coloured(R"re(stroke="(#[0-9a-f]+)"[^>]*data-element="(f[1-6]\.s[12])" data-kind="([a-z]+)")re");
  std::map<std::string, std::string> kind_of;
  for (auto it = std::sregex_iterator(with.begin(), with.end(), coloured); it != std::sregex_iterator(); ++it) {
    EXPECT_NE((*it)[1], "#bbbbbb");
    kind_of[(*it)[2]] = (*it)[3];
  }
  EXPECT_EQ(kind_of.size(), 12u) << "every sheet carries a visible resultant";
  for (const auto& [sheet, kind] : kind_of) EXPECT_EQ(kind, "bending") << sheet;
  EXPECT_NE(with.find("bending purple"), std::string::npos) << "the legend names the kind";
  // The sheets are drawn as sheets: elongation and bending_xz held, torsion and bending_xy
  // released in the model, so each lies in its element's x-z plane (z given as orientation).
  EXPECT_EQ(count(with, "class=\"sheet\""), 12);
  for (const auto& element : scene.elements) {
    ASSERT_TRUE(element.sheet_across.has_value()) << element.name;
    const Eigen::Vector3d along = scene.nodes[static_cast<std::size_t>(element.b)].position - scene.nodes[static_cast<std::size_t>(element.a)].position;
    EXPECT_NEAR(element.sheet_across->dot(along), 0.0, 1e-9 * along.norm());
    EXPECT_NEAR(std::abs(element.sheet_across->z()), 0.0, 1e-9) << "fold lines lie in horizontal planes";
  }
  // Wires are not sheets.
  const std::string wires = report::mechanism_svg(framework_scene_of("wire-flexure-guide.yaml"));
  EXPECT_EQ(count(wires, "class=\"sheet\""), 0);
  // The HTML scene carries the same: a non-zero value on every sheet, the kind, the table.
  const auto json = report::scene_json(scene);
  double smallest = 1e300;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) smallest = std::min(smallest, std::abs(double(json["stresses"][0]["value"][e])));
  EXPECT_GT(smallest, 0.0);
  EXPECT_GE(json["stresses"][0]["resultants"].size(), 12u);
}

TEST(Pictures, DaviesNetworkDrawsBothSelfStressesAndItsThreeModes) {
  // Seed 000, Appendix 3: FN = 3, CN = 2.
  const auto scene = network_scene_of("davies-2-circuit.yaml");
  ASSERT_EQ(scene.modes.size(), 3u);
  ASSERT_EQ(scene.stresses.size(), 2u);
  for (int k = 1; k <= 2; ++k) {
    const auto& stress = scene.stresses[static_cast<std::size_t>(k - 1)];
    EXPECT_FALSE(stress.wrenches.empty()) << "self-stress " << k;
    const std::string svg = report::mechanism_svg(scene, {0, k});
    EXPECT_GE(count(svg, "class=\"wrench\""), static_cast<int>(stress.wrenches.size())) << "self-stress " << k;
    EXPECT_NE(svg.find("line of action of the wrench"), std::string::npos);
  }
  for (int k = 1; k <= 3; ++k) {
    const auto& mode = scene.modes[static_cast<std::size_t>(k - 1)];
    EXPECT_FALSE(mode.twists.empty()) << "mode " << k;
    EXPECT_FALSE(mode.moving.empty()) << "mode " << k;
    const std::string svg = report::mechanism_svg(scene, {k, 0});
    EXPECT_GE(count(svg, "class=\"twist\""), static_cast<int>(mode.twists.size())) << "mode " << k;
    EXPECT_GE(count(svg, "class=\"undeformed\""), 1) << "mode " << k;
  }
  const auto json = report::scene_json(scene);
  EXPECT_EQ(json["stresses"].size(), 2u);
  EXPECT_FALSE(json["stresses"][0]["wrenches"].empty());
  EXPECT_FALSE(json["modes"][2]["twists"].empty());
}

// Networks above network::kDenseNetworkLimit couplings are drawn from the sparse analysis, as
// `analyze` reports them (the dense Davies analysis of 400 couplings took 14 s and 0.8 GB just to
// draw): 200 parallel links between the ground and a top bar (FN = 1, CN = 200 − 2 by hand, see
// scene_test), through `draw` and `report`.
TEST(Pictures, LargeNetworkIsDrawnFromTheSparseAnalysis) {
  std::string yaml = "kinestat: 1\nkind: network\nname: parallel links\ndimension: planar\nground: ground\ncouplings:\n";
  for (int i = 0; i < 200; ++i)
    yaml += "  - {name: A" + std::to_string(i) + ", type: revolute, between: [ground, L" + std::to_string(i) + "], point: [" +
            std::to_string(i) + ", 0]}\n  - {name: B" + std::to_string(i) + ", type: revolute, between: [L" + std::to_string(i) +
            ", top], point: [" + std::to_string(i) + ", 10]}\n";
  const std::string path = kinestat::testing::write_temp_file("parallel_links.yaml", yaml);
  const auto drawn = kinestat::testing::run_cli("draw " + path + " --what mechanism --mode 1 --stress 2");
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_NE(drawn.out.find("mode 1 (sparse QR basis) (of 1)"), std::string::npos);
  EXPECT_NE(drawn.out.find("self-stress 2 (sparse QR basis) (first 8 of 198)"), std::string::npos);
  EXPECT_NE(drawn.out.find("198 redundant constraints"), std::string::npos);
  EXPECT_GE(count(drawn.out, "class=\"wrench\""), 2);
  const auto refused = kinestat::testing::run_cli("draw " + path + " --what mechanism --stress 9");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--stress 9: the model has 198 self-stress state(s); the first 8 can be drawn"), std::string::npos) << refused.err;
  const auto graph = kinestat::testing::run_cli("draw " + path);
  ASSERT_EQ(graph.exit_code, 0) << graph.err;
  EXPECT_NE(graph.out.find("tree from the ground: branches thick, chords thin"), std::string::npos);
  // 202 bodies on one circle: no names (they would overlap), and the picture says so.
  EXPECT_NE(graph.out.find("202 bodies: names left out"), std::string::npos);
  EXPECT_EQ(graph.out.find(">L17<"), std::string::npos);
  if (report::html_report_built_in()) {
    const auto html = kinestat::testing::run_cli("report " + path);
    ASSERT_EQ(html.exit_code, 0) << html.err;
    EXPECT_NE(html.out.find("\"sparse\":true"), std::string::npos);
    EXPECT_NE(html.out.find("\"stress_total\":198"), std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST(Pictures, PlanarFourBarTwistsAreItsInstantCentres) {
  // Planar four-bar network, pivots A (0, 0), B (1, 2), C (4, 3), D (5, 0): the crank turns
  // about A, the rocker about D, the coupler about the intersection of lines AB and DC:
  // t (1, 2) = (5, 0) + s (-1, 3) gives t = 3, i.e. (3, 6). Rotations about z, pitch 0.
  const auto scene = network_scene_of("four-bar-planar.yaml");
  ASSERT_EQ(scene.modes.size(), 1u);
  std::map<std::string, Eigen::Vector3d> centre;
  for (const auto& twist : scene.modes[0].twists) {
    EXPECT_FALSE(twist.pure);
    EXPECT_NEAR(std::abs(twist.direction.z()), 1.0, 1e-9);
    EXPECT_NEAR(twist.pitch, 0.0, 1e-9);
    centre[twist.name] = twist.point;
  }
  ASSERT_EQ(centre.size(), 3u);
  EXPECT_NEAR((centre.at("crank") - Eigen::Vector3d(0, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((centre.at("rocker") - Eigen::Vector3d(5, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((centre.at("coupler") - Eigen::Vector3d(3, 6, 0)).norm(), 0.0, 1e-9);
}

TEST(Pictures, SauraEq2DiagramEdgesAvoidForeignCircles) {
  const auto file = kinestat::io::YamlFile::load(example_path("saura-eq2.yaml"));
  const auto model = kinestat::io::read_structure_model(file);
  const std::string svg = report::structure_svg(model, kinestat::structure::analyse_structure(model));
  struct Circle {
    double x, y, r;
  };
  std::map<int, Circle> circles;
  const std::regex circle(R"re(<circle data-group="(\d+)" cx="([-0-9.]+)" cy="([-0-9.]+)" r="([0-9.]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it)
    circles[std::stoi((*it)[1])] = {std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])};
  ASSERT_EQ(circles.size(), 4u);  // frame, SG-I, SG-II, SG-III
  const std::regex arrow(
      R"re(data-from="(\d+)" data-to="(\d+)" d="M([-0-9.]+),([-0-9.]+) Q([-0-9.]+),([-0-9.]+) ([-0-9.]+),([-0-9.]+)")re");
  int arrows = 0;
  bool frame_to_second = false;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), arrow); it != std::sregex_iterator(); ++it) {
    const int from = std::stoi((*it)[1]), to = std::stoi((*it)[2]);
    frame_to_second = frame_to_second || (from == 0 && to == 2);
    double p[6];
    for (int i = 0; i < 6; ++i) p[i] = std::stod((*it)[i + 3]);
    ++arrows;
    for (const auto& [group, c] : circles) {
      if (group == from || group == to) continue;
      for (int s = 0; s <= 200; ++s) {
        const double t = s / 200.0, u = 1 - t;
        const double x = u * u * p[0] + 2 * u * t * p[2] + t * t * p[4];
        const double y = u * u * p[1] + 2 * u * t * p[3] + t * t * p[5];
        ASSERT_GT(std::hypot(x - c.x, y - c.y), c.r) << "arrow " << from << " -> " << to << " passes under the circle of group " << group;
      }
    }
  }
  EXPECT_GE(arrows, 3);
  EXPECT_TRUE(frame_to_second) << "seed 004, Fig. 4: the frame assigns DOF to SG-II (the follower's cam pair)";
  // Each group is labelled with its bodies (seed 004: SG-I {2, 3}, SG-II {4}, SG-III {5}).
  EXPECT_NE(svg.find(">wheel, arm</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">follower</text>"), std::string::npos);
  EXPECT_NE(svg.find(">link</text>"), std::string::npos);
}

TEST(Pictures, VerdictAndUnitsAreShownWhenPresent) {
  auto scene = framework_scene_of("truss-12.yaml");
  kinestat::design::Verdict verdict;
  verdict.summary = "1 extra motion, 1 redundant constraint.";
  verdict.extra_motions = 1;
  verdict.redundant_constraints = 1;
  kinestat::design::DesignChange change;
  change.action = "release";
  change.target_kind = "deformation";
  change.target = "bar 7 elongation";
  change.becomes = "released";
  change.reason = "removes the self-stress";
  verdict.changes.push_back(change);
  verdict.changes_verified = true;
  scene.verdict = verdict;
  scene.units = "mm";
  const std::string svg = report::mechanism_svg(scene);
  EXPECT_NE(svg.find("Verdict: 1 extra motion, 1 redundant constraint."), std::string::npos);
  EXPECT_NE(svg.find("release bar 7 elongation"), std::string::npos);
  EXPECT_NE(svg.find(" mm</text>"), std::string::npos) << "scale bar in the model's unit";
  const auto json = report::scene_json(scene);
  EXPECT_EQ(json["units"], "mm");
  EXPECT_EQ(json["verdict"]["summary"], verdict.summary);
  EXPECT_EQ(json["verdict"]["changes"][0]["target"], "bar 7 elongation");
  scene.units.clear();
  EXPECT_NE(report::mechanism_svg(scene).find(" model units</text>"), std::string::npos);
  // The coupling graph of a network carries the verdict under the model's name.
  auto network = network_scene_of("davies-2-circuit.yaml");
  EXPECT_EQ(report::graph_svg(network).find("class=\"verdict\""), std::string::npos);
  network.verdict = verdict;
  EXPECT_NE(report::graph_svg(network).find("Verdict: 1 extra motion, 1 redundant constraint."), std::string::npos);
}

TEST(Pictures, SupportsAreDrawnByKind) {
  // Braced square: A held in x and y (a pin: truss nodes have no rotations), B on a roller
  // held in y only, free along x. Folded-sheet flexure: A clamped (beam node, rotations held).
  const auto square = framework_scene_of("braced-square.yaml");
  std::map<std::string, const report::SceneNode*> node;
  for (const auto& n : square.nodes) node[n.name] = &n;
  EXPECT_EQ(node.at("A")->support, "pinned");
  EXPECT_EQ(node.at("B")->support, "roller");
  ASSERT_EQ(node.at("B")->free_directions.size(), 1u);
  EXPECT_EQ(node.at("B")->free_directions[0], Eigen::Vector3d::UnitX());
  const std::string svg = report::mechanism_svg(square);
  EXPECT_NE(svg.find("data-node=\"A\" data-support=\"pinned\""), std::string::npos);
  EXPECT_NE(svg.find("data-node=\"B\" data-support=\"roller\""), std::string::npos);
  const auto sheet = framework_scene_of("folded-sheet-flexure.yaml");
  int clamped = 0;
  for (const auto& n : sheet.nodes) clamped += n.support == "fixed" ? 1 : 0;
  EXPECT_EQ(clamped, 1);
}

}  // namespace
