// SPDX-License-Identifier: BSD-3-Clause
// The misfit stress of over-constrained frameworks by the force method (issue 38, item 3), and
// the geometric stiffness of its prestress (item 4), against hand derivations.

#include <gtest/gtest.h>

#include <cmath>

#include "framework/framework_test_support.hpp"
#include "kinestat/framework/geometric_stiffness.hpp"
#include "kinestat/framework/misfit.hpp"

namespace kinestat::framework {
namespace {

// A planar square of side a with both diagonals on statically determinate supports (A pinned,
// B on a roller): one self-stress. `diagonals` false leaves the second diagonal out.
FrameworkModel braced_square(double a, bool both_diagonals) {
  std::string text = "kinestat: 1\nkind: framework\nname: braced square\ndimension: planar\n";
  text += "nodes: {A: [0, 0], B: [" + std::to_string(a) + ", 0], C: [" + std::to_string(a) + ", " + std::to_string(a) +
          "], D: [0, " + std::to_string(a) + "]}\n";
  text += "supports: {A: fixed, B: [y]}\nelements:\n";
  text += "  - {name: s1, type: truss, nodes: [A, B]}\n  - {name: s2, type: truss, nodes: [B, C]}\n";
  text += "  - {name: s3, type: truss, nodes: [C, D]}\n  - {name: s4, type: truss, nodes: [D, A]}\n";
  text += "  - {name: d1, type: truss, nodes: [A, C]}\n";
  if (both_diagonals) text += "  - {name: d2, type: truss, nodes: [B, D]}\n";
  return testing::parse_model(text);
}

// Unit EA and unit area for every bar: K_e = [EA / L], so the peak stress is |N|.
std::vector<ElementCompliance> unit_bars(const FrameworkModel& model) {
  std::vector<ElementCompliance> out;
  for (const Element& e : model.elements) {
    const double length = (model.nodes[e.nodes[1]].position - model.nodes[e.nodes[0]].position).norm();
    ElementCompliance c;
    c.stiffness = Eigen::MatrixXd::Constant(1, 1, 1.0 / length);
    c.area = 1.0;
    out.push_back(c);
  }
  return out;
}

TEST(Misfit, BarBetweenTwoWallsTakesEaDeltaOverL) {
  // One bar of EA = 3, L = 2 between fixed points, made δ = 0.01 short: S = [1], F = [L/EA],
  // s = (L/EA)⁻¹ δ = EA δ / L = 0.015, tension.
  const Eigen::VectorXd s = force_method_resultants(Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Constant(1, 1, 2.0 / 3.0),
                                                    Eigen::VectorXd::Constant(1, 0.01));
  EXPECT_NEAR(s(0), 0.015, 1e-15);
}

TEST(Misfit, BracedSquareGivesTheForceMethodBarForces) {
  // Side a = 2, EA = 1, diagonals a√2. Equilibrium at a corner of the self-stress: a side and
  // the diagonal, t_side + t_diag/√2 = 0, so s = (−1, −1, −1, −1, √2, √2) (sides, diagonals).
  // Σ sᵢ² Lᵢ/EA = 4a + 2·2·a√2 = 4a(1 + √2). A misfit δ of d1 (made δ short): α = √2 δ / (4a(1 + √2)),
  // diagonal force √2 α = δ / (2a(1 + √2)) (tension), side force −α (compression).
  const double a = 2.0, delta = 1e-3;
  const FrameworkModel model = braced_square(a, true);
  const FrameworkResult analysis = analyse_framework(model);
  ASSERT_EQ(analysis.self_stresses, 1);
  const MisfitResult misfit = analyse_misfit(model, analysis, unit_bars(model), delta);
  ASSERT_TRUE(misfit.computed);
  EXPECT_EQ(misfit.participating.size(), 6u);
  const double diagonal = delta / (2 * a * (1 + std::sqrt(2.0))), side = -std::sqrt(2.0) * delta / (4 * a * (1 + std::sqrt(2.0)));
  // The worst case is a diagonal misfit (a side misfit gives the diagonals only √2 δ/(4a(1 + √2))):
  ASSERT_TRUE(misfit.worst_source.has_value());
  const std::string source = model.elements[analysis.indexing.deformations[static_cast<std::size_t>(*misfit.worst_source)].element].name;
  EXPECT_TRUE(source == "d1" || source == "d2") << source;
  EXPECT_NEAR(misfit.worst.force, diagonal, 1e-12 * diagonal);
  EXPECT_NEAR(misfit.worst.stress, diagonal, 1e-12 * diagonal);  // unit area
  // Every bar's force in that case (the misfit bar and the other diagonal alike).
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const double expected = model.elements[e].name[0] == 'd' ? diagonal : side;
    EXPECT_NEAR(misfit.worst_resultants(analysis.indexing.first_deformation[e]), expected, 1e-12 * diagonal) << model.elements[e].name;
  }
  EXPECT_EQ(misfit.elements.size(), 6u);
  // Compatibility, with the hand self-stress σ = (−1, −1, −1, −1, √2, √2): the geometric
  // elongations F s − e₀ (elastic stretch less the misfit) come from a node motion, so the
  // self-stress does no work on them: Σ σ_i (L_i s_i / EA − e₀_i) = 0.
  double work = 0.0;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const double length = (model.nodes[model.elements[e].nodes[1]].position - model.nodes[model.elements[e].nodes[0]].position).norm();
    const double force = misfit.worst_resultants(analysis.indexing.first_deformation[e]);
    const double misfit_here = model.elements[e].name == source ? delta : 0.0;
    const double self_stress = model.elements[e].name[0] == 'd' ? std::sqrt(2.0) : -1.0;
    work += self_stress * (length * force - misfit_here);
  }
  EXPECT_NEAR(work, 0.0, 1e-15);
}

