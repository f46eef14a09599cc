// SPDX-License-Identifier: BSD-3-Clause
// Numerically hard frameworks: exactly singular geometry given in floating point, nearly
// singular geometry, and one model with element lengths of 1e3 and 1e-6. Each expected answer
// is derived by hand in the test's comment, not from the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "framework/framework_test_support.hpp"
#include "kinestat/framework/framework_analysis.hpp"

namespace kinestat::framework {
namespace {

constexpr double kAngle = 37.0 * std::numbers::pi / 180.0;  // no special angle: cos, sin are rounded

// Two bars A-C-B between fixed supports, along the direction at kAngle, with C moved across
// the line by `offset` (a fraction of the bar length); `length` is the bar length.
FrameworkModel two_bars(double offset, double length) {
  const double c = std::cos(kAngle), s = std::sin(kAngle);
  return testing::parse_model(fmt::format(
      "kinestat: 1\nkind: framework\ndimension: planar\n"
      "nodes: {{A: [0, 0], C: [{:.17g}, {:.17g}], B: [{:.17g}, {:.17g}]}}\n"
      "supports: {{A: fixed, B: fixed}}\n"
      "elements: [{{type: truss, nodes: [A, C]}}, {{type: truss, nodes: [C, B]}}]\n",
      length * (c - offset * s), length * (s + offset * c), 2 * length * c, 2 * length * s));
}

TEST(FrameworkHardCases, CollinearBarsFromTrigonometricValues) {
  // The rows of D(c) are the bars' unit vectors at C, e and -e: rank 1 exactly, so one
  // mechanism (C moves across the line, along (-sin, cos)) and one self-stress (equal tension,
  // u1 e - u2 e = 0). In floating point the second singular value is rounding noise.
  for (double length : {1.0, 1e-3, 1e3}) {
    const FrameworkResult a = analyse_framework(two_bars(0.0, length));
    ASSERT_EQ(a.rank, 1) << length;
    EXPECT_EQ(a.mechanisms, 1);
    EXPECT_EQ(a.self_stresses, 1);
    EXPECT_FALSE(a.decision.close());
    EXPECT_GT(a.decision.gap(), 1e12);
    ASSERT_EQ(a.modes.size(), 1u);
    const Eigen::Vector2d across(-std::sin(kAngle), std::cos(kAngle));
    EXPECT_NEAR(std::abs(a.modes[0].velocities.head<2>().dot(across)), 1.0, 1e-12);
    ASSERT_EQ(a.stresses.size(), 1u);
    EXPECT_NEAR(a.stresses[0].resultants(0), std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(a.stresses[0].resultants(1), std::sqrt(0.5), 1e-12);
  }
}

TEST(FrameworkHardCases, NearlyCollinearBarsAreReportedAsClose) {
  // C off the line by delta (relative): the unit vectors differ in angle by 2 delta, so the
  // singular values are sqrt(1 +- cos 2 delta) and their ratio is tan(delta).
  const FrameworkResult a = analyse_framework(two_bars(1e-9, 1.0));
  EXPECT_EQ(a.rank, 2);  // the default tolerance (2 eps) keeps it: exactly constrained ...
  EXPECT_TRUE(a.exactly_constrained());
  // ... with certainty (tan 1e-9 is far above the error bound, ~10 ε), and says how near it is.
  EXPECT_EQ(a.decision.status(), linalg::RankStatus::certain);
  EXPECT_NEAR(*a.decision.distance(), std::tan(1e-9), 1e-11);
  EXPECT_NEAR(a.relative_smallest_singular_value(), std::tan(1e-9), 1e-11);

  AnalysisOptions loose;
  loose.tolerances = Tolerances::with_rank(1e-8);  // a user's tolerance above tan(delta) drops it
  const FrameworkResult b = analyse_framework(two_bars(1e-9, 1.0), loose);
  EXPECT_EQ(b.rank, 1);
  EXPECT_TRUE(b.decision.close());

  const FrameworkResult c = analyse_framework(two_bars(1e-6, 1.0));  // far from the threshold
  EXPECT_EQ(c.rank, 2);
  EXPECT_FALSE(c.decision.close());
}

// A cantilever of two beams in line: A (fixed) to B is 1e3 long, B to C is 1e-6 long.
std::string cantilever(double scale) {
  return fmt::format(
      "kinestat: 1\nkind: framework\ndimension: planar\n"
      "nodes: {{A: [0, 0], B: [{:.17g}, 0], C: [{:.17g}, {:.17g}]}}\n"
      "supports: {{A: fixed}}\n"
      "elements: [{{type: beam, nodes: [A, B]}}, {{type: beam, nodes: [B, C]}}]\n",
      1e3 * scale, 1e3 * scale, 1e-6 * scale);
}

TEST(FrameworkHardCases, CantileverWithLengthsOf1e3And1eMinus6) {
  // Statically determinate: each beam's three deformations fix the three coordinates of its
  // free end given the other, so D(c) is 6 x 6 and non-singular whatever the lengths. Scaled
  // by one characteristic length only, the short beam's rotation column is 1e-9 of the rest
  // and the design looked near-singular; scaled by element lengths it is well conditioned.
  const FrameworkModel model = testing::parse_model(cantilever(1.0));
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 6);
  EXPECT_EQ(a.n, 6);
  EXPECT_EQ(a.rank, 6);
  EXPECT_TRUE(a.exactly_constrained());
  EXPECT_FALSE(a.decision.close());
  EXPECT_GT(a.relative_smallest_singular_value(), 1e-2);
  // In metres instead of millimetres, and turned: the same singular values.
  const FrameworkResult metres = analyse_framework(testing::parse_model(cantilever(1e-3)));
  const FrameworkResult turned =
      analyse_framework(testing::transformed(model, testing::planar_rotation(), Eigen::Vector3d(5, -2, 0), 1.0));
  for (const FrameworkResult* other : {&metres, &turned}) {
    ASSERT_EQ(other->singular_values.size(), a.singular_values.size());
    for (Eigen::Index i = 0; i < a.singular_values.size(); ++i)
      EXPECT_NEAR(other->singular_values(i), a.singular_values(i), 1e-9 * a.singular_values(0));
  }
}

TEST(FrameworkHardCases, ScalingByLengthsDoesNotHideASingularTinyPart) {
  // The collinear two-bar at a size of 1e-6 beside a 1e3 cantilever beam: the scaling comes
  // from lengths, not from the values of D(c), so the two-bar's rounding-level singular value
  // stays negligible. Columns: C (2) + G (3); rows: 2 bars + 3 beam deformations; rank 1 + 3:
  // one mechanism and one self-stress, both in the two-bar.
  const double c = std::cos(kAngle), s = std::sin(kAngle);
  const FrameworkModel model = testing::parse_model(fmt::format(
      "kinestat: 1\nkind: framework\ndimension: planar\n"
      "nodes: {{A: [0, 0], C: [{:.17g}, {:.17g}], B: [{:.17g}, {:.17g}], F: [0, 10], G: [1000, 10]}}\n"
      "supports: {{A: fixed, B: fixed, F: fixed}}\n"
      "elements: [{{type: truss, nodes: [A, C]}}, {{type: truss, nodes: [C, B]}}, {{type: beam, nodes: [F, G]}}]\n",
      1e-6 * c, 1e-6 * s, 2e-6 * c, 2e-6 * s));
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.n, 5);
  EXPECT_EQ(a.m, 5);
  EXPECT_EQ(a.rank, 4);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 1);
  EXPECT_FALSE(a.decision.close());
}

}  // namespace
}  // namespace kinestat::framework
