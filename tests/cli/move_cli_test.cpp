// SPDX-License-Identifier: BSD-3-Clause
// `kinestat move` (issue 13): a framework mode or a network's primary motion traced with its
// path printed, and a planar mechanism's positions solved group by group. Expected values come
// from the geometry (bar lengths, Bennett's relation, the hand-derived limit angle of the
// non-Grashof four-bar, the rank of a folded parallelogram), not from the program.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace {

using kinestat::testing::example_path;
using kinestat::testing::run_cli;
using kinestat::testing::write_temp_file;

std::string data_file(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/tests/kinematics/data/" + name; }

double length(const nlohmann::json& positions, const std::string& a, const std::string& b) {
  double sum = 0;
  for (std::size_t c = 0; c < positions[a].size(); ++c) {
    const double d = positions[a][c].get<double>() - positions[b][c].get<double>();
    sum += d * d;
  }
  return std::sqrt(sum);
}

// Every bar keeps its length at every point of the path (relative to the characteristic length).
void expect_bars_keep_length(const nlohmann::json& j, const std::vector<std::pair<std::string, std::string>>& bars) {
  const auto& start = j["path"][0]["positions"];
  const double size = j["characteristic_length"].get<double>();
  for (const auto& point : j["path"])
    for (const auto& [a, b] : bars) EXPECT_NEAR(length(point["positions"], a, b), length(start, a, b), 1e-9 * size) << a << b;
}

const char* kFourBarFramework = R"(kinestat: 1
kind: framework
name: four-bar of bars
dimension: planar
nodes: {A: [0, 0], B: [1, 2], C: [4, 3], D: [5, 0]}
supports: {A: fixed, D: fixed}
elements:
  - {type: truss, nodes: [A, B]}
  - {type: truss, nodes: [B, C]}
  - {type: truss, nodes: [C, D]}
)";