// The element a deformation index belongs to, by name.
std::string element_of(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index deformation) {
  return model.elements[analysis.indexing.deformations[static_cast<std::size_t>(deformation)].element].name;
}

TEST(Misfit, PerElementMisfitOfOneDiagonalGivesTheSingleDiagonalBarForces) {
  // `--misfit d1=δ` and nothing else: only d1 is made δ short, every other bar fits (misfit 0).
  // By the force method above: diagonals δ/(2a(1 + √2)) (tension), sides −√2 δ/(4a(1 + √2)),
  // and the cases of the other bars (zero misfit) lock in nothing.
  const double a = 2.0, delta = 1e-3;
  const FrameworkModel model = braced_square(a, true);
  const FrameworkResult analysis = analyse_framework(model);
  MisfitTolerance tolerance;
  tolerance.per_element = {{"d1", delta}};
  const MisfitResult misfit = analyse_misfit(model, analysis, unit_bars(model), tolerance);
  ASSERT_TRUE(misfit.worst_source.has_value());
  EXPECT_EQ(element_of(model, analysis, *misfit.worst_source), "d1");
  EXPECT_EQ(misfit.worst_misfit, delta);
  EXPECT_EQ(misfit.value, 0.0);
  EXPECT_EQ(misfit.participating.size(), 6u);  // every bar is in the self-stress, misfit or not
  const double diagonal = delta / (2 * a * (1 + std::sqrt(2.0))), side = -std::sqrt(2.0) * delta / (4 * a * (1 + std::sqrt(2.0)));
  EXPECT_NEAR(misfit.worst.force, diagonal, 1e-12 * diagonal);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const double expected = model.elements[e].name[0] == 'd' ? diagonal : side;
    EXPECT_NEAR(misfit.worst_resultants(analysis.indexing.first_deformation[e]), expected, 1e-12 * diagonal) << model.elements[e].name;
  }
}

