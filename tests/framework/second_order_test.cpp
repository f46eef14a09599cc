// SPDX-License-Identifier: BSD-3-Clause
// Second-order classification and finite-motion tracing of bar frameworks (issue 13).
// Every expectation is derived by hand below (and was cross-checked with an independent numpy
// script that builds the rigidity matrix, its self-stresses and the stress matrix Σ ω_e |Δu_e|²
// from scratch); none is copied from kinestat's output.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "framework_test_support.hpp"
#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/second_order.hpp"

namespace kinestat::framework {
namespace {

using testing::column_of;
using testing::load_example;
using testing::parse_model;
using testing::row_of;

// Number of modes of each order.
std::size_t count(const FrameworkResult& a, MotionOrder order) {
  std::size_t k = 0;
  for (const ModeOrder& o : a.orders) k += o.order == order ? 1 : 0;
  return k;
}

// Two collinear bars A–C–B, A and B pinned, C free. The mode is C across the line (C.y); the
// self-stress is equal tension t in both bars. Moving C by y stretches each bar (length 1) by
// y²/2 at second order, so the tension does work t·y² > 0 on the mode: blocked at second order
// (the stress matrix is ω(|Δu_AC|² + |Δu_CB|²) = 2ω y² with ω = t / 1 > 0).
TEST(SecondOrder, CollinearTwoBarIsInfinitesimal) {
  const FrameworkModel model = load_example("pellegrino-calladine-two-bar.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.orders.size(), 1u);
  const ModeOrder& o = a.orders[0];
  EXPECT_EQ(o.order, MotionOrder::infinitesimal);
  EXPECT_EQ(o.reason, OrderReason::prestress_stable);
  EXPECT_TRUE(a.prestress.tested);
  EXPECT_TRUE(a.prestress.stable);
  EXPECT_TRUE(a.prestress.exhaustive);
  // The blocking stress: equal tension, 1/√2 in each bar (unit norm, positive = tension).
  ASSERT_EQ(o.blocking_stress.size(), 2);
  EXPECT_NEAR(o.blocking_stress(0), 1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(o.blocking_stress(1), 1 / std::sqrt(2.0), 1e-12);
  EXPECT_FALSE(o.traced);
}

// The same, checked on the quadratic form itself: the stress matrix of the tension (1, 1) on the
// column C.y is 1/l + 1/l = 2 (characteristic length 1, bars of length 1), and on C.x it is 0
// (a bar's Hessian has no component along the bar).
TEST(SecondOrder, StressMatrixOfTheTwoBarByHand) {
  const FrameworkModel model = load_example("pellegrino-calladine-two-bar.yaml");
  const FrameworkResult a = analyse_framework(model);
  const Eigen::MatrixXd k = geometric_stiffness(model, a, Eigen::Vector2d(1.0, 1.0));
  const Eigen::Index x = column_of(model, a, "C.x"), y = column_of(model, a, "C.y");
  EXPECT_NEAR(k(y, y), 2.0, 1e-12);
  EXPECT_NEAR(k(x, x), 0.0, 1e-12);
  EXPECT_NEAR(k(x, y), 0.0, 1e-12);
}

// A node on three coplanar bars in space (all supports in the plane z = 0): the node can move
// out of the plane to first order (one mode, X.z) and the three bars carry one self-stress, all
// in tension when the node lies inside the triangle of the supports (here it does). Each bar of
// length l_e lengthens by z²/(2 l_e): with tensions t_e > 0 the work Σ t_e z²/l_e is positive,
// so the mode is infinitesimal.
TEST(SecondOrder, NodeOnThreeCoplanarBarsIsInfinitesimal) {
  const FrameworkModel model = parse_model(R"(kinestat: 1
kind: framework
dimension: spatial
nodes: {X: [0, 0, 0], A: [1, 0, 0], B: [-0.5, 0.8, 0], C: [-0.5, -0.9, 0]}
supports: {A: fixed, B: fixed, C: fixed}
elements:
  - {type: truss, nodes: [X, A]}
  - {type: truss, nodes: [X, B]}
  - {type: truss, nodes: [X, C]}
)");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 1);
  ASSERT_EQ(a.self_stresses, 1);
  ASSERT_EQ(a.orders.size(), 1u);
  EXPECT_EQ(a.orders[0].order, MotionOrder::infinitesimal);
  // All three bars in tension in the blocking stress.
  for (Eigen::Index r = 0; r < 3; ++r) EXPECT_GT(a.orders[0].blocking_stress(r), 0.0);
}

// The simplex tensegrity at its 150° twist: 6 rigid motions plus one internal mode, one
// self-stress (struts compressed, cables in tension). With that sign the stress matrix is
// positive on the internal mode — the prism is prestress stable (Connelly & Whiteley 1996;
// Calladine 1978). The rigid motions are finite (the whole body moves).
TEST(SecondOrder, TensegrityPrismIsPrestressStable) {
  const FrameworkModel model = load_example("simplex-tensegrity.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 7);
  EXPECT_EQ(a.prestress.rigid_motions, 6);
  EXPECT_EQ(a.prestress.nonrigid_modes, 1);
  EXPECT_TRUE(a.prestress.stable);
  EXPECT_GT(a.prestress.smallest_eigenvalue, 1e-3);
  // The stress that stabilises: struts (elements 1-3) compressed, cables (4-12) in tension.
  for (Eigen::Index r = 0; r < 3; ++r) EXPECT_LT(a.prestress.stress(r), 0.0);
  for (Eigen::Index r = 3; r < 12; ++r) EXPECT_GT(a.prestress.stress(r), 0.0);
  // Every mode with an internal component is infinitesimal; the echelon basis mixes the
  // internal mode into several basis vectors, so only counts of at least one are asserted.
  EXPECT_GE(count(a, MotionOrder::infinitesimal), 1u);
  EXPECT_EQ(count(a, MotionOrder::undetermined), 0u);
}

// The rigid motions of a free model span 6 dimensions in space, 3 in the plane; a model with
// a pinned node and a roller keeps none.
TEST(SecondOrder, RigidMotionsOfFreeAndSupportedModels) {
  const FrameworkModel octahedron = load_example("octahedron.yaml");
  EXPECT_EQ(rigid_motions(octahedron, analyse_framework(octahedron)).cols(), 6);
  const FrameworkModel braced = load_example("braced-square.yaml");
  EXPECT_EQ(rigid_motions(braced, analyse_framework(braced)).cols(), 0);
  // The octahedron is rigid (Cauchy): its six modes are all rigid motions, hence finite.
  const FrameworkResult a = analyse_framework(octahedron);
  EXPECT_EQ(count(a, MotionOrder::finite), 6u);
  for (const ModeOrder& o : a.orders) EXPECT_EQ(o.reason, OrderReason::rigid_motion);
}

// Seed 002's twelve trusses: one mode and one self-stress (all normal forces ±√3/6). The mode
// moves E, F, G, H tangentially; every bar to the supports turns about its support, and the top
// square turns rigidly about its centre to first order, so the Δu of each bar is perpendicular
// to it with |Δu| equal on the eight side bars (length √2) and on the four top bars (length
// √2): the work Σ σ_e |Δu_e|²/l_e has four side bars of each sign and two top bars of each sign
// at equal magnitudes, hence zero — the mode passes second order. The motion is the finite
// twist of the top square (the top square rotates about z and drops), so the trace closes.
TEST(SecondOrder, TwelveTrussesMoveFinitely) {
  const FrameworkModel model = load_example("truss-12.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.orders.size(), 1u);
  const ModeOrder& o = a.orders[0];
  EXPECT_LT(o.second_order_work, kSecondOrderWorkZero);
  EXPECT_FALSE(a.prestress.stable);
  ASSERT_TRUE(o.traced);
  EXPECT_EQ(o.order, MotionOrder::finite);
  EXPECT_EQ(o.reason, OrderReason::traced);
  EXPECT_LT(o.trace.max_residual, 1e-10);
  // Traced over 0.1 of the model's size (characteristic length √2·... the radius of the nodes).
  EXPECT_GE(o.trace.amplitude, 0.1 * a.length * (1 - 1e-6));
  // Bar lengths kept at every traced point (measured here from the positions).
  for (const Eigen::MatrixXd& p : o.trace.positions)
    for (const Element& e : model.elements) {
      const double l0 = (model.nodes[e.nodes[1]].position - model.nodes[e.nodes[0]].position).norm();
      EXPECT_NEAR((p.col(static_cast<Eigen::Index>(e.nodes[1])) - p.col(static_cast<Eigen::Index>(e.nodes[0]))).norm(), l0, 1e-10);
    }
  // The supports do not move; the top nodes do (by more than rounding).
  const Eigen::MatrixXd& last = o.trace.positions.back();
  EXPECT_EQ(last.col(0), model.nodes[0].position);
  EXPECT_GT((last.col(4) - model.nodes[4].position).norm(), 1e-3);
}

// Bricard's line-symmetric octahedron: 6 rigid motions + 1 flex, 1 self-stress; the flex is
// finite (Bricard 1897), so it must pass second order and trace with closure.
TEST(SecondOrder, BricardOctahedronFlexesFinitely) {
  const FrameworkModel model = load_example("bricard-octahedron.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 7);
  ASSERT_EQ(a.self_stresses, 1);
  EXPECT_EQ(a.prestress.nonrigid_modes, 1);
  EXPECT_FALSE(a.prestress.stable);
  std::size_t traced = 0;
  for (const ModeOrder& o : a.orders) {
    EXPECT_EQ(o.order, MotionOrder::finite);
    if (!o.traced) continue;
    ++traced;
    EXPECT_LT(o.trace.max_residual, 1e-10);
    EXPECT_GE(o.trace.amplitude, 0.1 * a.length * (1 - 1e-6));
  }
  EXPECT_GE(traced, 1u);
}

// Every mode of the free Bricard octahedron, not only the flex: each is a combination of the
// six rigid motions and the flex, all finite, so each must trace through 0.1 L with every
// bar length kept (measured here from the positions) and D(c) at rank 18 - 7 = 11 all along
// (a rank of 12 anywhere would leave only the rigid motions). Off the path the self-stress's
// dependent row turns independent with a tiny singular value; the corrector lost closure at
// steps 4-18 on six of the seven modes until it kept the path's rank.
TEST(SecondOrder, BricardOctahedronEveryModeTracesWithTheRankOfThePath) {
  const FrameworkModel model = load_example("bricard-octahedron.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.modes.size(), 7u);
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    SCOPED_TRACE("mode " + std::to_string(k + 1));
    const FiniteTrace trace = trace_motion(model, a, a.modes[k].velocities);
    EXPECT_TRUE(trace.closed);
    EXPECT_GE(trace.amplitude, 0.1 * a.length * (1 - 1e-6));
    for (Eigen::Index r : trace.rank_along_path) EXPECT_EQ(r, 11);
    for (const Eigen::MatrixXd& p : trace.positions)
      for (const Element& e : model.elements) {
        const double l0 = (model.nodes[e.nodes[1]].position - model.nodes[e.nodes[0]].position).norm();
        EXPECT_NEAR((p.col(static_cast<Eigen::Index>(e.nodes[1])) - p.col(static_cast<Eigen::Index>(e.nodes[0]))).norm(), l0, 1e-10);
      }
  }
}

// The planar four-bar (no self-stress): nothing can block it at second order; a four-bar away
// from its change points moves finitely, with the rank of D(c) constant (3) along the path.
TEST(SecondOrder, FourBarMovesFinitelyWithConstantRank) {
  const FrameworkModel model = load_example("four-bar-linkage.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.orders.size(), 1u);
  EXPECT_EQ(a.orders[0].order, MotionOrder::finite);
  EXPECT_FALSE(a.prestress.tested);  // no self-stress to test
  for (Eigen::Index r : a.orders[0].trace.rank_along_path) EXPECT_EQ(r, 3);
  EXPECT_TRUE(a.orders[0].trace.rank_drops.empty());
}

// A four-bar at its change point, all links collinear: ground A(0,0)–D(2,0), crank AB = 1,
// coupler BC = 2, rocker DC = 1, with B(1,0) and C(3,0). The three bars all lie along x, so
// D(c) has rank 2 (BC's row is the difference of the others): two modes (B.y, C.y) and one
// self-stress, force densities ω = (1, 1/2, −1) on AB, BC, CD by equilibrium of B and C.
// The stress matrix on (b, c) = (B.y, C.y) is b² + ½(c − b)² − c² = 1.5b² − bc − 0.5c²,
// indefinite (not prestress stable) with zeros along b = c (the parallelogram branch) and
// c = −3b (the other branch). Along b = c the linkage stays a parallelogram (crank angle θ:
// B = (cos θ, sin θ), C = (2 + cos θ, sin θ)) and D(c) has rank 3 off the line: the trace shows
// the rank drop at the start.
TEST(SecondOrder, FourBarChangePointShowsRankDropAtStart) {
  const FrameworkModel model = parse_model(R"(kinestat: 1
kind: framework
dimension: planar
nodes: {A: [0, 0], B: [1, 0], C: [3, 0], D: [2, 0]}
supports: {A: fixed, D: fixed}
elements:
  - {type: truss, nodes: [A, B]}
  - {type: truss, nodes: [B, C]}
  - {type: truss, nodes: [C, D]}
)");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 2);
  ASSERT_EQ(a.self_stresses, 1);
  EXPECT_TRUE(a.prestress.tested);
  EXPECT_FALSE(a.prestress.stable);
  // B.y alone: 1.5 > 0, blocked; C.y alone: −0.5, blocked (by the opposite stress).
  for (const ModeOrder& o : a.orders) {
    EXPECT_EQ(o.order, MotionOrder::infinitesimal);
    EXPECT_EQ(o.reason, OrderReason::blocked_by_stress);
  }
  // The parallelogram branch b = c.
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(a.n);
  direction(column_of(model, a, "B.y")) = 1.0;
  direction(column_of(model, a, "C.y")) = 1.0;
  const FiniteTrace trace = trace_motion(model, a, direction);
  EXPECT_TRUE(trace.closed);
  EXPECT_LT(trace.max_residual, 1e-10);
  ASSERT_EQ(trace.rank_along_path.size(), 21u);
  EXPECT_EQ(trace.rank_along_path.front(), 2);
  for (std::size_t k = 1; k < trace.rank_along_path.size(); ++k) EXPECT_EQ(trace.rank_along_path[k], 3);
  ASSERT_EQ(trace.rank_drops.size(), 1u);
  EXPECT_EQ(trace.rank_drops[0], 0u);
  // Still a parallelogram at the end: B and C at the same height, C − B = (2, 0).
  const Eigen::MatrixXd& end = trace.positions.back();
  EXPECT_NEAR((end.col(2) - end.col(1) - Eigen::Vector3d(2, 0, 0)).norm(), 0.0, 1e-9);
  // A direction off both branches (B.y alone) cannot be followed: the corrector loses closure.
  Eigen::VectorXd off = Eigen::VectorXd::Zero(a.n);
  off(column_of(model, a, "B.y")) = 1.0;
  EXPECT_FALSE(trace_motion(model, a, off).closed);
}

// Results do not depend on units or placement: the twelve trusses scaled by 1000 and moved
// rigidly classify the same, with the same relative residual scale.
TEST(SecondOrder, InvariantUnderScalingAndRigidMotion) {
  const FrameworkModel model = load_example("truss-12.yaml");
  const FrameworkModel moved = testing::transformed(model, testing::generic_rotation(), Eigen::Vector3d(3, -2, 7), 1000.0);
  const FrameworkResult a = analyse_framework(moved);
  ASSERT_EQ(a.orders.size(), 1u);
  EXPECT_EQ(a.orders[0].order, MotionOrder::finite);
  EXPECT_LT(a.orders[0].trace.max_residual, 1e-10);
  // (No rotation here: a rotated copy of exactly collinear bars is collinear only to rounding,
  // which the first-order rank already resolves as rigid.)
  const FrameworkModel two_bar = testing::transformed(load_example("pellegrino-calladine-two-bar.yaml"),
                                                      Eigen::Matrix3d::Identity(), Eigen::Vector3d(5, 1, 0), 0.001);
  const FrameworkResult b = analyse_framework(two_bar);
  ASSERT_EQ(b.mechanisms, 1);
  ASSERT_EQ(b.orders.size(), 1u);
  EXPECT_EQ(b.orders[0].order, MotionOrder::infinitesimal);
}

}  // namespace
}  // namespace kinestat::framework
