// SPDX-License-Identifier: BSD-3-Clause
// Seed 002, section 4: straight guiding mechanisms with wire and folded sheet flexures
// (Figs. 3-6). Expected values follow from the text and from hand analysis of the geometry
// documented in each example file.

#include <gtest/gtest.h>

#include <cmath>

#include "framework_test_support.hpp"

namespace kinestat::framework {
namespace {

using testing::column_of;
using testing::load_example;
using testing::row_of;

void expect_proposal_repairs(const FrameworkModel& model, const FrameworkResult& a) {
  EXPECT_EQ(static_cast<Eigen::Index>(a.releases.size()), a.self_stresses);
  EXPECT_EQ(static_cast<Eigen::Index>(a.constrain.size()), a.mechanisms);
  const FrameworkResult repaired = analyse_framework(apply_proposal(model, a));
  EXPECT_TRUE(repaired.exactly_constrained());
  EXPECT_EQ(repaired.m, repaired.n);
  EXPECT_EQ(repaired.rank, repaired.m);
  EXPECT_TRUE(repaired.releases.empty());
  EXPECT_TRUE(repaired.constrain.empty());
}

TEST(StraightGuide, FiveWireFlexuresAreExactlyConstrained) {
  const FrameworkModel model = load_example("wire-flexure-guide.yaml");
  const FrameworkResult a = analyse_framework(model);
  // Rows: 5 wire elongations + 5 x 6 rigid-body constraints; columns: 5 of C + 5 x 6 of P1-P5.
  EXPECT_EQ(a.m, 35);
  EXPECT_EQ(a.n, 35);
  EXPECT_EQ(a.rank, 35);
  EXPECT_TRUE(a.exactly_constrained());
  EXPECT_EQ(a.count.declared_dof(), 1);
  EXPECT_EQ(a.count.grubler_dof(), 1);
  EXPECT_GT(a.relative_smallest_singular_value(), 1e-3);
  expect_proposal_repairs(model, a);
}

TEST(StraightGuide, WireFlexuresLeaveExactlyTheIntendedTranslation) {
  FrameworkModel model = load_example("wire-flexure-guide.yaml");
  model.nodes[0].roles[2] = CoordinateRole::dependent;  // C.z no longer declared
  ASSERT_EQ(model.nodes[0].name, "C");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 0);
  ASSERT_EQ(a.modes.size(), 1u);
  // The mode is a pure translation along z: every node's z rate equal, everything else zero.
  const Eigen::VectorXd& v = a.modes[0].velocities;
  for (Eigen::Index j = 0; j < a.n; ++j) {
    const std::string label = report::framework_column_label(model, a, j);
    const bool z = label.size() > 2 && label.substr(label.size() - 2) == ".z";
    EXPECT_NEAR(v(j), z ? 1.0 / std::sqrt(6.0) : 0.0, 1e-12) << label;
  }
}

TEST(StraightGuide, SingleFoldedSheetImposesOneConstraintAndHasOneInternalMode) {
  const FrameworkModel model = load_example("folded-sheet-flexure.yaml");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 6);   // elongation and in-plane bending of two sheets
  EXPECT_EQ(a.n, 12);  // F and B
  EXPECT_EQ(a.rank, 6);
  EXPECT_EQ(a.self_stresses, 0);
  EXPECT_EQ(a.mechanisms, 6);  // 5 motions of the free end + 1 internal mode
  // End motions allowed: the rates of B over all modes span 5 dimensions, and none moves the
  // fold line (through F, along z) attached to B along z: v_z + (ω × (F − B))_z = 0.
  const double length = a.length;
  Eigen::MatrixXd end(6, 6);
  const char* labels[] = {"B.x", "B.y", "B.z", "B.rx", "B.ry", "B.rz"};
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    for (int s = 0; s < 6; ++s) end(s, static_cast<Eigen::Index>(k)) = a.modes[k].velocities(column_of(model, a, labels[s]));
    const Eigen::Vector3d v = length * end.col(static_cast<Eigen::Index>(k)).head<3>();
    const Eigen::Vector3d w = end.col(static_cast<Eigen::Index>(k)).tail<3>();
    const Eigen::Vector3d f_minus_b(0, -20, 0);
    EXPECT_NEAR(v.z() + w.cross(f_minus_b).z(), 0.0, 1e-9) << k;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(end);
  EXPECT_GT(svd.singularValues()(4), 1e-6);
  EXPECT_LT(svd.singularValues()(5), 1e-12);
}

TEST(StraightGuide, DoubleClampedFoldedSheetHasInternalModeAndInPlaneBendingStress) {
  const FrameworkModel model = load_example("folded-sheet-double-clamped.yaml");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 6);
  EXPECT_EQ(a.n, 6);
  EXPECT_EQ(a.rank, 5);
  ASSERT_EQ(a.mechanisms, 1);
  ASSERT_EQ(a.self_stresses, 1);
  // Internal mode: F rotates about the fold line (z), nothing else moves.
  EXPECT_EQ(a.modes[0].moving, std::vector<Eigen::Index>{column_of(model, a, "F.rz")});
  // By hand (non-dimensional rows of s1 = A->F along x and s2 = F->B along y, local z = global z):
  // s1.elongation = vx, s1.bending_xz_p = -vz, s1.bending_xz_q = vz + ry, s2.elongation = -vy,
  // s2.bending_xz_p = vz + rx, s2.bending_xz_q = -vz; the only self-stress is in-plane bending at
  // the two clamped ends with opposite signs: (s1.bending_xz_p, s2.bending_xz_q) = (1, -1)/sqrt(2).
  const Eigen::VectorXd& s = a.stresses[0].resultants;
  const Eigen::Index p = row_of(model, a, "s1.bending_xz_p"), q = row_of(model, a, "s2.bending_xz_q");
  EXPECT_NEAR(std::abs(s(p)), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s(p), -s(q), 1e-12);
  EXPECT_NEAR(s.norm(), 1.0, 1e-12);
  EXPECT_EQ(a.stresses[0].candidates, (std::vector<Eigen::Index>{std::min(p, q), std::max(p, q)}));
  expect_proposal_repairs(model, a);
}

