// SPDX-License-Identifier: BSD-3-Clause
// Second-order classification of network motions (issue 13): the expected orders come from
// hand derivations (the collinear triangle below) and from mechanisms known to move finitely
// (a motion that exists finitely cannot be blocked at second order): the planar and spherical
// four-bars, the planar four-bar analysed in space, Bennett's linkage (Bennett 1903), Sarrus'
// linkage, the parallelogram with a redundant crank and the idle spins of Davies' network.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/second_order.hpp"
#include "seed_fixture.hpp"

namespace kinestat::network {
namespace {

// Ground, two bodies, three revolutes about z at (0,0), (1,0), (2,0): a triangle of links
// flattened onto one line. Hand derivation (planar twists (ω; p × ω) = (1; p_y, −p_x)):
// S_A = (1; 0, 0), S_B = (1; 0, −1), S_C = (1; 0, −2). Closure θ_A S_A + θ_B S_B + θ_C S_C = 0
// has rank 2: FN = 1 with θ′ = (1, −2, 1), CN = 1 with w = (0, 1, 0) (a force along the line).
// Second order: X_A = (1; 0, 0), X_B = (−2; 0, 2), X_C = (1; 0, −2) and, with
// [(ω₁; v₁), (ω₂; v₂)] = (0; ω₁ ẑ × v₂ − ω₂ ẑ × v₁), [X_A, X_B] = (0; −2, 0),
// [X_A, X_C] = (0; 2, 0), [X_B, X_C] = (0; −2, 0): the sum (0; −2, 0) has wᵀb = −2 ≠ 0, so the
// motion is blocked by the tension along the line — infinitesimal, like two collinear bars.
std::string collinear_triangle(const char* dimension) {
  return std::string("kinestat: 1\nkind: network\nname: flattened triangle\ndimension: ") + dimension +
         "\nground: ground\ncouplings:\n"
         "  - {name: A, type: revolute, between: [ground, b1], point: [0, 0, 0], axis: [0, 0, 1]}\n"
         "  - {name: B, type: revolute, between: [b1, b2], point: [1, 0, 0], axis: [0, 0, 1]}\n"
         "  - {name: C, type: revolute, between: [b2, ground], point: [2, 0, 0], axis: [0, 0, 1]}\n";
}

TEST(NetworkSecondOrder, CollinearTriangleIsInfinitesimal) {
  const io::LoadedNetwork loaded = testing::parse_network(collinear_triangle("planar"));
  const NetworkResult r = analyse_network(loaded.model);
  ASSERT_EQ(r.FN, 1);
  ASSERT_EQ(r.CN, 1);
  const NetworkSecondOrder s = classify_network_motions(loaded.model, r);
  ASSERT_EQ(s.motions.size(), 1u);
  EXPECT_EQ(s.motions[0].order, NetworkMotionOrder::infinitesimal);
  EXPECT_EQ(s.motions[0].reason, NetworkOrderReason::blocked_by_stress);
  EXPECT_GT(s.motions[0].second_order_work, 1e-3);
  // The blocking self-stress is w = (T; U, V) = (0, ±1, 0): the force along the line.
  ASSERT_EQ(s.motions[0].blocking_stress.size(), 3);
  EXPECT_NEAR(std::abs(s.motions[0].blocking_stress(1)), 1.0, 1e-9);
  EXPECT_NEAR(s.motions[0].blocking_stress(0), 0.0, 1e-9);
  EXPECT_NEAR(s.motions[0].blocking_stress(2), 0.0, 1e-9);
  EXPECT_TRUE(s.prestress_tested);
  EXPECT_TRUE(s.prestress_stable);  // one motion and a form that is not zero on it
}

TEST(NetworkSecondOrder, CollinearTriangleInSpaceIsInfinitesimal) {
  const io::LoadedNetwork loaded = testing::parse_network(collinear_triangle("spatial"));
  const NetworkResult r = analyse_network(loaded.model);
  ASSERT_EQ(r.FN, 1);
  ASSERT_EQ(r.CN, 4);  // the planar self-stress and the three out-of-plane ones (d·l − m = 6 − 2)
  const NetworkSecondOrder s = classify_network_motions(loaded.model, r);
  EXPECT_EQ(s.motions[0].order, NetworkMotionOrder::infinitesimal);
  ASSERT_EQ(s.motions[0].blocking_stress.size(), 6);
  // (R, S, T; U, V, W): the force along x through the origin.
  EXPECT_NEAR(std::abs(s.motions[0].blocking_stress(3)), 1.0, 1e-9);
}

TEST(NetworkSecondOrder, TheSameTriangleMovedAndScaledGivesTheSameVerdict) {
  // Placement and unit never change the order: the flattened triangle at x + 100, in mm.
  const std::string text = "kinestat: 1\nkind: network\nname: moved\ndimension: planar\nground: ground\ncouplings:\n"
                           "  - {name: A, type: revolute, between: [ground, b1], point: [100000, 5000, 0], axis: [0, 0, 1]}\n"
                           "  - {name: B, type: revolute, between: [b1, b2], point: [101000, 5000, 0], axis: [0, 0, 1]}\n"
                           "  - {name: C, type: revolute, between: [b2, ground], point: [102000, 5000, 0], axis: [0, 0, 1]}\n";
  const io::LoadedNetwork loaded = testing::parse_network(text);
  const NetworkResult r = analyse_network(loaded.model);
  const NetworkSecondOrder s = classify_network_motions(loaded.model, r);
  ASSERT_EQ(s.motions.size(), 1u);
  EXPECT_EQ(s.motions[0].order, NetworkMotionOrder::infinitesimal);
  // The force along the line y = 5000 has moment −5000 U about the origin: (T; U, V) ∝ (∓5000, ±1, 0).
  const Eigen::VectorXd w = s.motions[0].blocking_stress;
  EXPECT_NEAR(w(0) / w(1), -5000.0, 1e-6);
}

TEST(NetworkSecondOrder, MechanismsThatMoveFinitelyPassSecondOrder) {
  for (const char* name : {"four-bar-spatial.yaml", "bennett.yaml", "sarrus.yaml", "parallelogram-redundant.yaml", "spherical-4r.yaml",
                           "davies-2-circuit.yaml"}) {
    SCOPED_TRACE(name);
    const io::LoadedNetwork loaded = testing::load_example(name);
    const NetworkResult r = analyse_network(loaded.model);
    ASSERT_GT(r.FN, 0);
    ASSERT_GT(r.CN, 0);
    // Second order alone (tracing off): finite_motion_test.cpp checks that the traces close.
    NetworkSecondOrderOptions untraced;
    untraced.trace = false;
    const NetworkSecondOrder s = classify_network_motions(loaded.model, r, untraced);
    ASSERT_EQ(s.motions.size(), static_cast<std::size_t>(r.FN));
    EXPECT_TRUE(s.unmodelled_couplings.empty());
    for (const auto& m : s.motions) {
      EXPECT_EQ(m.order, NetworkMotionOrder::undetermined);
      EXPECT_EQ(m.reason, NetworkOrderReason::passes_second_order);
      EXPECT_LT(m.second_order_work, 1e-9);
    }
    EXPECT_FALSE(s.prestress_stable);
  }
}

TEST(NetworkSecondOrder, WithoutSelfStressNothingBlocks) {
  const io::LoadedNetwork loaded = testing::load_example("four-bar-planar.yaml");
  const NetworkResult r = analyse_network(loaded.model);
  ASSERT_EQ(r.CN, 0);
  NetworkSecondOrderOptions untraced;  // second order alone; traced, the motion is finite (finite_motion_test.cpp)
  untraced.trace = false;
  const NetworkSecondOrder s = classify_network_motions(loaded.model, r, untraced);
  ASSERT_EQ(s.motions.size(), 1u);
  EXPECT_EQ(s.motions[0].order, NetworkMotionOrder::undetermined);
  EXPECT_EQ(s.motions[0].reason, NetworkOrderReason::no_self_stress);
}

}  // namespace
}  // namespace kinestat::network
