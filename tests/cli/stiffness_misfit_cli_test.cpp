// SPDX-License-Identifier: BSD-3-Clause
// `kinestat stiffness MODEL --at NODE --misfit VALUE [--json]` as a user runs it (issue 38,
// items 3-4): the cost of over-constraint of the steel leaf-spring guide against hand figures,
// the same guide made exactly constrained (no stress for any misfit), and a refused misfit.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_run.hpp"

namespace {

using kinestat::testing::run_cli;

const std::string kGuide = kinestat::testing::example_path("parallel-leaf-spring-guide-steel.yaml");

// The guide by hand (mm, N, t): E, leaf length l, width w (along y), thickness t (along x).
constexpr double kE = 210000.0, kLength = 40.0, kWidth = 10.0, kThickness = 0.2;
constexpr double kIz = kThickness * kWidth * kWidth * kWidth / 12.0;  // the leaves' stiff bending

// One self-stress: the leaves twist against each other about x, a pure moment in both. A misfit
// δ of one leaf end's bending_xy gives (force method, docs/stiffness.md) the moment
// M = δ E I_z / (2 l²) in each leaf and no axial force; the peak stress at c = w/2 is
// M c / I_z = δ E w / (4 l²): 3.28125 N/mm² for δ = 0.01 mm.
double moment_for(double misfit) { return misfit * kE * kIz / (2.0 * kLength * kLength); }
double stress_for(double misfit) { return misfit * kE * kWidth / (4.0 * kLength * kLength); }

// The guide with the release the analysis proposes (rigid body platform.T2.rx): exactly
// constrained, like seed 002's Fig. 3(b) against its over-constrained Fig. 3(a).
std::string exactly_constrained_guide() {
  std::ifstream in(kGuide);
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  const std::string platform = "nodes: [P, T1, T2]}";
  const auto at = model.find(platform);
  EXPECT_NE(at, std::string::npos);
  model.replace(at, platform.size(), "nodes: [P, T1, T2], released: [T2.rx]}");
  return kinestat::testing::write_temp_file("guide-exactly-constrained.yaml", model);
}

TEST(StiffnessMisfitCommand, JsonGivesTheWorstMisfitStressByHand) {
  const auto r = run_cli("stiffness " + kGuide + " --at P --misfit 0.01 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  const auto& misfit = report.at("misfit");
  EXPECT_EQ(misfit.at("value").get<double>(), 0.01);
  const auto& worst = misfit.at("worst");
  const std::string element = worst.at("element");
  EXPECT_TRUE(element == "leaf1" || element == "leaf2") << element;
  EXPECT_EQ(worst.at("force").get<double>(), 0.0);
  EXPECT_NEAR(worst.at("stress").get<double>(), stress_for(0.01), 1e-8 * stress_for(0.01));
  EXPECT_NEAR(worst.at("moment").get<double>(), moment_for(0.01), 1e-8 * moment_for(0.01));
  // Both leaves carry the self-stress's moment, equally.
  ASSERT_EQ(misfit.at("elements").size(), 2u);
  for (const auto& each : misfit.at("elements"))
    EXPECT_NEAR(each.at("stress").get<double>(), stress_for(0.01), 1e-8 * stress_for(0.01)) << each;
  // Deterministic bytes.
  EXPECT_EQ(run_cli("stiffness " + kGuide + " --at P --misfit 0.01 --json").out, r.out);
}

TEST(StiffnessMisfitCommand, StressIsLinearInTheMisfit) {
  const auto r = run_cli("stiffness " + kGuide + " --at P --misfit 0.1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double stress = nlohmann::json::parse(r.out).at("misfit").at("worst").at("stress").get<double>();
  EXPECT_NEAR(stress, stress_for(0.1), 1e-8 * stress_for(0.1));
}

TEST(StiffnessMisfitCommand, FrequenciesAscendAndTheFirstIsTheMassOnTheGuide) {
  const auto r = run_cli("stiffness " + kGuide + " --at P --misfit 0.01 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  const auto& frequencies = report.at("frequencies");
  ASSERT_GE(frequencies.size(), 2u);
  for (std::size_t i = 1; i < frequencies.size(); ++i)
    EXPECT_LE(frequencies[i - 1].get<double>(), frequencies[i].get<double>()) << i;
  // k = 24 E I_y / l³ (the platform's turn about y changes it by 1.6e-5 relative); m = the
  // 1e-4 t on P plus half of each leaf's ρ A l = 7.85e-9 · 2 · 40 t: f = √(k / m) / 2π.
  const double iy = kWidth * kThickness * kThickness * kThickness / 12.0;
  const double k = 24.0 * kE * iy / (kLength * kLength * kLength);
  const double m = 1e-4 + 7.85e-9 * 2.0 * 40.0;
  const double expected = std::sqrt(k / m) / (2.0 * std::acos(-1.0));
  EXPECT_NEAR(frequencies[0].get<double>(), expected, 1e-4 * expected);
  EXPECT_EQ(report.at("frequencies_with_misfit").size(), frequencies.size());
}

TEST(StiffnessMisfitCommand, TextNamesTheWorstElementAndItsStress) {
  const auto r = run_cli("stiffness " + kGuide + " --at P --misfit 0.01");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Cost of over-constraint (misfit 0.01 mm"), std::string::npos) << r.out;
  // 3.28125 N/mm² and 10.9375 N·mm, printed to four significant digits.
  EXPECT_NE(r.out.find("peak stress of 3.281 N/mm^2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bending moment of 10.94 N*mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("eigenfrequency [Hz]"), std::string::npos) << r.out;
}

TEST(StiffnessMisfitCommand, ExactlyConstrainedGuideTakesAMisfitWithoutStress) {
  const std::string model = exactly_constrained_guide();
  const auto json = run_cli("stiffness " + model + " --at P --misfit 0.01 --json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto report = nlohmann::json::parse(json.out);
  EXPECT_TRUE(report.at("misfit").at("worst").is_null()) << report.at("misfit");
  EXPECT_EQ(report.at("misfit").at("self_stresses"), 0);
  EXPECT_EQ(report.at("frequencies"), report.at("frequencies_with_misfit"));
  const auto text = run_cli("stiffness " + model + " --at P --misfit 0.01");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("no self-stress"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("without stress"), std::string::npos) << text.out;
}

TEST(StiffnessMisfitCommand, NegativeMisfitIsRefusedWithExitCode2) {
  const auto r = run_cli("stiffness " + kGuide + " --at P --misfit -1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--misfit"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not positive"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("stiffness " + kGuide + " --at P --misfit abc --json").exit_code, 2);
}

// A planar square of side 100 mm with both diagonals, steel bars of area 3 mm² (EA = 630000 N),
// on statically determinate supports: one self-stress (sides −1, diagonals √2).
std::string braced_square_file() {
  return kinestat::testing::write_temp_file(
      "braced-square-steel.yaml",
      "kinestat: 1\nkind: framework\nname: braced square\ndimension: planar\nunits: mm\n"
      "materials: {steel: {E: 210000, G: 80000}}\nsections: {bar: {area: 3}}\ndefaults: {material: steel, section: bar}\n"
      "nodes: {A: [0, 0], B: [100, 0], C: [100, 100], D: [0, 100]}\nsupports: {A: fixed, B: [y]}\nelements:\n"
      "  - {name: s1, type: truss, nodes: [A, B]}\n  - {name: s2, type: truss, nodes: [B, C]}\n"
      "  - {name: s3, type: truss, nodes: [C, D]}\n  - {name: s4, type: truss, nodes: [D, A]}\n"
      "  - {name: d1, type: truss, nodes: [A, C]}\n  - {name: d2, type: truss, nodes: [B, D]}\n");
}

TEST(StiffnessMisfitCommand, PerElementMisfitGivesThatElementsForceMethodCase) {
  // `--misfit d1=0.02`: only d1 is made 0.02 mm short. Force method (docs/stiffness.md):
  // Σ σᵢ² Lᵢ/EA = 4a(1 + √2)/EA, α = √2 δ EA/(4a(1 + √2)), diagonal force √2 α =
  // EA δ/(2a(1 + √2)) = 630000 · 0.02/(200 · 2.41421) = 26.096 N, stress over 3 mm².
  const std::string model = braced_square_file();
  const auto r = run_cli("stiffness " + model + " --at C --misfit d1=0.02 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto misfit = nlohmann::json::parse(r.out).at("misfit");
  EXPECT_TRUE(misfit.at("value").is_null());  // no plain VALUE: the other bars have none
  EXPECT_EQ(misfit.at("per_element"), nlohmann::json::parse(R"({"d1": 0.02})"));
  const double diagonal = 630000.0 * 0.02 / (2 * 100.0 * (1 + std::sqrt(2.0)));
  const auto& worst = misfit.at("worst");
  EXPECT_EQ(worst.at("source").get<std::string>().rfind("d1", 0), 0u) << worst.at("source");
  EXPECT_NEAR(worst.at("force").get<double>(), diagonal, 1e-6 * diagonal);
  EXPECT_NEAR(worst.at("stress").get<double>(), diagonal / 3.0, 1e-6 * diagonal);

  // Side s1 at 0.05 mm beside d1 at 0.02 mm: s1's case gives the diagonals √2 δ EA/(4a(1 + √2))
  // = 46.13 N (more than d1's 26.10 N), so it is the worst; the text names both tolerances.
  const double side_case = std::sqrt(2.0) * 0.05 * 630000.0 / (4 * 100.0 * (1 + std::sqrt(2.0)));
  const auto both = run_cli("stiffness " + model + " --at C --misfit s1=0.05 --misfit d1=0.02 --json");
  ASSERT_EQ(both.exit_code, 0) << both.err;
  const auto worst_both = nlohmann::json::parse(both.out).at("misfit").at("worst");
  EXPECT_EQ(worst_both.at("source").get<std::string>().rfind("s1", 0), 0u) << worst_both.at("source");
  EXPECT_NEAR(std::abs(worst_both.at("force").get<double>()), side_case, 1e-6 * side_case);
  const auto text = run_cli("stiffness " + model + " --at C --misfit s1=0.05 --misfit d1=0.02");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("misfit per held deformation: 0.02 mm in d1, 0.05 mm in s1, none elsewhere; force method"), std::string::npos)
      << text.out;
}

TEST(StiffnessMisfitCommand, PerElementMisfitOfAnUnknownElementIsOneLineWithExitCode2) {
  const auto r = run_cli("stiffness " + braced_square_file() + " --at C --misfit d9=0.02");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--misfit"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'d9'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const auto analyze = run_cli("analyze " + kGuide + " --misfit leaf3=0.01");
  EXPECT_EQ(analyze.exit_code, 2);
  EXPECT_NE(analyze.err.find("'leaf3'"), std::string::npos) << analyze.err;
}

}  // namespace
