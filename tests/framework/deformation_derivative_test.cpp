// SPDX-License-Identifier: BSD-3-Clause
// Analytic derivatives of the deformation functions (seed 002, eqs 2-4, including the
// second-order terms of eq 3) against central finite differences at generic configurations.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "kinestat/framework/deformation_functions.hpp"

namespace kinestat::framework {
namespace {

Eigen::Matrix3d rotate(const Eigen::Matrix3d& triad, const Eigen::Vector3d& axis_angle) {
  const double angle = axis_angle.norm();
  if (angle == 0.0) return triad;
  return Eigen::AngleAxisd(angle, axis_angle / angle).toRotationMatrix() * triad;
}

// A deformed, generic beam: ends not aligned with the triads, triads twisted differently, so
// that every second-order term of eq (3) contributes.
BeamConfiguration generic_beam(double torsion_coupling) {
  BeamConfiguration beam;
  beam.xp = {0.3, -0.2, 0.1};
  beam.xq = {1.4, 0.35, -0.25};
  const Eigen::Matrix3d base = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 0.5, 1).normalized()).toRotationMatrix();
  beam.triad_p = rotate(base, {0.12, -0.08, 0.15});
  beam.triad_q = rotate(base, {-0.1, 0.2, 0.05});
  beam.l0 = 1.1;
  beam.torsion_coupling = torsion_coupling;
  return beam;
}

// Central differences of ε (or ε̄) with respect to (ẋ_p, ω_p, ẋ_q, ω_q).
template <typename Function>
Derivative6x12 finite_difference(const BeamConfiguration& beam, Function f) {
  const double h = 1e-6;
  Derivative6x12 g;
  for (int k = 0; k < 12; ++k) {
    BeamConfiguration plus = beam, minus = beam;
    const int block = k / 3;
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(k % 3);
    switch (block) {
      case 0: plus.xp += step; minus.xp -= step; break;
      case 1: plus.triad_p = rotate(beam.triad_p, step); minus.triad_p = rotate(beam.triad_p, -step); break;
      case 2: plus.xq += step; minus.xq -= step; break;
      default: plus.triad_q = rotate(beam.triad_q, step); minus.triad_q = rotate(beam.triad_q, -step); break;
    }
    g.col(k) = (f(plus) - f(minus)) / (2 * h);
  }
  return g;
}

