// SPDX-License-Identifier: BSD-3-Clause
// Finite-motion tracing of coupling networks (issue 13, item 2). Every expected value comes from
// a closed form of the mechanism, derived in the comments, never from the program's output:
// Freudenstein's equation for the planar four-bar (analysed planar and in space), Bennett's
// relation tan(θ1/2) tan(θ2/2) = sin((β+α)/2) / sin((β−α)/2) with θ3 = −θ1, θ4 = −θ2, the
// spherical cosine law of the spherical four-bar's coupler, the two planar RRR legs of Sarrus'
// linkage, and the folded parallelogram (a change point) whose crank and rocker turn together.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <string>

#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/finite_motion.hpp"
#include "kinestat/network/second_order.hpp"
#include "seed_fixture.hpp"

namespace kinestat::network {
namespace {

constexpr double kPi = std::numbers::pi;

// The joint coordinate of the (single-magnitude) coupling `name` at point `k` of `trace`.
double joint(const Model& model, const NetworkResult& r, const NetworkTrace& trace, std::size_t k, const std::string& name) {
  for (std::size_t i = 0; i < r.motions.size(); ++i)
    if (model.couplings[static_cast<std::size_t>(r.motions[i].coupling)].name == name) return trace.coordinates[k](static_cast<Eigen::Index>(i));
  ADD_FAILURE() << "no coupling " << name;
  return 0.0;
}

// Traces primary motion 0 of an example with the defaults (0.1 of L in 20 steps) and checks
// what every finite motion must show: closed, 21 points, every residual below 1e-10, arc length
// 0.1 L reached (chords of the corrected points: at least the predicted 0.1, a little more on a
// curved path), the rank constant.
struct Traced {
  io::LoadedNetwork loaded;
  NetworkResult result;
  NetworkTrace trace;
};

Traced trace_example(const std::string& text_or_name, bool is_text = false, const Eigen::VectorXd* direction = nullptr) {
  Traced t{is_text ? testing::parse_network(text_or_name) : testing::load_example(text_or_name), {}, {}};
  t.result = analyse_network(t.loaded.model);
  const Eigen::VectorXd d = direction ? *direction : Eigen::VectorXd(t.result.motion_magnitudes.values.col(0));
  t.trace = trace_network_motion(t.loaded.model, t.result, d);
  return t;
}

void expect_closed_finite_path(const NetworkTrace& trace, Eigen::Index rank) {
  ASSERT_TRUE(trace.traced()) << trace_refusal_text(trace.refusal);
  EXPECT_TRUE(trace.closed);
  ASSERT_EQ(trace.coordinates.size(), 21u);
  EXPECT_LT(trace.max_residual, 1e-10);
  for (double residual : trace.residual_along_path) EXPECT_LT(residual, 1e-10);
  EXPECT_GE(trace.amplitude / trace.characteristic_length, 0.1 * (1 - 1e-9));
  EXPECT_LT(trace.amplitude / trace.characteristic_length, 0.101);
  for (Eigen::Index r : trace.rank_along_path) EXPECT_EQ(r, rank);
  EXPECT_TRUE(trace.rank_drops.empty());
}

// Planar four-bar A (0, 0), B (1, 2), C (4, 3), D (5, 0): crank a = |AB| = √5, coupler
// b = |BC| = √10, rocker c = |DC| = √10, ground d = |AD| = 5. With φ the crank angle at A and ψ
// the rocker angle at D (both from +x), Freudenstein's equation (Freudenstein 1955)
//     K1 cos ψ − K2 cos φ + K3 = cos(φ − ψ),  K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac)
// holds in every assembled position (at the start: φ0 = atan2(2, 1), ψ0 = atan2(3, −1), both
// sides 1/√2). Coupling A turns the crank relative to the ground (θA = φ − φ0); coupling D
// (from rocker to ground) turns the ground relative to the rocker (θD = −(ψ − ψ0)); the coupler
// BC turns by θA + θB, the angle of C′ − B′ with B′ = a(cos φ, sin φ), C′ = D + c(cos ψ, sin ψ).
void expect_four_bar_closed_forms(const Traced& t) {
  const double a = std::sqrt(5.0), b = std::sqrt(10.0), c = std::sqrt(10.0), d = 5.0;
  const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
  const double phi0 = std::atan2(2.0, 1.0), psi0 = std::atan2(3.0, -1.0), coupler0 = std::atan2(1.0, 3.0);
  const Model& m = t.loaded.model;
  for (std::size_t k = 0; k < t.trace.coordinates.size(); ++k) {
    const double phi = phi0 + joint(m, t.result, t.trace, k, "A");
    const double psi = psi0 - joint(m, t.result, t.trace, k, "D");
    EXPECT_NEAR(K1 * std::cos(psi) - K2 * std::cos(phi) + K3, std::cos(phi - psi), 1e-10) << "point " << k;
    const Eigen::Vector2d B(a * std::cos(phi), a * std::sin(phi)), C(d + c * std::cos(psi), c * std::sin(psi));
    EXPECT_NEAR((C - B).norm(), b, 1e-10);
    const double coupler = std::atan2(C.y() - B.y(), C.x() - B.x());
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "A") + joint(m, t.result, t.trace, k, "B"), coupler - coupler0, 1e-10);
    // The four relative rotations of a planar loop add up to nothing.
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "A") + joint(m, t.result, t.trace, k, "B") + joint(m, t.result, t.trace, k, "C") +
                    joint(m, t.result, t.trace, k, "D"),
                0.0, 1e-10);
  }
  // The crank did turn: 0.1 L of arc length is shared by four angles of one order of magnitude.
  EXPECT_GT(std::abs(joint(m, t.result, t.trace, 20, "A")), 0.01);
}

