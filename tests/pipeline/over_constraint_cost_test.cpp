// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze` of a framework with elastic data (issue 38, items 2 and 5): the cost of
// over-constraint computed in the pipeline (at the node of the intended motion; per unit misfit
// or for `--misfit`), after the verdict in text and under `stiffness` and `misfit` in JSON.
// Figures by hand.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;

const std::string kGuide = example_path("parallel-leaf-spring-guide-steel.yaml");
const std::string kReleasedGuide = std::string(KINESTAT_SOURCE_DIR) + "/tests/pipeline/data/leaf-spring-guide-steel-released.yaml";
const std::string kSixSheets = std::string(KINESTAT_SOURCE_DIR) + "/tests/pipeline/data/folded-sheet-guide-6-steel.yaml";

// The steel guide by hand: E = 210000 N/mm², leaves L = 40 mm long, 10 mm wide, 0.2 mm thick:
// I = 10 · 0.2³ / 12 mm⁴, motion stiffness (clamped-guided, two leaves, platform held from
// turning) 24 E I / L³ = 0.525 N/mm.
constexpr double kE = 210000.0, kL = 40.0, kI = 10.0 * 0.2 * 0.2 * 0.2 / 12.0;
constexpr double kMotion = 24.0 * kE * kI / (kL * kL * kL);
// Its one self-stress (the platform's turn about x against the leaves' in-plane bending): a
// misfit δ of a leaf's bending deformation gives the peak stress δ E w / (4 L²) with w = 10 mm
// (docs/stiffness.md, worked by hand): 328.125 N/mm² per mm of misfit.
constexpr double kStressPerMm = kE * 10.0 / (4.0 * kL * kL);

