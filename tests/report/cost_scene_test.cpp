// SPDX-License-Identifier: BSD-3-Clause
// The cost of over-constraint in the pictures (issue 38, item 5): the stress the worst misfit
// locks in drawn on the elements, and the eigenmodes as animated modes, against hand
// derivations (the force method on a braced square; a mass on a parallel leaf-spring guide).

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "framework/framework_test_support.hpp"
#include "kinestat/framework/over_constraint_cost.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/scene.hpp"
#include "support/cli_run.hpp"

namespace kinestat::report {
namespace {

// A planar square of side a (mm) with both diagonals, steel bars of area `area`, on statically
// determinate supports: one self-stress.
framework::FrameworkModel braced_square(double a, double area) {
  const std::string side = fmt::format("{}", a);
  return framework::testing::parse_model(
      "kinestat: 1\nkind: framework\nname: braced square\ndimension: planar\nunits: mm\n"
      "materials: {steel: {E: 210000, G: 80000}}\nsections: {bar: {area: " + fmt::format("{}", area) + "}}\n"
      "defaults: {material: steel, section: bar}\n"
      "nodes: {A: [0, 0], B: [" + side + ", 0], C: [" + side + ", " + side + "], D: [0, " + side + "]}\n"
      "supports: {A: fixed, B: [y]}\nelements:\n"
      "  - {name: s1, type: truss, nodes: [A, B]}\n  - {name: s2, type: truss, nodes: [B, C]}\n"
      "  - {name: s3, type: truss, nodes: [C, D]}\n  - {name: s4, type: truss, nodes: [D, A]}\n"
      "  - {name: d1, type: truss, nodes: [A, C]}\n  - {name: d2, type: truss, nodes: [B, D]}\n");
}

TEST(CostScene, BracedSquareMisfitStressIsTheForceMethodsOnEveryBar) {
  // By hand (force method, EA the same for every bar): the self-stress is sides −1, diagonals
  // √2; Σ sᵢ² Lᵢ / EA = (4a + 2·2·a√2) / EA = 4a(1 + √2) / EA. A misfit δ of a diagonal (made δ
  // short): α = √2 δ EA / (4a(1 + √2)); diagonal force √2 α = EA δ / (2a(1 + √2)) (tension), side
  // force −α (compression). A side misfit gives less (the diagonals √2 δ EA / (4a(1 + √2))), so
  // the worst case is a diagonal; stresses are the forces over A.
  const double a = 100.0, area = 3.0, e_modulus = 210000.0, delta = 0.02;
  const framework::FrameworkModel model = braced_square(a, area);
  const framework::FrameworkResult analysis = framework::analyse_framework(model);
  ASSERT_EQ(analysis.self_stresses, 1);
  framework::AnalysedCost analysed;
  analysed.cost = framework::over_constraint_cost(model, analysis, 2, delta);  // at C
  Scene scene = framework_scene(model, analysis);
  const std::size_t self_stresses = scene.stresses.size();
  add_framework_cost(scene, model, analysed);
  ASSERT_EQ(scene.stresses.size(), self_stresses + 1);
  const SceneStress& misfit = scene.stresses.back();
  EXPECT_EQ(misfit.unit, "N/mm^2");
  const double diagonal = e_modulus * delta / (2 * a * (1 + std::sqrt(2.0)));
  const double side = -std::sqrt(2.0) * e_modulus * delta / (4 * a * (1 + std::sqrt(2.0)));
  ASSERT_EQ(misfit.value.size(), scene.elements.size());
  for (std::size_t line = 0; line < scene.elements.size(); ++line) {
    const bool is_diagonal = scene.elements[line].name[0] == 'd';
    EXPECT_NEAR(misfit.value[line], is_diagonal ? diagonal : side, 1e-9 * diagonal) << scene.elements[line].name;
    EXPECT_EQ(misfit.kind[line], "elongation");
  }
  // The label names the worst element (a diagonal), its stress with units and the misfit.
  EXPECT_NE(misfit.label.find(fmt::format("{:.4g} N/mm^2", diagonal)), std::string::npos) << misfit.label;
  EXPECT_TRUE(misfit.label.find("worst d1,") != std::string::npos || misfit.label.find("worst d2,") != std::string::npos) << misfit.label;
  EXPECT_NE(misfit.label.find("0.02 mm"), std::string::npos) << misfit.label;
  // No masses: no eigenmodes added.
  for (const SceneMode& mode : scene.modes) EXPECT_TRUE(mode.kind.empty());
}

TEST(CostScene, BracedSquareWithOneDiagonalGetsNoStressEntry) {
  // Statically determinate (no self-stress): any misfit is taken up without stress.
  framework::FrameworkModel model = braced_square(100.0, 3.0);
  model.elements.pop_back();
  const framework::FrameworkResult analysis = framework::analyse_framework(model);
  ASSERT_EQ(analysis.self_stresses, 0);
  framework::AnalysedCost analysed;
  analysed.cost = framework::over_constraint_cost(model, analysis, 2, 0.02);
  Scene scene = framework_scene(model, analysis);
  add_framework_cost(scene, model, analysed);
  EXPECT_TRUE(scene.stresses.empty());
  EXPECT_EQ(scene.summary.back().value, "none: exactly constrained against misfit");
}

pipeline::ModelPictures steel_guide_pictures(std::optional<double> misfit) {
  return pipeline::picture_model(io::read_model_file(framework::testing::example_path("parallel-leaf-spring-guide-steel.yaml")),
                                 std::nullopt, false, misfit);
}

TEST(CostScene, SteelLeafGuideFirstEigenmodeIsTheGuidesMotionAtItsFrequency) {
  // By hand: two leaves (l = 40 mm, w = 10 mm, t = 0.2 mm, E = 210000 MPa) clamped-guided in
  // parallel: k = 24 E Iy / l³ with Iy = w t³ / 12; the mass at P is m = 1e-4 t plus the upper
  // halves of the two leaves (ρ w t l / 2 each, ρ = 7.85e-9 t/mm³). f₁ = √(k/m) / 2π, and the
  // mode moves P along x, the guide's motion (the platform's turning is 2.5e7 times stiffer).
  const double l = 40, w = 10, t = 0.2, e_modulus = 210000, rho = 7.85e-9;
  const double k = 24 * e_modulus * (w * t * t * t / 12) / (l * l * l);
  const double m = 1e-4 + rho * w * t * l;
  const double f1 = std::sqrt(k / m) / (2 * std::numbers::pi);
  const pipeline::ModelPictures pictures = steel_guide_pictures(std::nullopt);
  const Scene& scene = pictures.scene;
  std::vector<const SceneMode*> eigenmodes;
  for (const SceneMode& mode : scene.modes)
    if (mode.kind == "vibration") eigenmodes.push_back(&mode);
  ASSERT_FALSE(eigenmodes.empty());
  const SceneMode& first = *eigenmodes.front();
  EXPECT_EQ(first.label.rfind(fmt::format("eigenmode 1: {:.4g} Hz", f1), 0), 0u) << first.label << " against " << f1;
  std::size_t p = 0;
  while (scene.nodes[p].name != "P") ++p;
  const Eigen::Vector3d& v = first.velocity[p];
  EXPECT_NEAR(std::abs(v.x()), 1.0, 1e-6);  // the largest translation, scaled to 1
  EXPECT_NEAR(v.y(), 0.0, 1e-9);
  EXPECT_NEAR(v.z(), 0.0, 1e-9);
  // Ascending frequencies in the labels' order.
  double previous = 0.0;
  for (const SceneMode* mode : eigenmodes) {
    const double f = std::stod(mode->label.substr(mode->label.find(": ") + 2));
    EXPECT_GE(f, previous) << mode->label;
    previous = f;
  }
}

TEST(CostScene, SteelLeafGuideMisfitStressIsOnBothLeavesAsBending) {
  // By hand (docs/stiffness.md, worked example): a misfit δ of one leaf's in-plane bending
  // gives both leaves the end moment δ E Iz / (2 l²), peak stress δ E w / (4 l²); per mm of
  // misfit (no --misfit): 328.125 N/mm².
  const double l = 40, w = 10, e_modulus = 210000;
  for (const double delta : {1.0, 0.01}) {
    const pipeline::ModelPictures pictures = steel_guide_pictures(delta == 1.0 ? std::nullopt : std::optional<double>(delta));
    const Scene& scene = pictures.scene;
    ASSERT_FALSE(scene.stresses.empty());
    const SceneStress& misfit = scene.stresses.back();
    ASSERT_EQ(misfit.unit, "N/mm^2");
    const double peak = delta * e_modulus * w / (4 * l * l);
    for (std::size_t line = 0; line < scene.elements.size(); ++line) {
      if (scene.elements[line].name.rfind("leaf", 0) != 0) continue;
      EXPECT_NEAR(misfit.value[line], peak, 1e-9 * peak) << scene.elements[line].name;
      EXPECT_EQ(misfit.kind[line], "bending");
    }
    EXPECT_NE(misfit.label.find(fmt::format("{:.4g} N/mm^2", peak)), std::string::npos) << misfit.label;
    EXPECT_NE(misfit.label.find(delta == 1.0 ? "per mm of misfit" : "from a misfit of 0.01 mm"), std::string::npos) << misfit.label;
    // The viewer reads the unit and the eigenmodes' kind from the scene JSON.
    const nlohmann::ordered_json json = scene_json(scene);
    EXPECT_EQ(json["stresses"].back()["unit"], "N/mm^2");
    EXPECT_EQ(json["modes"].back()["kind"], "vibration");
  }
}

TEST(CostScene, ModelsWithoutElasticDataKeepTheirSceneAndRefuseAMisfit) {
  const auto file = io::read_model_file(framework::testing::example_path("folded-sheet-guide-6.yaml"));
  const pipeline::ModelPictures pictures = pipeline::picture_model(file, std::nullopt);
  for (const SceneStress& stress : pictures.scene.stresses) EXPECT_TRUE(stress.unit.empty());
  for (const SceneMode& mode : pictures.scene.modes) EXPECT_TRUE(mode.kind.empty());
  const nlohmann::ordered_json json = scene_json(pictures.scene);
  for (const auto& stress : json["stresses"]) EXPECT_FALSE(stress.contains("unit"));
  for (const auto& mode : json["modes"]) EXPECT_FALSE(mode.contains("kind"));
  const auto refused = kinestat::testing::run_cli("report " + framework::testing::example_path("folded-sheet-guide-6.yaml") +
                                                  " --misfit 0.01 -o /dev/null");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--misfit needs a framework model with materials and sections"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace kinestat::report
