// SPDX-License-Identifier: BSD-3-Clause
// Numerically hard coupling networks (issue: robustness): exactly singular geometry given in
// floating point, nearly singular geometry, ill-scaled models and decisions near the
// tolerance. Expected answers come from the geometry, not from the program.
#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/network/analyse_network.hpp"

namespace kinestat::network {
namespace {

using screw::Rational;
using screw::Vec3;

Coupling revolute(const std::string& name, int from, int to, const Vec3& point, const Vec3& axis) {
  Coupling c;
  c.name = name;
  c.type = screw::CouplingType::revolute;
  c.from = from;
  c.to = to;
  c.geometry.point = point;
  c.geometry.axis = axis;
  return c;
}

Vec3 exact(double x, double y, double z) { return {Rational(x), Rational(y), Rational(z)}; }

// Bennett linkage from Denavit-Hartenberg parameters in double precision (T = Rz(theta)
// Tx(a) Rx(alpha)): twists 30 and 60 degrees, a / sin(alpha) = b / sin(beta), closure
// tan(theta2 / 2) = sin((beta + alpha) / 2) / sin((beta - alpha) / 2) / tan(theta1 / 2),
// theta3 = -theta1, theta4 = -theta2 (Bennett 1903). Mobility 1 although Grubler-Kutzbach
// gives 6 (4 - 1 - 4) + 4 = -2.
Model bennett_from_trigonometry() {
  const double pi = std::acos(-1.0);
  const double alpha = pi / 6, beta = pi / 3, a = 1.0, b = a * std::sin(beta) / std::sin(alpha);
  const double t1 = 50 * pi / 180;
  const double t2 = 2 * std::atan(std::sin((beta + alpha) / 2) / std::sin((beta - alpha) / 2) / std::tan(t1 / 2));
  const double theta[4] = {t1, t2, -t1, -t2}, length[4] = {a, b, a, b}, twist[4] = {alpha, beta, alpha, beta};
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  Model model;
  model.bodies = {"1", "2", "3", "4"};
  for (int joint = 0; joint < 4; ++joint) {
    const Eigen::Vector3d axis = t.block<3, 1>(0, 2), origin = t.block<3, 1>(0, 3);
    model.couplings.push_back(revolute("J" + std::to_string(joint + 1), joint, (joint + 1) % 4,
                                       exact(origin.x(), origin.y(), origin.z()), exact(axis.x(), axis.y(), axis.z())));
    const double ct = std::cos(theta[joint]), st = std::sin(theta[joint]);
    const double ca = std::cos(twist[joint]), sa = std::sin(twist[joint]);
    Eigen::Matrix4d dh;
    dh << ct, -st * ca, st * sa, length[joint] * ct, st, ct * ca, -ct * sa, length[joint] * st, 0, sa, ca, 0, 0, 0, 0, 1;
    t = t * dh;
  }
  model.max_significant_digits = 17;  // as if written out in full: automatic arithmetic picks floating point
  return model;
}

TEST(HardCases, BennettFromTrigonometricValues) {
  const Model model = bennett_from_trigonometry();
  const NetworkResult f = analyse_network(model);
  EXPECT_FALSE(f.exact);
  EXPECT_EQ(f.FN, 1);
  EXPECT_EQ(f.CN, 3);  // FN - CN = F - 6 l = 4 - 6
  EXPECT_FALSE(f.circulation.solution.rank.close());
  EXPECT_GT(f.circulation.solution.rank.gap(), 1e8);
  // Exact arithmetic on the rounded values analyses a slightly different, rigid linkage, and
  // says that floating point disagrees.
  AnalysisOptions exact_options;
  exact_options.arithmetic = Arithmetic::exact;
  const NetworkResult e = analyse_network(model, exact_options);
  EXPECT_EQ(e.FN, 0);
  EXPECT_EQ(e.CN, 2);
  ASSERT_TRUE(e.floating_point_disagreement.has_value());
  EXPECT_EQ(*e.floating_point_disagreement, std::make_pair(1, 3));
}

// Planar double parallelogram: ground pivots (0,0), (1,0), (2,0); coupler pivots (0,1), (1,1),
// (2 + perturbation, 1), so the coupler side of the second parallelogram is longer than the
// ground side by the perturbation. Exactly parallel: FN = 1 with one redundant link, CN = 1
// (FN - CN = F - 3 l = 6 - 3 * 2). A perturbation tilts the third crank, so the coupler can
// no longer translate: rigid and statically determinate (FN = 0, CN = 0).
Model double_parallelogram(const Rational& perturbation) {
  Model model;
  model.space = screw::ScrewSpace::planar();
  model.bodies = {"ground", "crank1", "crank2", "crank3", "coupler"};
  const Vec3 z{0, 0, 1};
  model.couplings = {revolute("A", 0, 1, {0, 0, 0}, z), revolute("B", 0, 2, {1, 0, 0}, z),
                     revolute("C", 0, 3, {2, 0, 0}, z), revolute("D", 1, 4, {0, 1, 0}, z),
                     revolute("E", 2, 4, {1, 1, 0}, z), revolute("F", 3, 4, {2 + perturbation, 1, 0}, z)};
  return model;
}

TEST(HardCases, NearlySingularParallelogramIsReportedAsClose) {
  AnalysisOptions floating;
  floating.arithmetic = Arithmetic::floating;
  const NetworkResult parallel = analyse_network(double_parallelogram(0), floating);
  EXPECT_EQ(parallel.FN, 1);
  EXPECT_EQ(parallel.CN, 1);
  EXPECT_FALSE(parallel.circulation.solution.rank.close());

  const NetworkResult perturbed = analyse_network(double_parallelogram(Rational(1, 1000000000)), floating);
  EXPECT_EQ(perturbed.FN, 0);
  EXPECT_EQ(perturbed.CN, 0);
  // The kept singular value ~1e-9 of the largest is far above rounding (the error bound is
  // ~36 ε of the largest): the rank is certain, and its distance says the design is near a mechanism.
  EXPECT_EQ(perturbed.circulation.solution.rank.status(), linalg::RankStatus::certain);
  EXPECT_LT(*perturbed.circulation.solution.rank.distance(), kNearRankChange);
  EXPECT_LT(perturbed.circulation.solution.rank.smallest_kept, 1e-8 * perturbed.circulation.solution.rank.largest);

  // With a tolerance above the perturbation the same model reads as the parallelogram, and the
  // dropped singular value far above rounding marks the decision as close.
  AnalysisOptions loose = floating;
  loose.tolerances = Tolerances::with_rank(1e-7);
  const NetworkResult tolerant = analyse_network(double_parallelogram(Rational(1, 1000000000)), loose);
  EXPECT_EQ(tolerant.FN, 1);
  EXPECT_EQ(tolerant.CN, 1);
  EXPECT_TRUE(tolerant.circulation.solution.rank.close());

  // Exact arithmetic has no tolerance question: the perturbed linkage is rigid.
  AnalysisOptions exact_options;
  exact_options.arithmetic = Arithmetic::exact;
  EXPECT_EQ(analyse_network(double_parallelogram(Rational(1, 1000000000)), exact_options).FN, 0);
}

TEST(HardCases, IllScaledFourBar) {
  // A planar four-bar whose crank is 1e-6 long while the other links are about 1e3: still
  // FN = 1, CN = 0 in exact and in floating-point arithmetic.
  Model model;
  model.space = screw::ScrewSpace::planar();
  model.bodies = {"ground", "crank", "coupler", "rocker"};
  const Vec3 z{0, 0, 1};
  const Rational micro(1, 1000000);
  model.couplings = {revolute("A", 0, 1, {0, 0, 0}, z), revolute("B", 1, 2, {0, micro, 0}, z),
                     revolute("C", 2, 3, {1000, 700, 0}, z), revolute("D", 3, 0, {1200, 0, 0}, z)};
  for (Arithmetic arithmetic : {Arithmetic::exact, Arithmetic::floating}) {
    AnalysisOptions options;
    options.arithmetic = arithmetic;
    const NetworkResult r = analyse_network(model, options);
    EXPECT_EQ(r.FN, 1);
    EXPECT_EQ(r.CN, 0);
    EXPECT_EQ(r.pairs.size(), 6u);
  }
}

}  // namespace
}  // namespace kinestat::network
