// SPDX-License-Identifier: BSD-3-Clause
// `kinestat stiffness MODEL --at NODE [--json]` as a user runs it (issue 38): the figures of the
// shipped steel leaf-spring guide, its JSON contract, and one-line errors with exit code 2.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "support/cli_run.hpp"

namespace kinestat::stiffness_cli_tests {
namespace {

using kinestat::testing::run_cli;

const std::string kGuide = kinestat::testing::example_path("parallel-leaf-spring-guide-steel.yaml");

// By hand for the example (E = 210000 MPa, leaves 40 × 10 × 0.2 mm, 50 mm apart): the motion
// stiffness with the platform held from turning 24 E Iy / L³ = 24 · 210000 · (10 · 0.2³/12) /
// 40³ = 0.525 N/mm; the support along the leaves 2 E A / L = 2 · 210000 · 2 / 40 = 21000 N/mm.
constexpr double kMotionHeld = 0.525, kAxialSupport = 21000.0;

TEST(StiffnessCommand, TextNamesTheMotionTheSupportAndTheUnits) {
  const auto r = run_cli("stiffness " + kGuide + " --at P");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("stiffness at node P"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("intended motion: x 0.52499"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("z 21000 N/mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("N*mm/rad"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("compliance (inverse):"), std::string::npos) << r.out;
}

TEST(StiffnessCommand, JsonCarriesTheContract) {
  const auto r = run_cli("stiffness " + kGuide + " --at P --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  ASSERT_TRUE(report.contains("kinestat_version"));
  EXPECT_EQ(report["report_version"], 1);
  const auto& s = report["stiffness"];
  EXPECT_EQ(s["at"], "P");
  EXPECT_EQ(s["coordinates"], nlohmann::json({"x", "y", "z", "rx", "ry", "rz"}));
  ASSERT_EQ(s["matrix"].size(), 6u);
  ASSERT_EQ(s["compliance"].size(), 6u);
  EXPECT_NEAR(s["matrix"][0][0].get<double>(), kMotionHeld, 1e-8 * kMotionHeld);
  EXPECT_NEAR(s["matrix"][2][2].get<double>(), kAxialSupport, 1e-8 * kAxialSupport);
  // matrix × compliance = identity (to the ten printed digits).
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      double product = 0, scale = 0;
      for (int k = 0; k < 6; ++k) {
        product += s["matrix"][i][k].get<double>() * s["compliance"][k][j].get<double>();
        scale += std::abs(s["matrix"][i][k].get<double>() * s["compliance"][k][j].get<double>());
      }
      EXPECT_NEAR(product, i == j ? 1.0 : 0.0, 1e-7 * std::max(scale, 1.0)) << i << "," << j;
    }
  }
  EXPECT_EQ(s["units"]["translation"], "N/mm");
  ASSERT_EQ(s["motion"].size(), 1u);
  EXPECT_EQ(s["motion"][0]["coordinate"], "x");
  // The weakest translational support is y with the platform free to turn about x: the two
  // leaves bend as cantilevers in their stiff plane, 2 · 3 E Iz / L³ = 6 · 210000 · (0.2 · 10³/12)
  // / 40³ = 328.125 N/mm; the motion with the platform free to turn about y is
  // 24 E Iy / L³ − (12 E Iy / L²)² / (8 E Iy / L + 2 (E A / L) 25²) = 0.525 − 10.5² / 13125280.
  const double motion = kMotionHeld - 10.5 * 10.5 / 13125280.0;
  EXPECT_NEAR(s["motion"][0]["stiffness"].get<double>(), motion, 1e-8 * motion);
  EXPECT_NEAR(s["support_ratio"].get<double>(), 328.125 / motion, 1e-8 * 328.125 / motion);
  // Deterministic: the same input gives the same bytes.
  EXPECT_EQ(run_cli("stiffness " + kGuide + " --at P --json").out, r.out);
}

TEST(StiffnessCommand, MisfitAddsTheCostOfOverConstraint) {
  // The guide is over-constrained (the leaves twist against each other about x): a misfit
  // gives a worst case in one of the two (symmetric) leaves; the misfit figures themselves are
  // tested with S2's misfit tests. A misfit must be a positive length.
  const auto r = run_cli("stiffness " + kGuide + " --at P --misfit 0.01 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report.contains("stiffness"));
  ASSERT_TRUE(report.contains("misfit"));
  EXPECT_EQ(report["misfit"]["value"], 0.01);
  const std::string worst = report["misfit"]["worst"]["element"];
  EXPECT_TRUE(worst == "leaf1" || worst == "leaf2") << worst;
  EXPECT_EQ(run_cli("stiffness " + kGuide + " --at P --misfit -1").exit_code, 2);
}

TEST(StiffnessCommand, UnknownNodeIsALocatedOneLineError) {
  const auto r = run_cli("stiffness " + kGuide + " --at Q9");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("parallel-leaf-spring-guide-steel.yaml:1:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("unknown node 'Q9'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(StiffnessCommand, ModelWithoutElasticDataIsAOneLineError) {
  const auto r = run_cli("stiffness " + kinestat::testing::example_path("parallel-leaf-spring-guide.yaml") + " --at T1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("no elastic data"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(StiffnessCommand, BadMaterialIsALocatedError) {
  const std::string path = kinestat::testing::write_temp_file("stiffness-bad-material.yaml", R"(kinestat: 1
kind: framework
materials: {steel: {E: -5}}
nodes: {A: [0, 0, 0], B: [1, 0, 0]}
elements: [{type: truss, nodes: [A, B]}]
)");
  const auto r = run_cli("stiffness " + path + " --at B");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("stiffness-bad-material.yaml:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("E must be positive"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace kinestat::stiffness_cli_tests