TEST(NetworkTrace, PlanarFourBarFollowsFreudensteinsEquation) {
  const Traced t = trace_example("four-bar-planar.yaml");
  // L: centroid (2.5, 1.25) of the pivots, largest coordinate distance |0 − 2.5| = 2.5.
  EXPECT_DOUBLE_EQ(t.trace.characteristic_length, 2.5);
  expect_closed_finite_path(t.trace, 3);  // 3 closure rows, all independent (CN = 0)
  expect_four_bar_closed_forms(t);
}

TEST(NetworkTrace, FourBarAnalysedInSpaceFollowsFreudensteinsEquation) {
  const Traced t = trace_example("four-bar-spatial.yaml");
  expect_closed_finite_path(t.trace, 3);  // planar twists: a 3-system at every position (CN = 3)
  expect_four_bar_closed_forms(t);
}

TEST(NetworkTrace, TheSameFourBarMovedAndInMillimetresGivesTheSameAngles) {
  // Placement and unit never change a rotation: the pivots × 1000, moved by (7000, −3000).
  const std::string text = "kinestat: 1\nkind: network\nname: moved\ndimension: planar\nground: ground\ncouplings:\n"
                           "  - {name: A, type: revolute, between: [ground, crank], point: [7000, -3000]}\n"
                           "  - {name: B, type: revolute, between: [crank, coupler], point: [8000, -1000]}\n"
                           "  - {name: C, type: revolute, between: [coupler, rocker], point: [11000, 0]}\n"
                           "  - {name: D, type: revolute, between: [rocker, ground], point: [12000, -3000]}\n";
  const Traced moved = trace_example(text, true);
  const Traced plain = trace_example("four-bar-planar.yaml");
  EXPECT_DOUBLE_EQ(moved.trace.characteristic_length, 2500.0);
  expect_closed_finite_path(moved.trace, 3);
  ASSERT_EQ(moved.trace.coordinates.size(), plain.trace.coordinates.size());
  const double sign = moved.result.motion_magnitudes.values.col(0).dot(plain.result.motion_magnitudes.values.col(0)) > 0 ? 1.0 : -1.0;
  for (std::size_t k = 0; k < plain.trace.coordinates.size(); ++k)
    EXPECT_LT((moved.trace.coordinates[k] - sign * plain.trace.coordinates[k]).norm(), 1e-9);
  EXPECT_NEAR(moved.trace.amplitude / 1000.0, plain.trace.amplitude, 1e-9);
}