TEST(Misfit, PerElementWorstCaseIsTheLargestUnitForceTimesItsMisfit) {
  // Diagonals d1 = 1e-3, d2 = 3e-3, sides none: a diagonal misfit δ gives |force| at most
  // δ/(2a(1 + √2)), so d2's case is the worst, three times d1's: 3e-3/(2a(1 + √2)).
  const double a = 2.0, root2 = std::sqrt(2.0);
  const FrameworkModel model = braced_square(a, true);
  const FrameworkResult analysis = analyse_framework(model);
  MisfitTolerance diagonals;
  diagonals.per_element = {{"d1", 1e-3}, {"d2", 3e-3}};
  const MisfitResult two = analyse_misfit(model, analysis, unit_bars(model), diagonals);
  ASSERT_TRUE(two.worst_source.has_value());
  EXPECT_EQ(element_of(model, analysis, *two.worst_source), "d2");
  const double d2_force = 3e-3 / (2 * a * (1 + root2));
  EXPECT_NEAR(two.worst.force, d2_force, 1e-12 * d2_force);
  EXPECT_NEAR(two.worst.stress, d2_force, 1e-12 * d2_force);  // unit area

  // A side misfit δ (α = −δ/(4a(1 + √2))) gives the diagonals |√2 α| = √2 δ/(4a(1 + √2)), the
  // sides |α|: per unit misfit 1/√2 of a diagonal's. With d1 = d2 = 1e-3 and the sides the plain
  // 1.5e-3, a side's case is worse (√2·1.5e-3/4 = 0.530e-3 > 1e-3/2 = 0.5e-3, over a(1 + √2)),
  // its largest force on a diagonal; with the sides at 1.3e-3 (0.460e-3) a diagonal's wins.
  for (const double side_misfit : {1.5e-3, 1.3e-3}) {
    MisfitTolerance mixed;
    mixed.value = side_misfit;
    mixed.per_element = {{"d1", 1e-3}, {"d2", 1e-3}};
    const MisfitResult m = analyse_misfit(model, analysis, unit_bars(model), mixed);
    ASSERT_TRUE(m.worst_source.has_value());
    const std::string source = element_of(model, analysis, *m.worst_source);
    const double side_case = root2 * side_misfit / (4 * a * (1 + root2)), diagonal_case = 1e-3 / (2 * a * (1 + root2));
    if (side_misfit == 1.5e-3) {
      EXPECT_EQ(source[0], 's') << source;
      EXPECT_EQ(m.worst_misfit, side_misfit);
      EXPECT_EQ(model.elements[m.worst.element].name[0], 'd');
      EXPECT_NEAR(std::abs(m.worst.force), side_case, 1e-12 * side_case);
    } else {
      EXPECT_EQ(source[0], 'd') << source;
      EXPECT_NEAR(m.worst.force, diagonal_case, 1e-12 * diagonal_case);
    }
  }
}

TEST(Misfit, PerElementMisfitOfAnUnknownElementIsRefused) {
  const FrameworkModel model = braced_square(2.0, true);
  MisfitTolerance tolerance;
  tolerance.per_element = {{"d3", 1e-3}};
  EXPECT_EQ(unknown_misfit_element(model, tolerance), std::optional<std::string>("d3"));
  EXPECT_THROW(analyse_misfit(model, analyse_framework(model), unit_bars(model), tolerance), std::invalid_argument);
}

TEST(Misfit, BracedSquareStressScalesWithTheMisfitAndTheUnit) {
  // The same square in mm (a = 2000 mm, EA in N: unchanged per bar force) and in m (a = 2 m):
  // the force for a misfit of 1 mm = 1e-3 m is the same number of newtons: EA δ/(2a(1+√2)) with
  // EA = 1 N in both — a linear result, and the unit cancels in δ/a.
  const FrameworkModel metres = braced_square(2.0, true), millimetres = braced_square(2000.0, true);
  const MisfitResult m = analyse_misfit(metres, analyse_framework(metres), unit_bars(metres), 1e-3);
  std::vector<ElementCompliance> mm_bars = unit_bars(millimetres);
  const MisfitResult mm = analyse_misfit(millimetres, analyse_framework(millimetres), mm_bars, 1.0);
  EXPECT_NEAR(mm.worst.force, m.worst.force, 1e-12 * m.worst.force);
}

