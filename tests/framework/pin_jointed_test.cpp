// SPDX-License-Identifier: BSD-3-Clause
// Pin-jointed frameworks with known counts of mechanisms m and self-stresses s (Pellegrino &
// Calladine 1986 and textbook cases). Each expectation comes from Maxwell's rule
// s − m = b − (d·j − k) plus the specific geometry, as explained in each example file.
// Here m counts every kinematically indeterminate mode, rigid-body motions included.

#include <gtest/gtest.h>

#include <cmath>

#include "framework_test_support.hpp"

namespace kinestat::framework {
namespace {

using testing::load_example;

struct Case {
  const char* file;
  Eigen::Index bars, free_coordinates, mechanisms, self_stresses;
};

class PinJointed : public ::testing::TestWithParam<Case> {};

TEST_P(PinJointed, CountsFollowMaxwellAndGeometry) {
  const Case c = GetParam();
  const FrameworkModel model = load_example(c.file);
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, c.bars);
  EXPECT_EQ(a.n, c.free_coordinates);
  EXPECT_EQ(a.mechanisms, c.mechanisms);
  EXPECT_EQ(a.self_stresses, c.self_stresses);
  // Maxwell's rule in the form s − m = b − (d j − k).
  EXPECT_EQ(a.self_stresses - a.mechanisms, c.bars - c.free_coordinates);
  EXPECT_EQ(static_cast<Eigen::Index>(a.modes.size()), c.mechanisms);
  EXPECT_EQ(static_cast<Eigen::Index>(a.stresses.size()), c.self_stresses);
  for (const auto& mode : a.modes) EXPECT_NEAR(mode.velocities.norm(), 1.0, 1e-12);
  for (const auto& state : a.stresses) EXPECT_NEAR(state.resultants.norm(), 1.0, 1e-12);
  if (c.mechanisms > 0 || c.self_stresses > 0) {
    const FrameworkResult repaired = analyse_framework(apply_proposal(model, a));
    EXPECT_TRUE(repaired.exactly_constrained());
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, PinJointed,
                         ::testing::Values(Case{"truss-12.yaml", 12, 12, 1, 1},
                                           Case{"pellegrino-calladine-two-bar.yaml", 2, 2, 1, 1},
                                           Case{"braced-square.yaml", 6, 5, 0, 1},
                                           Case{"four-bar-linkage.yaml", 3, 4, 1, 0},
                                           Case{"octahedron.yaml", 12, 18, 6, 0},
                                           Case{"cube-frame.yaml", 12, 24, 12, 0},
                                           Case{"simplex-tensegrity.yaml", 12, 18, 7, 1}));

TEST(PinJointed, TwoBarMechanismIsTheMiddleJointMovingAcross) {
  const FrameworkModel model = load_example("pellegrino-calladine-two-bar.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.modes.size(), 1u);
  EXPECT_EQ(a.modes[0].moving, std::vector<Eigen::Index>{testing::column_of(model, a, "C.y")});
  // Equal tension in both bars.
  EXPECT_NEAR(a.stresses[0].resultants(0), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(a.stresses[0].resultants(1), std::sqrt(0.5), 1e-12);
}

TEST(PinJointed, BracedSquareSelfStressIsTheClassicPattern) {
  // Sides in compression, diagonals in tension (or the reverse) with |N_diagonal| = sqrt(2)|N_side|:
  // normalised, sides ±1/sqrt(8), diagonals ∓1/2.
  const FrameworkResult a = analyse_framework(load_example("braced-square.yaml"));
  ASSERT_EQ(a.stresses.size(), 1u);
  const Eigen::VectorXd& s = a.stresses[0].resultants;
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(s(i), -s(4) / std::sqrt(2.0), 1e-12) << i;
  EXPECT_NEAR(std::abs(s(4)), 0.5, 1e-12);
  EXPECT_NEAR(s(5), s(4), 1e-12);
}

TEST(PinJointed, SimplexAtAGenericTwistHasNoSelfStress) {
  // Rotating the top triangle away from the 150-degree twist removes the self-stress and the
  // infinitesimal mechanism: only the 6 rigid-body motions remain (Maxwell: s - m = -6).
  FrameworkModel model = load_example("simplex-tensegrity.yaml");
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(-0.35, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (Node& node : model.nodes)
    if (node.name[0] == 'T') node.position = turn * node.position;
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.self_stresses, 0);
  EXPECT_EQ(a.mechanisms, 6);
}

TEST(PinJointed, OctahedronMechanismsAreRigidBodyMotions) {
  // Each mode must be a rigid motion: for every bar, (v_q - v_p)·(x_q - x_p) = 0 trivially, so
  // test more: the 6 modes span the same space as the 6 rigid-body velocity fields.
  const FrameworkModel model = load_example("octahedron.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.modes.size(), 6u);
  Eigen::MatrixXd rigid(18, 6);
  for (int k = 0; k < 6; ++k) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
      const Eigen::Vector3d x = model.nodes[n].position;
      const Eigen::Vector3d v = k < 3 ? Eigen::Vector3d(Eigen::Vector3d::Unit(k)) : Eigen::Vector3d(Eigen::Vector3d::Unit(k - 3).cross(x));
      rigid.block<3, 1>(static_cast<Eigen::Index>(3 * n), k) = v;
    }
  }
  Eigen::MatrixXd modes(18, 6);
  for (int k = 0; k < 6; ++k) modes.col(k) = a.modes[static_cast<std::size_t>(k)].velocities;
  Eigen::MatrixXd both(18, 12);
  both << rigid, modes;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(both);
  EXPECT_LT(svd.singularValues()(6), 1e-10);  // rank 6: the same space
}

}  // namespace
}  // namespace kinestat::framework