// Bennett's linkage of examples/bennett.yaml (see examples/tools/bennett_geometry.py): the file
// axes are the Denavit–Hartenberg z axes z0..z3 and each coupling J_i turns link i relative to
// link i−1 about z_(i−1), so θ_i = θ_i0 + x_Ji with tan(θ10/2) = 2, tan(θ20/2) = 5/2,
// θ30 = −θ10, θ40 = −θ20. Bennett (1903): tan(θ1/2) tan(θ2/2) = sin((β+α)/2) / sin((β−α)/2)
// = (tan(β/2) + tan(α/2)) / (tan(β/2) − tan(α/2)) = (1/2 + 1/3) / (1/2 − 1/3) = 5, and θ3 = −θ1,
// θ4 = −θ2, so x_J3 = −x_J1 and x_J4 = −x_J2.
TEST(NetworkTrace, BennettKeepsBennettsRelation) {
  const Traced t = trace_example("bennett.yaml");
  expect_closed_finite_path(t.trace, 3);  // the four joint screws stay a 3-system (CN = 3)
  const double theta10 = 2 * std::atan(2.0), theta20 = 2 * std::atan(2.5);
  const Model& m = t.loaded.model;
  for (std::size_t k = 0; k < t.trace.coordinates.size(); ++k) {
    const double x1 = joint(m, t.result, t.trace, k, "J1"), x2 = joint(m, t.result, t.trace, k, "J2");
    EXPECT_NEAR(std::tan((theta10 + x1) / 2) * std::tan((theta20 + x2) / 2), 5.0, 1e-9) << "point " << k;
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "J3"), -x1, 1e-10);
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "J4"), -x2, 1e-10);
  }
  EXPECT_GT(std::abs(joint(m, t.result, t.trace, 20, "J1")), 0.01);
}

// Spherical four-bar of examples/spherical-4r.yaml: axes a = (2, 1, 0) (ground–input),
// b = (0, 2, 1) (input–coupler), c = (1, 0, 2) (coupler–output), d = (1, 1, 1) (output–ground)
// through one point. The input turns by x_A about a, carrying b; the output turns by −x_D about
// d (coupling D turns the ground relative to the output), carrying c; the coupler keeps the
// angle between b and c: R(a, x_A) b̂ · R(d, −x_D) ĉ = b̂ · ĉ = 2/5 — the spherical cosine law of
// the coupler's side.
TEST(NetworkTrace, SphericalFourBarKeepsItsCouplerArc) {
  const Traced t = trace_example("spherical-4r.yaml");
  expect_closed_finite_path(t.trace, 3);
  const Eigen::Vector3d a = Eigen::Vector3d(2, 1, 0).normalized(), b = Eigen::Vector3d(0, 2, 1).normalized();
  const Eigen::Vector3d c = Eigen::Vector3d(1, 0, 2).normalized(), d = Eigen::Vector3d(1, 1, 1).normalized();
  ASSERT_NEAR(b.dot(c), 0.4, 1e-15);
  const Model& m = t.loaded.model;
  for (std::size_t k = 0; k < t.trace.coordinates.size(); ++k) {
    const Eigen::Vector3d b_now = Eigen::AngleAxisd(joint(m, t.result, t.trace, k, "A"), a) * b;
    const Eigen::Vector3d c_now = Eigen::AngleAxisd(-joint(m, t.result, t.trace, k, "D"), d) * c;
    EXPECT_NEAR(b_now.dot(c_now), 0.4, 1e-10) << "point " << k;
  }
  EXPECT_GT(std::abs(joint(m, t.result, t.trace, 20, "A")), 0.01);
}

// Sarrus' linkage of examples/sarrus.yaml: the top plate translates along z to height h (2 at
// the start). Leg 1 (axes ∥ x, in the yz plane): A1 (0, 0, 0), B1 (0, y, h/2), C1 (0, 0, h) with
// |A1B1| = |B1C1| = √2, so y = √(2 − h²/4) and, angles about +x measured from +y towards +z,
// link 1a at atan2(h/2, y) (π/4 at the start), link 1b at atan2(h/2, −y) (3π/4). Leg 2 (axes ∥ y,
// in the xz plane): B2 − A2 = (x, 0, h/2), x = y, angles about +y measured from +z towards +x,
// link 2a at atan2(x, h/2) (π/4), link 2b at atan2(−x, h/2) (−π/4). Each coupling turns its `to`
// body relative to its `from` body; the top does not turn. h itself follows from x_A1:
// h/2 = √2 sin(π/4 + x_A1).
TEST(NetworkTrace, SarrusTopTranslatesAndItsLegsFollowTheirClosedForms) {
  const Traced t = trace_example("sarrus.yaml");
  expect_closed_finite_path(t.trace, 5);  // 6 joints, FN = 1: rank 5 all along
  const Model& m = t.loaded.model;
  for (std::size_t k = 0; k < t.trace.coordinates.size(); ++k) {
    const double half = std::sqrt(2.0) * std::sin(kPi / 4 + joint(m, t.result, t.trace, k, "A1"));
    const double y = std::sqrt(2.0 - half * half);
    const double l1a = std::atan2(half, y) - kPi / 4, l1b = std::atan2(half, -y) - 3 * kPi / 4;
    const double l2a = std::atan2(y, half) - kPi / 4, l2b = std::atan2(-y, half) + kPi / 4;
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "B1"), l1b - l1a, 1e-10) << "point " << k;
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "C1"), -l1b, 1e-10);
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "A2"), l2a, 1e-10);
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "B2"), l2b - l2a, 1e-10);
    EXPECT_NEAR(joint(m, t.result, t.trace, k, "C2"), -l2b, 1e-10);
  }
  EXPECT_GT(std::abs(joint(m, t.result, t.trace, 20, "A1")), 0.01);
}