TEST(DeformationDerivative, BasicBeamDeformationsMatchFiniteDifferences) {
  const BeamConfiguration beam = generic_beam(0.0);
  const Derivative6x12 numeric = finite_difference(beam, [](const BeamConfiguration& b) { return beam_basic_deformations(b); });
  EXPECT_LT((beam_basic_derivative(beam) - numeric).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(DeformationDerivative, BeamDeformationsWithSecondOrderTermsMatchFiniteDifferences) {
  for (double c : {0.0, 0.37}) {
    const BeamConfiguration beam = generic_beam(c);
    const Vector6 basic = beam_basic_deformations(beam);
    // The configuration really is deformed in every mode, so no term of eq (3) drops out.
    for (int i = 0; i < 6; ++i) EXPECT_GT(std::abs(basic(i)), 1e-3) << i;
    const Derivative6x12 numeric = finite_difference(beam, [](const BeamConfiguration& b) { return beam_deformations(b); });
    const Derivative6x12 analytic = beam_deformation_derivative(beam);
    EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-8) << "c_r = " << c;
    // And the second-order terms make a difference here (the test would catch their loss).
    EXPECT_GT((analytic - beam_basic_derivative(beam)).cwiseAbs().maxCoeff(), 1e-3);
  }
}

TEST(DeformationDerivative, TrussElongationMatchesFiniteDifferences) {
  const Eigen::Vector3d p(0.3, -0.2, 0.1), q(1.4, 0.35, -0.25);
  const double h = 1e-6;
  const auto analytic = truss_elongation_derivative(p, q);
  for (int k = 0; k < 6; ++k) {
    Eigen::Vector3d pp = p, pm = p, qp = q, qm = q;
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(k % 3);
    if (k < 3) { pp += step; pm -= step; } else { qp += step; qm -= step; }
    const double numeric = (truss_elongation(pp, qp, 1.0) - truss_elongation(pm, qm, 1.0)) / (2 * h);
    EXPECT_NEAR(analytic(k), numeric, 1e-9) << k;
  }
  EXPECT_NEAR(truss_elongation(p, q, 1.0), (q - p).norm() - 1.0, 1e-15);
}

TEST(DeformationDerivative, BeamDeformationsAreInvariantUnderRigidMotion) {
  const BeamConfiguration beam = generic_beam(0.37);
  BeamConfiguration moved = beam;
  const Eigen::Matrix3d r = Eigen::AngleAxisd(1.3, Eigen::Vector3d(-1, 2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(5, -7, 2);
  moved.xp = r * beam.xp + t;
  moved.xq = r * beam.xq + t;
  moved.triad_p = r * beam.triad_p;
  moved.triad_q = r * beam.triad_q;
  EXPECT_LT((beam_deformations(moved) - beam_deformations(beam)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DeformationDerivative, UndeformedBeamAlongXByHand) {
  // Beam from the origin to (2, 0, 0), triads = global axes: ε̄ = 0, and by eq (4)
  // dε̄4/dω_q = l0 (e_z × e_l) = 2 e_y, dε̄5/dω_p = l0 (e_y × e_l) = -2 e_z,
  // dε̄3/dẋ_q = -l0 e_zᵀ (I - e_l e_lᵀ)/l = -e_z, dε̄2/dω_p = l0/2 (e_z × e_y - e_y × e_z) = -2 e_x.
  BeamConfiguration beam;
  beam.xq = {2, 0, 0};
  beam.l0 = 2;
  EXPECT_LT(beam_deformations(beam).cwiseAbs().maxCoeff(), 1e-15);
  const Derivative6x12 g = beam_deformation_derivative(beam);
  EXPECT_EQ(Eigen::Vector3d(g.block<1, 3>(3, 9).transpose()), Eigen::Vector3d(0, 2, 0));
  EXPECT_EQ(Eigen::Vector3d(g.block<1, 3>(4, 3).transpose()), Eigen::Vector3d(0, 0, -2));
  EXPECT_EQ(Eigen::Vector3d(g.block<1, 3>(2, 6).transpose()), Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(Eigen::Vector3d(g.block<1, 3>(1, 3).transpose()), Eigen::Vector3d(-2, 0, 0));
  EXPECT_EQ(Eigen::Vector3d(g.block<1, 3>(0, 0).transpose()), Eigen::Vector3d(-1, 0, 0));
}

TEST(DeformationDerivative, RigidLinkMatchesFiniteDifferencesOfBodyFrameCoordinates) {
  // The body-frame coordinates of node j seen from the reference node r: R_rᵀ (x_j − x_r) and
  // the relative rotation; at R_r = R_j = I their rates are the rows of rigid_link_derivative.
  const Eigen::Vector3d xr(0.2, 0.4, -0.3), xj(1.1, -0.6, 0.8);
  const Derivative6x12 g = rigid_link_derivative(xr, xj);
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(k);
    const Eigen::Matrix3d rp = rotate(Eigen::Matrix3d::Identity(), step), rm = rotate(Eigen::Matrix3d::Identity(), -step);
    const Eigen::Vector3d numeric = (rp.transpose() * (xj - xr) - rm.transpose() * (xj - xr)) / (2 * h);
    EXPECT_LT((g.block<3, 1>(0, 3 + k) - numeric).cwiseAbs().maxCoeff(), 1e-9);
  }
  EXPECT_EQ(Eigen::Matrix3d(g.block<3, 3>(0, 6)), Eigen::Matrix3d::Identity());
  EXPECT_EQ(Eigen::Matrix3d(g.block<3, 3>(3, 9)), Eigen::Matrix3d::Identity());
  EXPECT_EQ(Eigen::Matrix3d(g.block<3, 3>(3, 3)), -Eigen::Matrix3d::Identity());
}

}  // namespace
}  // namespace kinestat::framework
