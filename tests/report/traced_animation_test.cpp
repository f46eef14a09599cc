// SPDX-License-Identifier: BSD-3-Clause
// Issue 13, item 2: the HTML report animates a framework's finite modes through configurations
// traced both ways, written compactly into the scene; modes that are not traced keep the
// first-order animation with the reason. Expected bar lengths are the models' own, computed by
// hand from the coordinates in the example files (not read back from kinestat).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/two_way_trace.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/scene.hpp"
#include "support/cli_run.hpp"

namespace {

using kinestat::testing::example_path;
namespace framework = kinestat::framework;
namespace report = kinestat::report;

struct Traced {
  framework::FrameworkModel model;
  framework::FrameworkResult analysis;
  report::Scene scene;
};

Traced traced_scene_of(const std::string& example) {
  Traced t;
  t.model = kinestat::io::read_framework_model(kinestat::io::YamlFile::load(example_path(example)));
  const framework::AnalysisOptions options;
  t.analysis = framework::analyse_framework(t.model, options);
  t.scene = report::framework_scene(t.model, t.analysis, framework::animation_traces(t.model, t.analysis, options));
  return t;
}

// Largest |length − rest| / rest over the scene's elements, for node positions `p`.
double worst_length_error(const report::Scene& scene, const std::vector<Eigen::Vector3d>& p, const std::vector<double>& rest) {
  double worst = 0.0;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const auto a = static_cast<std::size_t>(scene.elements[e].a), b = static_cast<std::size_t>(scene.elements[e].b);
    worst = std::max(worst, std::abs((p[b] - p[a]).norm() - rest[e]) / rest[e]);
  }
  return worst;
}

// The traced path both ways: 2 × kAnimationSteps + 1 points with the model's configuration in
// the middle, arc lengths increasing through 0 to about ± the amplitude asked for
// (kAnimationAmplitude of the characteristic length), every bar at its hand-computed length at
// every point.
void expect_two_way_path(const Traced& t, const std::vector<double>& rest) {
  ASSERT_EQ(t.scene.modes.size(), 1u);
  const auto& mode = t.scene.modes[0];
  ASSERT_TRUE(mode.trace.has_value()) << mode.first_order_reason;
  EXPECT_TRUE(mode.first_order_reason.empty());
  const auto& trace = *mode.trace;
  const auto steps = static_cast<std::size_t>(framework::kAnimationSteps);
  ASSERT_EQ(trace.positions.size(), 2 * steps + 1);
  ASSERT_EQ(trace.arc.size(), trace.positions.size());
  EXPECT_EQ(trace.start, steps);
  EXPECT_EQ(trace.arc[trace.start], 0.0);
  for (std::size_t k = 1; k < trace.arc.size(); ++k) EXPECT_GT(trace.arc[k], trace.arc[k - 1]) << k;
  const double amplitude = framework::kAnimationAmplitude * t.analysis.length;
  EXPECT_NEAR(trace.arc.back(), amplitude, 0.02 * amplitude);
  EXPECT_NEAR(trace.arc.front(), -amplitude, 0.02 * amplitude);
  EXPECT_TRUE(trace.note.empty()) << trace.note;
  EXPECT_LE(trace.max_residual, 1e-10);
  for (std::size_t i = 0; i < t.model.nodes.size(); ++i) EXPECT_EQ(trace.positions[trace.start][i], t.model.nodes[i].position);
  double worst = 0.0;
  for (const auto& p : trace.positions) worst = std::max(worst, worst_length_error(t.scene, p, rest));
  EXPECT_LT(worst, 1e-10);
  // It moves: the far ends differ from the start by a visible amount.
  double moved = 0.0;
  for (std::size_t i = 0; i < t.model.nodes.size(); ++i)
    moved = std::max({moved, (trace.positions.front()[i] - trace.positions[trace.start][i]).norm(),
                      (trace.positions.back()[i] - trace.positions[trace.start][i]).norm()});
  EXPECT_GT(moved, 0.1 * t.analysis.length);
}

// The traced path as the viewer rebuilds it from the scene JSON: the written positions plus
// `quantum` times the integer offsets of the moving nodes.
std::vector<std::vector<Eigen::Vector3d>> path_from_json(const nlohmann::ordered_json& scene, std::size_t mode) {
  const auto& p = scene["nodes"]["position"];
  const auto& trace = scene["modes"][mode]["trace"];
  const double q = trace["quantum"].get<double>();
  std::vector<std::vector<Eigen::Vector3d>> path;
  for (const auto& offsets : trace["offsets"]) {
    std::vector<Eigen::Vector3d> nodes;
    for (std::size_t i = 0; i < p.size() / 3; ++i) nodes.emplace_back(p[3 * i].get<double>(), p[3 * i + 1].get<double>(), p[3 * i + 2].get<double>());
    std::size_t j = 0;
    for (const auto& node : trace["nodes"]) {
      const auto i = node.get<std::size_t>();
      for (int c = 0; c < 3; ++c) nodes[i](c) += q * offsets[3 * j + static_cast<std::size_t>(c)].get<double>();
      ++j;
    }
    path.push_back(std::move(nodes));
  }
  return path;
}