TEST(Misfit, ExactlyConstrainedTrussTakesAnyMisfitWithoutStress) {
  // One diagonal only: b = 5 = 2j − 3, rigid and statically determinate, no self-stress.
  const FrameworkModel model = braced_square(1.0, false);
  const FrameworkResult analysis = analyse_framework(model);
  ASSERT_EQ(analysis.self_stresses, 0);
  for (const double value : {1e-6, 1.0, 42.0}) {
    const MisfitResult misfit = analyse_misfit(model, analysis, unit_bars(model), value);
    EXPECT_TRUE(misfit.computed);
    EXPECT_FALSE(misfit.worst_source.has_value());
    EXPECT_TRUE(misfit.participating.empty());
    EXPECT_TRUE(misfit.worst_resultants.isZero(0.0));
  }
}

TEST(Misfit, SelfStressThroughRigidBarsOnlyIsRefused) {
  // A rigid loop (zero flexibility) cannot take a misfit with a finite stress.
  EXPECT_THROW(force_method_resultants(Eigen::MatrixXd::Ones(2, 1), Eigen::MatrixXd::Zero(2, 2), Eigen::VectorXd::Ones(2)),
               std::invalid_argument);
}

TEST(GeometricStiffness, TrussIsAxialForceOverLengthOnTransverseMotion) {
  // A bar from P = (1, 2, 3) to Q = (3, 5, 9): L = |(2, 3, 6)| = 7, e = (2, 3, 6)/7. With axial
  // force N = 5: K_G = N/L (I − e eᵀ) on (x_P, x_Q) as [[G, −G], [−G, G]].
  const FrameworkModel model = testing::parse_model(
      "kinestat: 1\nkind: framework\nname: bar\ndimension: spatial\nnodes: {P: [1, 2, 3], Q: [3, 5, 9]}\n"
      "elements:\n  - {type: truss, nodes: [P, Q]}\n");
  const FrameworkIndexing indexing = index_framework(model);
  const Eigen::MatrixXd k = prestress_geometric_stiffness(model, indexing, Eigen::VectorXd::Constant(1, 5.0));
  const Eigen::Vector3d e = Eigen::Vector3d(2, 3, 6) / 7.0;
  const Eigen::Matrix3d g = 5.0 / 7.0 * (Eigen::Matrix3d::Identity() - e * e.transpose());
  ASSERT_EQ(k.rows(), 6);
  EXPECT_TRUE((k.topLeftCorner<3, 3>().isApprox(g, 1e-14)));
  EXPECT_TRUE((k.topRightCorner<3, 3>().isApprox(-g, 1e-14)));
  EXPECT_TRUE((k.bottomRightCorner<3, 3>().isApprox(g, 1e-14)));
  // Along the bar a tension does not stiffen: K_G e = 0.
  EXPECT_LT((g * e).norm(), 1e-15);
}

}  // namespace
}  // namespace kinestat::framework