TEST(StraightGuide, FiveFoldedSheetFlexuresGiveSquareNonSingularJacobian) {
  const FrameworkModel model = load_example("folded-sheet-guide-5.yaml");
  const FrameworkResult a = analyse_framework(model);
  // Seed: "In each folded sheet flexure, there are six constrained deformations and one
  // independent deformation, so there are 35 rows in total" and 5 x 6 + 5 = 35 columns.
  EXPECT_EQ(a.m, 35);
  EXPECT_EQ(a.n, 35);
  EXPECT_EQ(a.count.fixed_deformations, 30);
  EXPECT_EQ(a.count.independent_deformations, 5);
  EXPECT_EQ(a.rank, 35);
  EXPECT_TRUE(a.exactly_constrained());
  EXPECT_GT(a.relative_smallest_singular_value(), 1e-3);
  expect_proposal_repairs(model, a);
}

TEST(StraightGuide, SymmetricFiveFlexureVariantIsUnderAndOverConstrained) {
  const FrameworkModel model = load_example("folded-sheet-guide-5-symmetric.yaml");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 35);
  EXPECT_EQ(a.n, 35);
  EXPECT_EQ(a.rank, 34);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 1);
  // The self-stress is carried by in-plane bending (bending_xz), never by elongation, and every
  // flexure takes part (the two parallel lower constraints balance the three upper ones).
  ASSERT_EQ(a.stresses.size(), 1u);
  const Eigen::VectorXd& s = a.stresses[0].resultants;
  for (int f = 1; f <= 5; ++f) {
    double bending = 0.0;
    for (const char* sheet : {".s1", ".s2"}) {
      const std::string element = "f" + std::to_string(f) + sheet;
      EXPECT_NEAR(s(row_of(model, a, element + ".elongation")), 0.0, 1e-9);
      bending += std::abs(s(row_of(model, a, element + ".bending_xz_p"))) + std::abs(s(row_of(model, a, element + ".bending_xz_q")));
    }
    EXPECT_GT(bending, 1e-3) << "flexure " << f;
  }
  expect_proposal_repairs(model, a);
}

TEST(StraightGuide, SixFoldedSheetFlexuresAreOverConstrainedWithBendingInAllSheets) {
  const FrameworkModel model = load_example("folded-sheet-guide-6.yaml");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 42);
  EXPECT_EQ(a.n, 41);
  EXPECT_EQ(a.rank, 41);
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.self_stresses, 1);
  EXPECT_EQ(report::framework_classification(a), "statically indeterminate, kinematically determinate");
  const Eigen::VectorXd& s = a.stresses[0].resultants;
  for (int f = 1; f <= 6; ++f) {
    for (const char* sheet : {".s1", ".s2"}) {
      const std::string element = "f" + std::to_string(f) + sheet;
      const double bending =
          std::abs(s(row_of(model, a, element + ".bending_xz_p"))) + std::abs(s(row_of(model, a, element + ".bending_xz_q")));
      EXPECT_GT(bending, 1e-3) << element;
    }
  }
  expect_proposal_repairs(model, a);
}

}  // namespace
}  // namespace kinestat::framework

namespace kinestat::framework {
namespace {

TEST(StraightGuide, PlanarParallelLeafSpringGuide) {
  // Two parallel planar leaf springs (bending released, elongation rigid) carry a rigid stage:
  // each spring is one constraint along itself, so the stage keeps one freedom, translation
  // along x. Rows: 2 elongations + 2 x 3 rigid-body coordinates; columns: C, D (3 each) and the
  // stage node S without its declared x: 8 x 8.
  const std::string text = R"(kinestat: 1
kind: framework
dimension: planar
nodes: {A: [0, 0], B: [2, 0], C: [0, 5], D: [2, 5], S: [1, 5]}
supports: {A: fixed, B: fixed}
independent: {S: [x]}
elements:
  - {type: beam, nodes: [A, C], released: [bending]}
  - {type: beam, nodes: [B, D], released: [bending]}
  - {name: stage, type: rigid_body, nodes: [S, C, D]}
)";
  FrameworkModel model = testing::parse_model(text);
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 8);
  EXPECT_EQ(a.n, 8);
  EXPECT_TRUE(a.exactly_constrained());
  model.nodes[4].roles[0] = CoordinateRole::dependent;
  const FrameworkResult free = analyse_framework(model);
  ASSERT_EQ(free.mechanisms, 1);
  for (Eigen::Index j = 0; j < free.n; ++j) {
    const std::string label = report::framework_column_label(model, free, j);
    const bool x = label.substr(label.size() - 2) == ".x";
    EXPECT_NEAR(free.modes[0].velocities(j), x ? 1.0 / std::sqrt(3.0) : 0.0, 1e-12) << label;
  }
}

}  // namespace
}  // namespace kinestat::framework
