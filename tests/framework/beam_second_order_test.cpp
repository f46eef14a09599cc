// SPDX-License-Identifier: BSD-3-Clause
// Second order and finite motion of frameworks with beams and rigid bodies (issue 13). The
// second derivatives of seed 002's deformations are checked against finite differences of the
// deformation functions along the motion they are defined on; the classifications against hand
// derivations written out above each test.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "framework_test_support.hpp"
#include "kinestat/framework/deformation_functions.hpp"
#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/second_order.hpp"

namespace kinestat::framework {
namespace {

using testing::column_of;
using testing::load_example;
using testing::parse_model;

Eigen::Matrix3d turned(const Eigen::Vector3d& omega, double t) {
  const double angle = omega.norm() * t;
  if (omega.norm() == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, omega.normalized()).toRotationMatrix();
}

// The beam after time t of the motion x + t ẋ, exp(t[ω]) triad at both ends.
BeamConfiguration moved(const BeamConfiguration& b, const NodeRates12& r, double t) {
  BeamConfiguration m = b;
  m.xp = b.xp + t * r.segment<3>(0);
  m.xq = b.xq + t * r.segment<3>(6);
  m.triad_p = turned(r.segment<3>(3), t) * b.triad_p;
  m.triad_q = turned(r.segment<3>(9), t) * b.triad_q;
  return m;
}

// Second derivative at t = 0 of f(t) by central differences with one Richardson step (error
// O(h⁴) plus rounding ≈ ε|f| / h²).
template <typename F>
auto second_difference(F f, double h) {
  auto central = [&](double step) { return ((f(step) - 2 * f(0.0) + f(-step)) / (step * step)).eval(); };
  return ((4 * central(h / 2) - central(h)) / 3).eval();
}

// A beam that is already deformed (triads not aligned with each other or with the chord), so
// that dε/dε̄ of eq (3) is not the identity, moving in a generic direction.
TEST(BeamSecondOrder, SecondDerivativesMatchFiniteDifferencesOfTheDeformations) {
  BeamConfiguration b;
  b.xp = Eigen::Vector3d(0.1, -0.2, 0.05);
  b.xq = Eigen::Vector3d(1.3, 0.25, -0.3);
  const Eigen::Vector3d x = (b.xq - b.xp).normalized();
  Eigen::Vector3d z = Eigen::Vector3d(0.2, 0.1, 1.0);
  z = (z - z.dot(x) * x).normalized();
  Eigen::Matrix3d triad;
  triad << x, z.cross(x), z;
  b.triad_p = turned(Eigen::Vector3d(0.03, -0.05, 0.02), 1.0) * triad;
  b.triad_q = turned(Eigen::Vector3d(-0.04, 0.02, 0.06), 1.0) * triad;
  b.l0 = 1.2;
  b.torsion_coupling = 0.07;
  NodeRates12 rates;
  rates << 0.3, -0.7, 0.2, 0.9, -0.4, 0.5, -0.6, 0.1, 0.8, -0.3, 0.7, 0.2;
  const Vector6 expected = second_difference([&](double t) { return beam_deformations(moved(b, rates, t)); }, 1e-3);
  const Vector6 analytic = beam_deformation_second_derivative(b, rates);
  EXPECT_LT((analytic - expected).norm(), 1e-7 * (1.0 + expected.norm())) << analytic.transpose() << "\n" << expected.transpose();
  const Vector6 basic_expected = second_difference([&](double t) { return beam_basic_deformations(moved(b, rates, t)); }, 1e-3);
  EXPECT_LT((beam_basic_second_derivative(b, rates) - basic_expected).norm(), 1e-7 * (1.0 + basic_expected.norm()));

  // A truss: (|Δẋ|² − (e·Δẋ)²)/l.
  const Eigen::Vector3d vp(0.3, -0.7, 0.2), vq(-0.6, 0.1, 0.8);
  const auto length = [&](double t) {
    Eigen::Matrix<double, 1, 1> l;
    l << truss_elongation(b.xp + t * vp, b.xq + t * vq, 1.0);
    return l;
  };
  EXPECT_NEAR(truss_elongation_second_derivative(b.xp, b.xq, vp, vq), second_difference(length, 1e-3)(0), 1e-7);
}

// The rigid link's relative coordinates along the motion: exp(−t[ω_r])(x_j − x_r) and the
// rotation vector of exp(−t[ω_r]) exp(t[ω_j]).
TEST(BeamSecondOrder, RigidLinkSecondDerivativeMatchesFiniteDifferences) {
  const Eigen::Vector3d xr(0.2, 0.4, -0.1), xj(1.1, -0.3, 0.6);
  NodeRates12 rates;
  rates << 0.3, -0.7, 0.2, 0.9, -0.4, 0.5, -0.6, 0.1, 0.8, -0.3, 0.7, 0.2;
  const auto relative = [&](double t) {
    const Eigen::Matrix3d back = turned(rates.segment<3>(3), t).transpose();
    const Eigen::AngleAxisd rotation(back * turned(rates.segment<3>(9), t));
    Vector6 g;
    g << back * ((xj + t * rates.segment<3>(6)) - (xr + t * rates.segment<3>(0))), rotation.angle() * rotation.axis();
    return g;
  };
  const Vector6 expected = second_difference(relative, 1e-3);
  EXPECT_LT((rigid_link_second_derivative(xr, xj, rates) - expected).norm(), 1e-7 * (1.0 + expected.norm()));
}

// Two collinear planar beams A–M–B (length 1, A and B clamped), bending released so that only
// the elongations are held: like the collinear two-bar, with M's rotation free as well. Modes:
// M.y and M.rz; self-stress: equal tension (1, 1)/√2. By hand (characteristic length 1, eq 3's
// ε1 = ε̄1 + (2ε̄5² + ε̄5ε̄6 + 2ε̄6²)/(30 l0) for the planar beam's bendings):
//   A–M: ε̄5′ = v, ε̄6′ = ω − v, ε̄1″ = v²;  M–B: ε̄5′ = −v − ω, ε̄6′ = v, ε̄1″ = v²,
// so Σ ε1″ = 2v² + (2/30)(6v² + 4ω²) = 2.4 v² + (4/15) ω² (the vω terms cancel). The tension's
// stiffness on (M.x, M.y, M.rz) is diag(0, 2.4, 4/15)/√2: positive definite on both modes, so
// the framework is prestress stable and both modes are infinitesimal.
TEST(BeamSecondOrder, CollinearBeamsWithReleasedBendingArePrestressStable) {
  const FrameworkModel model = parse_model(R"(kinestat: 1
kind: framework
dimension: planar
nodes: {A: [0, 0], M: [1, 0], B: [2, 0]}
supports: {A: fixed, B: fixed}
elements:
  - {name: a, type: beam, nodes: [A, M], released: [bending]}
  - {name: b, type: beam, nodes: [M, B], released: [bending]}
)");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 2);
  ASSERT_EQ(a.self_stresses, 1);
  const double s = 1 / std::sqrt(2.0);
  const Eigen::MatrixXd k = geometric_stiffness(model, a, Eigen::Vector2d(s, s));
  const Eigen::Index x = column_of(model, a, "M.x"), y = column_of(model, a, "M.y"), rz = column_of(model, a, "M.rz");
  EXPECT_NEAR(k(x, x), 0.0, 1e-12);
  EXPECT_NEAR(k(y, y), 2.4 * s, 1e-12);
  EXPECT_NEAR(k(rz, rz), 4.0 / 15 * s, 1e-12);
  EXPECT_NEAR(k(y, rz), 0.0, 1e-12);
  EXPECT_NEAR(k(x, y), 0.0, 1e-12);
  EXPECT_TRUE(a.prestress.stable);
  ASSERT_EQ(a.orders.size(), 2u);
  for (const ModeOrder& o : a.orders) {
    EXPECT_EQ(o.order, MotionOrder::infinitesimal);
    EXPECT_EQ(o.reason, OrderReason::prestress_stable);
  }
}

// Seed 002, Fig. 4(b): the double-clamped folded sheet A–F–B (sheets along x and y, both with
// local z = global z, in-plane bending `bending_xz` and elongation held). Its internal mode is F
// turning about the fold line z. Second order: turning F about z leaves every z axis in place,
// so the torsion rate ε̄2′ = 0 and the held in-plane bendings ε3, ε4 = ε̄3,4 ± ε̄2(ε̄5 + ε̄6)/(6 l0)
// have ε″ = 0; the self-stress (in-plane bending only) does no work: the mode passes. Finitely,
// F turns by θ about z and moves in the xy-plane: every sheet stays in its plane (torsion and
// in-plane bending stay 0) and the two held elongations ε1 = ε̄1 + (2ε̄5² + ε̄5ε̄6 + 2ε̄6²)/(30 l0)
// fix F's two in-plane coordinates. To second order ε̄6 = l0 θ in sheet 1 (A–F) and ε̄5 = −l0 θ in
// sheet 2 (F–B), so F moves by Δx = −l0 θ²/15 (sheet 1 shortens its chord) and Δy = +l0 θ²/15
// (sheet 2, from F to B along +y), and stays at z = 0: a finite motion.
TEST(BeamSecondOrder, FoldedSheetInternalModeMovesFinitely) {
  const FrameworkModel model = load_example("folded-sheet-double-clamped.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 1);
  ASSERT_EQ(a.orders.size(), 1u);
  const ModeOrder& o = a.orders[0];
  EXPECT_LT(o.second_order_work, 1e-12);
  EXPECT_EQ(o.order, MotionOrder::finite);
  EXPECT_EQ(o.reason, OrderReason::traced);
  ASSERT_TRUE(o.trace.closed);
  EXPECT_LT(o.trace.max_residual, 1e-10);
  EXPECT_TRUE(o.trace.rank_drops.empty());
  // The arc length is θ L (F's translation is of second order); compare F's position.
  const double l0 = 20.0;
  const double theta = o.trace.amplitude / a.length;
  EXPECT_NEAR(theta, 0.1, 2e-3);
  const Eigen::Vector3d f = o.trace.positions.back().col(1);
  EXPECT_NEAR(f.x() - 20.0, -l0 * theta * theta / 15, 2e-2 * l0 * theta * theta / 15);
  EXPECT_NEAR(f.y(), l0 * theta * theta / 15, 2e-2 * l0 * theta * theta / 15);
  EXPECT_NEAR(f.z(), 0.0, 1e-12);
}

// Seed 002, Fig. 5: five folded sheets, the two lower fold lines (F4, F5) both along x. Their
// two constraints on the body are parallel, hence dependent: one extra motion and one
// self-stress. The model is mirror-symmetric in x = 0 (F2 ↔ F3), and the extra motion is
// symmetric (C translates in y and turns about x). A turn about x maps the x direction onto
// itself, so along that motion both lower fold lines stay along x, their constraints stay
// parallel and the dependency persists: the motion is finite, D(c) keeps rank 34 along it, and
// the path stays in the mirror-symmetric configurations (C, F1, F4, F5 at x = 0; F3 the mirror
// image of F2).
TEST(BeamSecondOrder, FoldedSheetGuideOfFig5HasAFiniteExtraMotion) {
  const FrameworkModel model = load_example("folded-sheet-guide-5-symmetric.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 1);
  ASSERT_EQ(a.self_stresses, 1);
  ASSERT_EQ(a.orders.size(), 1u);
  const ModeOrder& o = a.orders[0];
  EXPECT_EQ(o.order, MotionOrder::finite);
  EXPECT_EQ(o.reason, OrderReason::traced);
  EXPECT_LT(o.trace.max_residual, 1e-10);
  EXPECT_NEAR(o.trace.amplitude, 0.1 * a.length, 1e-3 * a.length);
  for (const Eigen::Index rank : o.trace.rank_along_path) EXPECT_EQ(rank, 34);
  auto node = [&](const std::string& name) {
    for (std::size_t k = 0; k < model.nodes.size(); ++k)
      if (model.nodes[k].name == name) return static_cast<Eigen::Index>(k);
    return Eigen::Index{-1};
  };
  const Eigen::MatrixXd& end = o.trace.positions.back();
  EXPECT_GT((end - o.trace.positions.front()).norm(), 1.0);  // it did move (model size about 58)
  for (const char* name : {"C", "F1", "F4", "F5"}) EXPECT_NEAR(end(0, node(name)), 0.0, 1e-9) << name;
  const Eigen::Vector3d f2 = end.col(node("F2")), f3 = end.col(node("F3"));
  EXPECT_NEAR(f2.x(), -f3.x(), 1e-9);
  EXPECT_NEAR(f2.y(), f3.y(), 1e-9);
  EXPECT_NEAR(f2.z(), f3.z(), 1e-9);
}

}  // namespace
}  // namespace kinestat::framework