nlohmann::json analyze_json(const std::string& arguments) {
  const auto run = run_cli("analyze --json " + arguments);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

TEST(AnalyzeCost, SteelGuideHasTheStiffnessAtTheGuidedNodeAndTheMisfitPerMm) {
  const nlohmann::json report = analyze_json(kGuide);
  ASSERT_TRUE(report.contains("stiffness"));
  const auto& stiffness = report["stiffness"];
  EXPECT_EQ(stiffness["at"], "P");  // the node with the independent coordinate
  EXPECT_EQ(stiffness["coordinates"][0], "x");
  // The matrix entry holds every other coordinate of P: 24 E I / L³ exactly (ten digits).
  EXPECT_NEAR(stiffness["matrix"][0][0].get<double>(), kMotion, 1e-9 * kMotion);
  // The intended motion with P free to turn: the leaves' axial stiffness resists the turn, so
  // slightly less (0.52499 N/mm; docs/stiffness.md), within 1e-4 of 24 E I / L³.
  ASSERT_EQ(stiffness["motion"].size(), 1u);
  EXPECT_EQ(stiffness["motion"][0]["coordinate"], "x");
  EXPECT_NEAR(stiffness["motion"][0]["stiffness"].get<double>(), kMotion, 1e-4 * kMotion);
  EXPECT_LT(stiffness["motion"][0]["stiffness"].get<double>(), kMotion);
  // No --misfit: per one mm of misfit.
  const auto& misfit = report["misfit"];
  EXPECT_EQ(misfit["per_unit"], true);
  EXPECT_EQ(misfit["value"], 1.0);
  EXPECT_EQ(misfit["unit"], "mm");
  EXPECT_EQ(misfit["self_stresses"], 1);
  ASSERT_TRUE(misfit["worst"].is_object());
  EXPECT_NEAR(misfit["worst"]["stress"].get<double>(), kStressPerMm, 1e-6 * kStressPerMm);
  // The mass of 0.1 kg (1e-4 t in N, mm, s) plus the leaves' lumped halves at their tips
  // (2 · 7.85e-9 · 40 · 10 · 0.2 / 2 t) on the motion stiffness: f1 = √(k/m) / 2π.
  ASSERT_TRUE(report.contains("frequencies"));
  const double mass = 1e-4 + 7.85e-9 * 40 * 10 * 0.2;
  const double f1 = std::sqrt(stiffness["motion"][0]["stiffness"].get<double>() / mass) / (2 * std::numbers::pi);
  EXPECT_NEAR(report["frequencies"][0].get<double>(), f1, 1e-3 * f1);
  // What the prestress does depends on the misfit's size: only for a given --misfit.
  EXPECT_FALSE(report.contains("frequencies_with_misfit"));
  EXPECT_FALSE(misfit["stiffness"].contains("with"));
}

TEST(AnalyzeCost, GivenMisfitScalesTheStressLinearly) {
  const nlohmann::json small = analyze_json(kGuide + " --misfit 0.01");
  EXPECT_EQ(small["misfit"]["per_unit"], false);
  EXPECT_EQ(small["misfit"]["value"], 0.01);
  EXPECT_NEAR(small["misfit"]["worst"]["stress"].get<double>(), 0.01 * kStressPerMm, 1e-6 * kStressPerMm);
  EXPECT_TRUE(small.contains("frequencies_with_misfit"));
  EXPECT_TRUE(small["misfit"]["stiffness"].contains("with"));
  const nlohmann::json twice = analyze_json(kGuide + " --misfit 0.02");
  EXPECT_NEAR(twice["misfit"]["worst"]["stress"].get<double>(), 0.02 * kStressPerMm, 1e-6 * kStressPerMm);
}

TEST(AnalyzeCost, ExactlyConstrainedGuideTakesAnyMisfitWithoutStress) {
  const nlohmann::json report = analyze_json(kReleasedGuide + " --misfit 0.05");
  EXPECT_EQ(report["verdict"]["summary"].get<std::string>().rfind("Exactly constrained", 0), 0u) << report["verdict"];
  EXPECT_EQ(report["stiffness"]["at"], "P");
  EXPECT_EQ(report["misfit"]["self_stresses"], 0);
  EXPECT_TRUE(report["misfit"]["worst"].is_null());
  EXPECT_TRUE(report["misfit"]["elements"].empty());
  const auto text = run_cli("analyze " + kReleasedGuide);
  EXPECT_NE(text.out.find("taken up without stress"), std::string::npos) << text.out;
}

TEST(AnalyzeCost, OverConstrainedSixSheetsLockAStressLinearInTheMisfit) {
  const nlohmann::json per_mm = analyze_json(kSixSheets);
  EXPECT_EQ(per_mm["stiffness"]["at"], "C");
  EXPECT_EQ(per_mm["misfit"]["self_stresses"], 1);
  ASSERT_TRUE(per_mm["misfit"]["worst"].is_object());
  const double stress = per_mm["misfit"]["worst"]["stress"].get<double>();
  EXPECT_GT(stress, 0.0);
  EXPECT_FALSE(per_mm.contains("frequencies"));  // no masses
  for (double misfit : {0.01, 0.03}) {
    const nlohmann::json given = analyze_json(kSixSheets + " --misfit " + std::to_string(misfit));
    EXPECT_EQ(given["misfit"]["worst"]["element"], per_mm["misfit"]["worst"]["element"]);
    EXPECT_NEAR(given["misfit"]["worst"]["stress"].get<double>(), misfit * stress, 1e-8 * stress);
  }
}

TEST(AnalyzeCost, TextBlockFollowsTheVerdict) {
  const auto run = run_cli("analyze " + kGuide);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::size_t verdict = run.out.find("Verdict: ");
  const std::size_t block = run.out.find("Cost of over-constraint (per mm of misfit");
  const std::size_t counts = run.out.find("framework parallel leaf-spring guide");
  ASSERT_NE(block, std::string::npos) << run.out;
  EXPECT_LT(verdict, block);
  EXPECT_LT(block, counts);
  EXPECT_NE(run.out.find("stiffness at P: motion x 0.52499"), std::string::npos) << run.out;
  // --brief stays the verdict alone.
  const auto brief = run_cli("analyze --brief " + kGuide);
  EXPECT_EQ(brief.out.find("Cost of over-constraint"), std::string::npos) << brief.out;
}

TEST(AnalyzeCost, ModelsWithoutElasticDataHaveNoCostKeys) {
  const nlohmann::json report = analyze_json(example_path("folded-sheet-guide-6.yaml"));
  EXPECT_FALSE(report.contains("stiffness"));
  EXPECT_FALSE(report.contains("misfit"));
  // --misfit needs elastic data (one located line); it must be a positive finite length
  // (the option check of `kinestat stiffness --misfit`): exit 2.
  const auto plain = run_cli("analyze " + example_path("folded-sheet-guide-6.yaml") + " --misfit 0.01");
  EXPECT_EQ(plain.exit_code, 2);
  EXPECT_EQ(std::count(plain.err.begin(), plain.err.end(), '\n'), 1) << plain.err;
  EXPECT_NE(plain.err.find("folded-sheet-guide-6.yaml:1:1: error: --misfit needs"), std::string::npos) << plain.err;
  for (const char* value : {"-1", "nan", "0", "inf", "x"}) {
    const auto run = run_cli("analyze " + kGuide + " --misfit " + std::string(value));
    EXPECT_EQ(run.exit_code, 2) << value;
    EXPECT_TRUE(run.out.empty()) << value;
  }
}

TEST(AnalyzeCost, ThePipelineCarriesTheCostForEveryCaller) {
  // The Python module's to_json goes through pipeline::report_json_text: the same keys.
  const io::ModelFile file = io::read_model_file(kGuide);
  pipeline::AnalysisRequest request;
  request.misfit = 0.01;
  const pipeline::ModelAnalysis analysis = pipeline::analyse_model(file, request);
  ASSERT_TRUE(analysis.framework && analysis.framework->cost && analysis.framework->cost->cost);
  EXPECT_EQ(file.framework->nodes[analysis.framework->cost->cost->node].name, "P");
  const nlohmann::json report = nlohmann::json::parse(pipeline::report_json_text(file, analysis));
  EXPECT_EQ(report["stiffness"]["at"], "P");
  EXPECT_NEAR(report["misfit"]["worst"]["stress"].get<double>(), 0.01 * kStressPerMm, 1e-6 * kStressPerMm);
}

}  // namespace
}  // namespace kinestat