TEST(TracedAnimation, Truss12IsTracedBothWaysWithEveryBarAtRootTwo) {
  // Seed 002, Fig. 2: all twelve bars join points √2 apart, e.g. A (−1, −1, 0) to E (0, −1, 1)
  // and E to F (1, 0, 1).
  const Traced t = traced_scene_of("truss-12.yaml");
  expect_two_way_path(t, std::vector<double>(12, std::sqrt(2.0)));
  // The supports A-D never move.
  for (const auto& p : t.scene.modes[0].trace->positions)
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(p[i], t.model.nodes[i].position);
}

TEST(TracedAnimation, FourBarOfBarsIsTracedBothWays) {
  // A (0, 0), B (2, 0), C (2, 1.5), D (0, 1): A-D 1, D-C √(4 + 0.25), C-B 1.5.
  const Traced t = traced_scene_of("four-bar-linkage.yaml");
  expect_two_way_path(t, {1.0, std::sqrt(4.25), 1.5});
}

TEST(TracedAnimation, SceneJsonWritesOnlyMovingNodesAndKeepsBarLengthsToTheQuantum) {
  const Traced t = traced_scene_of("truss-12.yaml");
  const nlohmann::ordered_json j = report::scene_json(t.scene);
  const auto& trace = j["modes"][0]["trace"];
  EXPECT_EQ(trace["nodes"], nlohmann::ordered_json::parse("[4, 5, 6, 7]"));  // E-H; A-D are supported
  EXPECT_EQ(trace["start"].get<std::size_t>(), static_cast<std::size_t>(framework::kAnimationSteps));
  // Quantum: a power of ten at most 1e-8 of the shortest moving bar (√2): 1e-8.
  EXPECT_DOUBLE_EQ(trace["quantum"].get<double>(), 1e-8);
  EXPECT_FALSE(j["modes"][0].contains("first_order"));
  const auto path = path_from_json(j, 0);
  ASSERT_EQ(path.size(), 2 * static_cast<std::size_t>(framework::kAnimationSteps) + 1);
  double worst = 0.0;
  for (const auto& p : path) worst = std::max(worst, worst_length_error(t.scene, p, std::vector<double>(12, std::sqrt(2.0))));
  // Rounding bound: two ends, half a quantum per coordinate: √3 · 1e-8 absolute on √2.
  EXPECT_LE(worst, std::sqrt(3.0) * 1e-8 / std::sqrt(2.0) + 1e-10);
  EXPECT_GT(worst, 0.0);  // the offsets are rounded, not exact
}

TEST(TracedAnimation, InfinitesimalModeIsFirstOrderWithItsReason) {
  // Two collinear bars: the middle node's mode is blocked at second order by the tension in
  // both bars (Pellegrino & Calladine's product force), so it is never traced.
  const Traced t = traced_scene_of("pellegrino-calladine-two-bar.yaml");
  ASSERT_EQ(t.scene.modes.size(), 1u);
  EXPECT_FALSE(t.scene.modes[0].trace.has_value());
  EXPECT_EQ(t.scene.modes[0].first_order_reason.rfind("blocked at second order", 0), 0u) << t.scene.modes[0].first_order_reason;
  const nlohmann::ordered_json j = report::scene_json(t.scene);
  EXPECT_FALSE(j["modes"][0].contains("trace"));
  EXPECT_EQ(j["modes"][0]["first_order"], t.scene.modes[0].first_order_reason);
}

TEST(TracedAnimation, SceneWithoutTracesSaysTheMotionWasNotTraced) {
  const auto model = kinestat::io::read_framework_model(kinestat::io::YamlFile::load(example_path("truss-12.yaml")));
  const auto scene = report::framework_scene(model, framework::analyse_framework(model));
  ASSERT_EQ(scene.modes.size(), 1u);
  EXPECT_FALSE(scene.modes[0].trace.has_value());
  EXPECT_EQ(scene.modes[0].first_order_reason, "the finite motion was not traced for this picture");
}

TEST(TracedAnimation, ReportOfTheFourBarIsDeterministicAndCarriesTheTrace) {
  if (!report::html_report_built_in()) GTEST_SKIP() << "HTML output is not built in";
  const auto first = kinestat::testing::run_cli("report " + example_path("four-bar-linkage.yaml"));
  const auto second = kinestat::testing::run_cli("report " + example_path("four-bar-linkage.yaml"));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(first.out, second.out);
  EXPECT_NE(first.out.find("\"trace\":{\"max_residual\":"), std::string::npos);
}

}  // namespace

namespace kinestat {
namespace {

// Network motions are traced by `kinestat move`, but the HTML draws them by their twists: every
// network mode says so in the panel (the issue: "first-order only where tracing fails, and said
// so"), naming the command that traces it.
TEST(TracedAnimation, NetworkModesSayTheyAreDrawnToFirstOrder) {
  const io::LoadedNetwork loaded = io::read_network_model(io::YamlFile::load(testing::example_path("bennett.yaml")));
  const network::NetworkResult result = io::analyse_network_file(loaded, "bennett.yaml", {});
  const report::Scene scene = report::network_scene(loaded.model, result);
  ASSERT_EQ(scene.modes.size(), 1u);  // Bennett: FN = 1
  EXPECT_NE(scene.modes[0].first_order_reason.find("kinestat move FILE --mode 1"), std::string::npos)
      << scene.modes[0].first_order_reason;
}

}  // namespace
}  // namespace kinestat