TEST(MoveCli, Truss12ModeIsTracedToAmplitudeTenthWithClosure) {
  const auto r = run_cli("move " + example_path("truss-12.yaml") + " --mode 1 --amplitude 0.1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["order"], "finite");
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_LT(j["max_residual"].get<double>(), 1e-10);
  EXPECT_EQ(j["path"].size(), 21u);
  // The arc length reached is the amplitude asked for, 0.1 of the characteristic length (chords
  // of a curved path: slightly less than the predictor's steps).
  const double size = j["characteristic_length"].get<double>();
  EXPECT_NEAR(j["amplitude"].get<double>() / size, 0.1, 0.005);
  for (const auto& point : j["path"]) EXPECT_LT(point["residual"].get<double>(), 1e-10);
  expect_bars_keep_length(j, {{"A", "E"}, {"B", "E"}, {"B", "F"}, {"C", "F"}, {"C", "G"}, {"D", "G"}, {"D", "H"}, {"A", "H"},
                              {"E", "F"}, {"F", "G"}, {"G", "H"}, {"H", "E"}});
  // The supports stay where they are.
  EXPECT_EQ(j["path"].back()["positions"]["A"], j["path"][0]["positions"]["A"]);
}

TEST(MoveCli, FourBarOfBarsIsTracedWithConstantRank) {
  const auto file = write_temp_file("four-bar-bars.yaml", kFourBarFramework);
  const auto r = run_cli("move " + file + " --mode 1 --amplitude 0.1 --steps 10 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_LT(j["max_residual"].get<double>(), 1e-10);
  EXPECT_EQ(j["path"].size(), 11u);
  EXPECT_TRUE(j["rank_drops"].empty());
  for (const auto& point : j["path"]) EXPECT_EQ(point["rank"], 3);
  expect_bars_keep_length(j, {{"A", "B"}, {"B", "C"}, {"C", "D"}});
  EXPECT_NEAR(j["amplitude"].get<double>() / j["characteristic_length"].get<double>(), 0.1, 0.005);
  // The coupler moved.
  EXPECT_NE(j["path"].back()["positions"]["B"], j["path"][0]["positions"]["B"]);
  const auto text = run_cli("move " + file + " --mode 1");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("the rank of D(c) stays constant"), std::string::npos) << text.out;
}

TEST(MoveCli, CollinearTwoBarIsReportedInfinitesimal) {
  const auto r = run_cli("move " + example_path("pellegrino-calladine-two-bar.yaml") + " --mode 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["order"], "infinitesimal");
  EXPECT_FALSE(j["closed"].get<bool>());
  const auto text = run_cli("move " + example_path("pellegrino-calladine-two-bar.yaml") + " --mode 1");
  ASSERT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("order: infinitesimal"), std::string::npos) << text.out;
}

TEST(MoveCli, BadModeNumberAndMissingOptionsExitTwoWithOneLine) {
  for (const std::string& arguments :
       {"move " + example_path("truss-12.yaml") + " --mode 2", "move " + example_path("truss-12.yaml") + " --mode 0",
        "move " + example_path("truss-12.yaml"),
        "move " + example_path("truss-12.yaml") + " --mode 1 --input A=1",
        "move " + example_path("four-bar-planar.yaml") + " --mode 2",
        "move " + example_path("four-bar-planar.yaml") + " --mode 1 --input A=1",
        "move " + example_path("four-bar-planar.yaml") + " --amplitude 0.2",
        "move " + example_path("four-bar-planar.yaml"),
        "move " + example_path("four-bar-planar.yaml") + " --input X=1",
        "move " + example_path("four-bar-planar.yaml") + " --input A=1 --input D=0",
        "move " + example_path("four-bar-planar.yaml") + " --input A=one",
        "move " + example_path("four-bar-planar.yaml") + " --sweep A=0:1",
        "move " + example_path("watt-six-bar.yaml") + " --input A=1"}) {
    const auto r = run_cli(arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.out;
    EXPECT_FALSE(r.err.empty()) << arguments;
  }
  const auto mode = run_cli("move " + example_path("truss-12.yaml") + " --mode 2");
  EXPECT_NE(mode.err.find("--mode 2"), std::string::npos) << mode.err;
  EXPECT_EQ(std::count(mode.err.begin(), mode.err.end(), '\n'), 1) << mode.err;
}

// Beams: seed 002's double-clamped folded sheet (Fig. 4b). Its internal mode turns the fold node
// F about the fold line z; F then moves only in its plane z = 0 (the sheets keep their planes,
// derived in tests/framework/beam_second_order_test.cpp), and every point closes.
TEST(MoveCli, FoldedSheetInternalModeIsTracedWithClosure) {
  const auto r = run_cli("move " + example_path("folded-sheet-double-clamped.yaml") + " --mode 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["order"], "finite");
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_LT(j["max_residual"].get<double>(), 1e-10);
  ASSERT_EQ(j["path"].size(), 21u);
  for (const auto& point : j["path"]) EXPECT_NEAR(point["positions"]["F"][2].get<double>(), 0.0, 1e-9);
}

TEST(MoveCli, FourBarReportsTheInputsAtWhichItCannotBeAssembled) {
  // Hand derivation (position_solver_test.cpp): the crank input of examples/four-bar-planar.yaml
  // cannot pass atan(4/3) = 0.9273 rad nor −π.
  const auto one = run_cli("move " + example_path("four-bar-planar.yaml") + " --input A=1.0");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.out.find("cannot be assembled"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("{coupler, rocker}"), std::string::npos) << one.out;
  const auto r = run_cli("move " + example_path("four-bar-planar.yaml") + " --sweep A=0:6.283185307179586:72 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["steps"].size(), 73u);
  const double limit = std::atan(4.0 / 3);
  for (const auto& step : j["steps"]) {
    const double v = step["inputs"]["A"].get<double>();
    if (std::abs(v - std::numbers::pi) < 1e-9) continue;
    EXPECT_EQ(step["assembled"].get<bool>(), !(v > limit && v < std::numbers::pi)) << v;
    if (step["assembled"].get<bool>()) {
      EXPECT_LT(step["max_residual"].get<double>(), 1e-10);
    }
  }
  ASSERT_FALSE(j["not_assembled"].empty());
  EXPECT_EQ(j["not_assembled"][0]["group"], 2);
  EXPECT_GT(j["not_assembled"][0]["inputs"]["A"].get<double>(), limit);
  const auto again = run_cli("move " + example_path("four-bar-planar.yaml") + " --sweep A=0:6.283185307179586:72 --json");
  EXPECT_EQ(r.out, again.out);
}

TEST(MoveCli, TriadSweepTextNamesTheGroupsAndTheirMethods) {
  const auto r = run_cli("move " + data_file("class-iii-triad-planar.yaml") + " --sweep A=0:6.283185307179586:36");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triad"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Newton's method"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("cannot be assembled"), std::string::npos) << r.out;
}

// Bennett's linkage (examples/bennett.yaml; the derivation is in
// tests/network/finite_motion_test.cpp): with θ1 = 2 atan 2 + x_J1 and θ2 = 2 atan(5/2) + x_J2,
// tan(θ1/2) tan(θ2/2) = 5 and x_J3 = −x_J1, x_J4 = −x_J2 at every point of the path.
TEST(MoveCli, NetworkPrimaryMotionIsTracedWithJointCoordinates) {
  const auto r = run_cli("move " + example_path("bennett.yaml") + " --mode 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "network");
  EXPECT_EQ(j["order"], "finite");
  EXPECT_EQ(j["modes"], 1);
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_TRUE(j["not_traced"].is_null());
  EXPECT_TRUE(j["failed_step"].is_null());
  EXPECT_LT(j["max_residual"].get<double>(), 1e-10);
  EXPECT_TRUE(j["rank_drops"].empty());
  ASSERT_EQ(j["path"].size(), 21u);
  const double size = j["characteristic_length"].get<double>();
  EXPECT_NEAR(j["amplitude"].get<double>() / size, 0.1, 0.001);
  const double theta10 = 2 * std::atan(2.0), theta20 = 2 * std::atan(2.5);
  for (const auto& point : j["path"]) {
    EXPECT_LT(point["residual"].get<double>(), 1e-10);
    EXPECT_EQ(point["rank"], 3);
    const auto& x = point["coordinates"];
    ASSERT_EQ(x.size(), 4u) << x;
    const double x1 = x["t_J1"].get<double>(), x2 = x["rot1_J2"].get<double>();
    EXPECT_NEAR(std::tan((theta10 + x1) / 2) * std::tan((theta20 + x2) / 2), 5.0, 1e-8);  // ten printed digits
    EXPECT_NEAR(x["rot1_J3"].get<double>(), -x1, 1e-9);
    EXPECT_NEAR(x["rot1_J4"].get<double>(), -x2, 1e-9);
  }
  EXPECT_GT(std::abs(j["path"].back()["coordinates"]["t_J1"].get<double>()), 0.01);
  const auto again = run_cli("move " + example_path("bennett.yaml") + " --mode 1 --json");
  EXPECT_EQ(r.out, again.out);  // byte-identical
  const auto text = run_cli("move " + example_path("bennett.yaml") + " --mode 1 --steps 5 --amplitude 0.05");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("order: finite"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("stays constant"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("t_J1"), std::string::npos) << text.out;
}

// A parallelogram folded flat, A (0, 0), B (1, 0), C (3, 0), D (2, 0): at the start the four
// planar twists (1; 0, −x) have rank 2 (FN = 2, CN = 1), a four-bar away from the flat position
// rank 3 — the change point, reported as a rank drop at point 0 whichever primary motion is
// followed.
TEST(MoveCli, FoldedParallelogramReportsTheRankDropAtTheStart) {
  const auto file = write_temp_file("folded-parallelogram.yaml", R"(kinestat: 1
kind: network
name: folded parallelogram
dimension: planar
ground: ground
couplings:
  - {name: A, type: revolute, between: [ground, crank], point: [0, 0]}
  - {name: B, type: revolute, between: [crank, coupler], point: [1, 0]}
  - {name: C, type: revolute, between: [coupler, rocker], point: [3, 0]}
  - {name: D, type: revolute, between: [rocker, ground], point: [2, 0]}
)");
  for (const char* mode : {"1", "2"}) {
    SCOPED_TRACE(mode);
    const auto r = run_cli("move " + file + " --mode " + mode + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["modes"], 2);
    ASSERT_FALSE(j["path"].empty());
    EXPECT_EQ(j["path"][0]["rank"], 2);
    ASSERT_FALSE(j["rank_drops"].empty()) << r.out;
    EXPECT_EQ(j["rank_drops"][0], 0);
    if (j["path"].size() > 1) {
      EXPECT_EQ(j["path"][1]["rank"], 3);
    }
  }
  const auto text = run_cli("move " + file + " --mode 1");
  EXPECT_NE(text.out.find("drops at step 0"), std::string::npos) << text.out;
}

// Three revolutes on one line: blocked at second order (tests/network/second_order_test.cpp by
// hand), and the triangle's only position is the flat one, so the trace fails at once.
TEST(MoveCli, ThreeRevolutesOnALineAreInfinitesimal) {
  const auto file = write_temp_file("flat-triangle.yaml", R"(kinestat: 1
kind: network
name: flattened triangle
dimension: planar
ground: ground
couplings:
  - {name: A, type: revolute, between: [ground, b1], point: [0, 0]}
  - {name: B, type: revolute, between: [b1, b2], point: [1, 0]}
  - {name: C, type: revolute, between: [b2, ground], point: [2, 0]}
)");
  const auto r = run_cli("move " + file + " --mode 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["order"], "infinitesimal");
  EXPECT_FALSE(j["closed"].get<bool>());
  EXPECT_EQ(j["failed_step"], 1);
  const auto text = run_cli("move " + file + " --mode 1");
  EXPECT_NE(text.out.find("order: infinitesimal"), std::string::npos) << text.out;
}

}  // namespace
