// SPDX-License-Identifier: BSD-3-Clause
// Eigenfrequencies K φ = ω² M φ with massless coordinates condensed out (issue 38, item 4),
// against hand derivations: spring–mass chains and a mass on a parallel leaf-spring guide.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "framework/framework_test_support.hpp"
#include "kinestat/framework/over_constraint_cost.hpp"
#include "kinestat/framework/stiffness.hpp"
#include "kinestat/framework/vibration.hpp"

namespace kinestat::framework {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

TEST(Vibration, TwoMassChainHasTheGoldenRatioFrequencies) {
  // wall –k– m –k– m: K = k [[2, −1], [−1, 1]], M = m I; det(K − λM) = 0 gives
  // λ = (3 ∓ √5)/2 · k/m.
  const double k = 400.0, m = 2.0;
  Eigen::MatrixXd stiffness(2, 2);
  stiffness << 2 * k, -k, -k, k;
  const VibrationModes modes = vibration_modes(stiffness, m * Eigen::MatrixXd::Identity(2, 2));
  ASSERT_EQ(modes.frequencies.size(), 2);
  EXPECT_NEAR(modes.frequencies(0), std::sqrt((3 - std::sqrt(5.0)) / 2 * k / m) / kTwoPi, 1e-12);
  EXPECT_NEAR(modes.frequencies(1), std::sqrt((3 + std::sqrt(5.0)) / 2 * k / m) / kTwoPi, 1e-12);
  // Mass-normalised: φᵀ M φ = 1.
  EXPECT_NEAR(m * modes.shapes.col(0).squaredNorm(), 1.0, 1e-12);
}

TEST(Vibration, MasslessNodeBetweenSpringsIsCondensedToSpringsInSeries) {
  // wall –k1– (no mass) –k2– m: k = k1 k2 / (k1 + k2), f = √(k/m)/2π; the massless node moves
  // k2/(k1 + k2) of the mass's displacement.
  const double k1 = 300.0, k2 = 600.0, m = 0.5;
  Eigen::MatrixXd stiffness(2, 2);
  stiffness << k1 + k2, -k2, -k2, k2;
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(2, 2);
  mass(1, 1) = m;
  const VibrationModes modes = vibration_modes(stiffness, mass);
  ASSERT_EQ(modes.frequencies.size(), 1);
  EXPECT_NEAR(modes.frequencies(0), std::sqrt(k1 * k2 / (k1 + k2) / m) / kTwoPi, 1e-12);
  EXPECT_NEAR(modes.shapes(0, 0) / modes.shapes(1, 0), k2 / (k1 + k2), 1e-12);
}

TEST(Vibration, FullMassMatrixGivesTheSameFrequenciesInAnyBasis) {
  // The chain of the first test in rotated coordinates q = Qᵀ x (K' = Qᵀ K Q, M' = Qᵀ M Q), with a
  // massless third coordinate coupled by a spring k3 to the second mass: the frequencies do not
  // depend on the basis, and the massless direction is found as such.
  const double k = 400.0, m = 2.0, k3 = 1000.0;
  Eigen::MatrixXd stiffness(3, 3), mass = Eigen::MatrixXd::Zero(3, 3);
  stiffness << 2 * k, -k, 0, -k, k + k3, -k3, 0, -k3, k3 + 50.0;
  mass(0, 0) = mass(1, 1) = m;
  const Eigen::Matrix3d q = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 2).normalized()).toRotationMatrix();
  const VibrationModes direct = vibration_modes(stiffness, mass);
  const VibrationModes rotated = vibration_modes(q.transpose() * stiffness * q, q.transpose() * mass * q);
  ASSERT_EQ(direct.frequencies.size(), 2);
  ASSERT_EQ(rotated.frequencies.size(), 2);
  EXPECT_NEAR(rotated.frequencies(0), direct.frequencies(0), 1e-9 * direct.frequencies(0));
  EXPECT_NEAR(rotated.frequencies(1), direct.frequencies(1), 1e-9 * direct.frequencies(1));
  // Independently: condensing the third coordinate by hand, k_eff of the second mass's spring to
  // ground through node 3 is k3·50/(k3 + 50); the 2×2 problem [[2k, −k], [−k, k + k_eff]] / m.
  const double k_eff = k3 * 50.0 / (k3 + 50.0);
  const double trace = (3 * k + k_eff) / m, det = (2 * k * (k + k_eff) - k * k) / (m * m);
  EXPECT_NEAR(direct.frequencies(0), std::sqrt((trace - std::sqrt(trace * trace - 4 * det)) / 2) / kTwoPi, 1e-9);
}

TEST(Vibration, MasslessMechanismIsRefused) {
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(2, 2);
  mass(0, 0) = 1.0;
  EXPECT_THROW(vibration_modes(Eigen::MatrixXd::Zero(2, 2), mass), std::invalid_argument);
}