namespace kinestat::framework {
namespace {

// Steel sheets of 20 mm × 0.2 mm on every element of a folded-sheet guide (mm, N, MPa): the
// sheets' thin direction is local y (they release bending_xy), so the rectangle is
// [0.2 along y, 20 along z]. `scale` 1e-3 gives the same guide in metres.
FrameworkModel with_steel_sheets(FrameworkModel model, double scale) {
  Material steel;
  steel.name = "steel";
  steel.youngs_modulus = 2e5 / (scale * scale);
  steel.poisson = 0.3;
  model.materials.push_back(steel);
  Section sheet;
  sheet.name = "sheet";
  sheet.shape = SectionShape::rectangle;
  sheet.dimensions = {0.2 * scale, 20 * scale};
  model.sections.push_back(completed_section(sheet));
  model.default_material = 0;
  model.default_section = 0;
  return model;
}

TEST(Misfit, SixFoldedSheetGuideHasMisfitStressAndTheReleasedOneHasNone) {
  // Seed 002, Fig. 6: one self-stress, in-plane bending in all sheets. A misfit of 0.01 mm must
  // stress the sheets; after the release the verdict proposes (apply_proposal) the design is
  // exactly constrained and the same misfit gives no stress at all.
  const FrameworkModel six = with_steel_sheets(testing::load_example("folded-sheet-guide-6.yaml"), 1.0);
  const FrameworkResult analysis = analyse_framework(six);
  ASSERT_EQ(analysis.self_stresses, 1);
  const MisfitResult before = analyse_misfit(six, analysis, element_compliance(six), 0.01);
  ASSERT_TRUE(before.worst_source.has_value());
  EXPECT_GT(before.worst.stress, 0.0);
  EXPECT_GT(before.worst.moment, 0.0);  // in-plane bending
  // Every sheet carries the self-stress (12 elements), as the seed's figure shows.
  EXPECT_EQ(before.elements.size(), 12u);

  const FrameworkModel released = apply_proposal(six, analysis);
  const FrameworkResult after_analysis = analyse_framework(released);
  ASSERT_EQ(after_analysis.self_stresses, 0);
  const MisfitResult after = analyse_misfit(released, after_analysis, element_compliance(released), 0.01);
  EXPECT_FALSE(after.worst_source.has_value());
  EXPECT_TRUE(after.worst_resultants.isZero(0.0));

  // The five-flexure guide of Fig. 3(b) is exactly constrained as drawn.
  const FrameworkModel five = with_steel_sheets(testing::load_example("folded-sheet-guide-5.yaml"), 1.0);
  const FrameworkResult five_analysis = analyse_framework(five);
  EXPECT_EQ(five_analysis.self_stresses, 0);
  EXPECT_FALSE(analyse_misfit(five, five_analysis, element_compliance(five), 0.01).worst_source.has_value());
}

TEST(Misfit, FoldedSheetGuideInMetresGivesTheSameFiguresConverted) {
  // The same guide, lengths × 1e-3, E × 1e6, misfit 1e-5 m: forces in N unchanged, moments
  // N·mm → N·m (× 1e-3), stresses N/mm² → Pa (× 1e6).
  const FrameworkModel mm = with_steel_sheets(testing::load_example("folded-sheet-guide-6.yaml"), 1.0);
  const FrameworkModel m =
      with_steel_sheets(testing::transformed(testing::load_example("folded-sheet-guide-6.yaml"), Eigen::Matrix3d::Identity(),
                                             Eigen::Vector3d::Zero(), 1e-3),
                        1e-3);
  const MisfitResult in_mm = analyse_misfit(mm, analyse_framework(mm), element_compliance(mm), 0.01);
  const MisfitResult in_m = analyse_misfit(m, analyse_framework(m), element_compliance(m), 1e-5);
  ASSERT_TRUE(in_mm.worst_source && in_m.worst_source);
  // (The design is three-fold symmetric: equally stressed sheets tie, so the element named may
  // differ by rounding; its figures may not.) Forces on the scale of stress × sheet area (4 mm²).
  const double force_scale = in_mm.worst.stress * 4.0;
  EXPECT_NEAR(std::abs(in_m.worst.force), std::abs(in_mm.worst.force), 1e-6 * force_scale);
  EXPECT_NEAR(in_m.worst.moment, 1e-3 * in_mm.worst.moment, 1e-6 * 1e-3 * in_mm.worst.moment);
  EXPECT_NEAR(in_m.worst.stress, 1e6 * in_mm.worst.stress, 1e-6 * 1e6 * in_mm.worst.stress);
}

}  // namespace
}  // namespace kinestat::framework