// A Grashof-neutral parallelogram folded flat, the change point of the four-bar: A (0, 0),
// B (1, 0), C (3, 0), D (2, 0) — ground AD = 2, crank AB = 1, coupler BC = 2, rocker DC = 1, all
// collinear. By hand (planar twists (1; y, −x)): the four twists (1; 0, 0), (1; 0, −1),
// (1; 0, −3), (1; 0, −2) have rank 2, so FN = 2 and CN = 1 there; away from the flat position a
// four-bar has rank 3. The parallelogram branch — crank and rocker turning by φ together, the
// coupler translating: B = (cos φ, sin φ), C = (2 + cos φ, sin φ), |BC| = 2 — is
// x = φ (1, −1, 1, −1) exactly.
const char* kFoldedParallelogram = "kinestat: 1\nkind: network\nname: folded parallelogram\ndimension: planar\nground: ground\n"
                                   "couplings:\n"
                                   "  - {name: A, type: revolute, between: [ground, crank], point: [0, 0]}\n"
                                   "  - {name: B, type: revolute, between: [crank, coupler], point: [1, 0]}\n"
                                   "  - {name: C, type: revolute, between: [coupler, rocker], point: [3, 0]}\n"
                                   "  - {name: D, type: revolute, between: [rocker, ground], point: [2, 0]}\n";

TEST(NetworkTrace, FoldedParallelogramShowsTheRankDropAtTheStart) {
  const io::LoadedNetwork loaded = testing::parse_network(kFoldedParallelogram);
  const NetworkResult r = analyse_network(loaded.model);
  ASSERT_EQ(r.FN, 2);
  ASSERT_EQ(r.CN, 1);
  // The parallelogram branch in the magnitude order of the analysis (one per coupling, A..D).
  Eigen::VectorXd branch(4);
  for (std::size_t i = 0; i < 4; ++i) branch(static_cast<Eigen::Index>(i)) = (r.motions[i].coupling % 2 == 0) ? 1.0 : -1.0;
  const NetworkTrace trace = trace_network_motion(loaded.model, r, branch);
  ASSERT_TRUE(trace.traced());
  EXPECT_TRUE(trace.closed);
  EXPECT_LT(trace.max_residual, 1e-10);
  ASSERT_EQ(trace.rank_along_path.size(), 21u);
  EXPECT_EQ(trace.rank_along_path[0], 2);
  for (std::size_t k = 1; k < trace.rank_along_path.size(); ++k) EXPECT_EQ(trace.rank_along_path[k], 3) << "point " << k;
  ASSERT_EQ(trace.rank_drops.size(), 1u);
  EXPECT_EQ(trace.rank_drops[0], 0u);
  for (std::size_t k = 0; k < trace.coordinates.size(); ++k) {
    const double phi = joint(loaded.model, r, trace, k, "A");
    EXPECT_NEAR(joint(loaded.model, r, trace, k, "B"), -phi, 1e-12);
    EXPECT_NEAR(joint(loaded.model, r, trace, k, "C"), phi, 1e-12);
    EXPECT_NEAR(joint(loaded.model, r, trace, k, "D"), -phi, 1e-12);
    // Arc length in rad: |φ (1, −1, 1, −1)| = 2|φ|, L = 1.5 (centroid x = 1.5).
    EXPECT_NEAR(2 * std::abs(phi) * 1.5, trace.arc_length_along_path[k], 1e-12);
  }
}