// A planar parallel leaf-spring guide: leaves of length L at x = 0 and x = d, clamped at y = 0,
// joined at the top by a rigid connector (a beam without elastic data), mass m/2 on each top
// node, leaves massless. Units: `scale` 1 for mm (N, t, MPa), 1e-3 for m (N, kg, Pa).
FrameworkModel leaf_guide(double scale) {
  const double l = 40 * scale, d = 50 * scale;
  FrameworkModel model = testing::parse_model(
      "kinestat: 1\nkind: framework\nname: planar leaf guide\ndimension: planar\n"
      "nodes: {B1: [0, 0], T1: [0, " + std::to_string(l) + "], B2: [" + std::to_string(d) + ", 0], T2: [" + std::to_string(d) +
      ", " + std::to_string(l) + "]}\nsupports: {B1: fixed, B2: fixed}\nelements:\n"
      "  - {name: leaf1, type: beam, nodes: [B1, T1]}\n  - {name: leaf2, type: beam, nodes: [B2, T2]}\n"
      "  - {name: body, type: beam, nodes: [T1, T2]}\n");
  Material steel;
  steel.name = "steel";
  steel.youngs_modulus = 2e5 / (scale * scale);  // 200 GPa: 2e5 N/mm², 2e11 N/m²
  model.materials.push_back(steel);
  Section leaf;  // in-plane thickness h = 0.2 mm, out-of-plane width b = 10 mm
  leaf.name = "leaf";
  leaf.shape = SectionShape::explicit_values;
  const double h = 0.2 * scale, b = 10 * scale;
  leaf.area = b * h;
  leaf.iz = b * h * h * h / 12;  // in-plane bending
  leaf.iy = h * b * b * b / 12;
  model.sections.push_back(leaf);
  for (std::size_t e = 0; e < 2; ++e) {
    model.elements[e].material = 0;
    model.elements[e].section = 0;
  }
  const double m = scale == 1.0 ? 1e-4 : 0.1;  // 0.1 kg = 1e-4 t
  model.masses.push_back(NodeMass{1, m / 2, std::nullopt});
  model.masses.push_back(NodeMass{3, m / 2, std::nullopt});
  return model;
}

// The hand answer: the body's sway u and rotation θ (the vertical translation decouples). Each
// leaf is a clamped beam whose top moves by u and turns by θ: lateral 12EI/L³, coupling 6EI/L²,
// rotation 4EI/L; θ also stretches the leaves by ±θ d/2 (axial EA/L). So
//   K = [[24EI/L³, 12EI/L²], [12EI/L², 8EI/L + EA d²/(2L)]], M = diag(m, m d²/4),
// and the lowest root of det(K − λM) = 0. Without the rotation (θ = 0, a guided body) this is
// λ = 24EI/(m L³): the closed form the test also checks to the size of the coupling, (h/d)².
double leaf_guide_first_frequency(double scale) {
  const double l = 40 * scale, d = 50 * scale, h = 0.2 * scale, b = 10 * scale, e = 2e5 / (scale * scale);
  const double m = scale == 1.0 ? 1e-4 : 0.1;
  const double ei = e * b * h * h * h / 12, ea = e * b * h;
  const double k11 = 24 * ei / (l * l * l), k12 = 12 * ei / (l * l), k22 = 8 * ei / l + ea * d * d / (2 * l);
  const double m11 = m, m22 = m * d * d / 4;
  const double qa = m11 * m22, qb = -(k11 * m22 + k22 * m11), qc = k11 * k22 - k12 * k12;
  // The larger root without cancellation, the smaller from the product of the roots c/a.
  const double larger = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  return std::sqrt(qc / (qa * larger)) / kTwoPi;
}

TEST(Vibration, MassOnParallelLeafSpringGuide) {
  const FrameworkModel model = leaf_guide(1.0);
  const std::optional<VibrationModes> modes = framework_vibration(model, assemble_stiffness(model), Eigen::MatrixXd());
  ASSERT_TRUE(modes.has_value());
  ASSERT_EQ(modes->frequencies.size(), 3);  // sway, vertical, rotation of the body
  EXPECT_NEAR(modes->frequencies(0), leaf_guide_first_frequency(1.0), 1e-9 * modes->frequencies(0));
  // k = 24EI/L³ = 24 · 2e5 · (10 · 0.2³/12) / 40³ = 0.5 N/mm, m = 1e-4 t: √(k/m)/2π = 11.2540 Hz,
  // to within the rotation coupling (h/d)² ≈ 1.6e-5.
  EXPECT_NEAR(modes->frequencies(0), std::sqrt(0.5 / 1e-4) / kTwoPi, 1e-4 * modes->frequencies(0));
}

TEST(Vibration, LeafSpringGuideInMetresGivesTheSameHertz) {
  const FrameworkModel mm = leaf_guide(1.0), m = leaf_guide(1e-3);
  const std::optional<VibrationModes> in_mm = framework_vibration(mm, assemble_stiffness(mm), Eigen::MatrixXd());
  const std::optional<VibrationModes> in_m = framework_vibration(m, assemble_stiffness(m), Eigen::MatrixXd());
  ASSERT_TRUE(in_mm && in_m);
  ASSERT_EQ(in_mm->frequencies.size(), in_m->frequencies.size());
  for (Eigen::Index i = 0; i < in_mm->frequencies.size(); ++i)
    EXPECT_NEAR(in_m->frequencies(i), in_mm->frequencies(i), 1e-8 * in_mm->frequencies(i));
  EXPECT_NEAR(in_m->frequencies(0), leaf_guide_first_frequency(1e-3), 1e-9 * in_m->frequencies(0));
}

}  // namespace
}  // namespace kinestat::framework