// Three revolutes on one line (the docs' example, second_order_test.cpp by hand): blocked at
// second order, so it stays infinitesimal and is not traced; a trace forced along its
// first-order motion cannot close (the triangle's only position is the flat one).
TEST(NetworkTrace, ThreeRevolutesOnALineStayInfinitesimal) {
  const std::string text = "kinestat: 1\nkind: network\nname: flattened triangle\ndimension: planar\nground: ground\ncouplings:\n"
                           "  - {name: A, type: revolute, between: [ground, b1], point: [0, 0, 0], axis: [0, 0, 1]}\n"
                           "  - {name: B, type: revolute, between: [b1, b2], point: [1, 0, 0], axis: [0, 0, 1]}\n"
                           "  - {name: C, type: revolute, between: [b2, ground], point: [2, 0, 0], axis: [0, 0, 1]}\n";
  const io::LoadedNetwork loaded = testing::parse_network(text);
  const NetworkResult r = analyse_network(loaded.model);
  const NetworkSecondOrder s = classify_network_motions(loaded.model, r);
  ASSERT_EQ(s.motions.size(), 1u);
  EXPECT_EQ(s.motions[0].order, NetworkMotionOrder::infinitesimal);
  EXPECT_FALSE(s.motions[0].traced);
  const NetworkTrace forced = trace_network_motion(loaded.model, r, r.motion_magnitudes.values.col(0));
  ASSERT_TRUE(forced.traced());
  EXPECT_FALSE(forced.closed);
  EXPECT_EQ(forced.failed_step, 1u);
  EXPECT_GT(forced.max_residual, 1e-10);
}

// A circuit through a higher pair has no finite model here: not traced, and the reason names it.
TEST(NetworkTrace, HigherPairsAreNotTraced) {
  const std::string text = "kinestat: 1\nkind: network\nname: cam\ndimension: planar\nground: ground\ncouplings:\n"
                           "  - {name: A, type: revolute, between: [ground, crank], point: [0, 0]}\n"
                           "  - {name: B, type: revolute, between: [crank, follower], point: [1, 0]}\n"
                           "  - {name: K, type: point_on_line, between: [follower, ground], point: [2, 1], normal: [0, 1]}\n";
  const io::LoadedNetwork loaded = testing::parse_network(text);
  const NetworkResult r = analyse_network(loaded.model);
  ASSERT_GT(r.FN, 0);
  const NetworkTrace trace = trace_network_motion(loaded.model, r, r.motion_magnitudes.values.col(0));
  EXPECT_EQ(trace.refusal, TraceRefusal::unmodelled_coupling);
  ASSERT_EQ(trace.unmodelled_couplings.size(), 1u);
  EXPECT_EQ(trace.unmodelled_couplings[0], "K");
  EXPECT_TRUE(trace.coordinates.empty());
}

// Mechanisms known to move finitely (the examples of second_order_test.cpp) are now `finite`,
// each traced to 0.1 of its size with closure below 1e-10; the planar four-bar too (CN = 0).
TEST(NetworkTrace, MechanismsThatMoveFinitelyAreClassifiedFinite) {
  for (const char* name : {"four-bar-planar.yaml", "four-bar-spatial.yaml", "bennett.yaml", "sarrus.yaml", "spherical-4r.yaml",
                           "parallelogram-redundant.yaml", "davies-2-circuit.yaml"}) {
    SCOPED_TRACE(name);
    const io::LoadedNetwork loaded = testing::load_example(name);
    const NetworkResult r = analyse_network(loaded.model);
    const NetworkSecondOrder s = classify_network_motions(loaded.model, r);
    ASSERT_EQ(s.motions.size(), static_cast<std::size_t>(r.FN));
    for (const auto& m : s.motions) {
      EXPECT_EQ(m.order, NetworkMotionOrder::finite);
      EXPECT_EQ(m.reason, NetworkOrderReason::traced);
      ASSERT_TRUE(m.traced);
      EXPECT_TRUE(m.trace.closed);
      EXPECT_LT(m.trace.max_residual, 1e-10);
      EXPECT_GE(m.trace.amplitude / m.trace.characteristic_length, 0.1 * (1 - 1e-9));
    }
  }
}

TEST(NetworkTrace, TracingCanBeTurnedOff) {
  const io::LoadedNetwork loaded = testing::load_example("bennett.yaml");
  const NetworkResult r = analyse_network(loaded.model);
  NetworkSecondOrderOptions options;
  options.trace = false;
  const NetworkSecondOrder s = classify_network_motions(loaded.model, r, options);
  ASSERT_EQ(s.motions.size(), 1u);
  EXPECT_EQ(s.motions[0].order, NetworkMotionOrder::undetermined);
  EXPECT_EQ(s.motions[0].reason, NetworkOrderReason::passes_second_order);
  EXPECT_FALSE(s.motions[0].traced);
}

}  // namespace
}  // namespace kinestat::network
