// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/deformation_functions.hpp"

#include <Eigen/Geometry>

namespace kinestat::framework {

namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

double truss_elongation(const Eigen::Vector3d& xp, const Eigen::Vector3d& xq, double l0) { return (xq - xp).norm() - l0; }

Eigen::Matrix<double, 1, 6> truss_elongation_derivative(const Eigen::Vector3d& xp, const Eigen::Vector3d& xq) {
  const Eigen::Vector3d e = (xq - xp).normalized();
  Eigen::Matrix<double, 1, 6> row;
  row << -e.transpose(), e.transpose();
  return row;
}

Vector6 beam_basic_deformations(const BeamConfiguration& b) {
  const Eigen::Vector3d d = b.xq - b.xp;
  const double l = d.norm();
  const Eigen::Vector3d e = d / l;
  const Eigen::Vector3d yp = b.triad_p.col(1), zp = b.triad_p.col(2), yq = b.triad_q.col(1), zq = b.triad_q.col(2);
  Vector6 eps;
  eps << l - b.l0, b.l0 * (zp.dot(yq) - yp.dot(zq)) / 2, -b.l0 * e.dot(zp), b.l0 * e.dot(zq), b.l0 * e.dot(yp),
      -b.l0 * e.dot(yq);
  return eps;
}

Vector6 beam_second_order_terms(const Vector6& b, double l0, double torsion_coupling) {
  Vector6 q;
  q(0) = (2 * b(2) * b(2) + b(2) * b(3) + 2 * b(3) * b(3) + 2 * b(4) * b(4) + b(4) * b(5) + 2 * b(5) * b(5)) / (30 * l0) +
         torsion_coupling * b(1) * b(1) / (2 * l0 * l0 * l0);
  q(1) = (-b(2) * b(5) + b(3) * b(4)) / l0;
  q(2) = b(1) * (b(4) + b(5)) / (6 * l0);
  q(3) = -b(1) * (b(4) + b(5)) / (6 * l0);
  q(4) = -b(1) * (b(2) + b(3)) / (6 * l0);
  q(5) = b(1) * (b(2) + b(3)) / (6 * l0);
  return q;
}

Vector6 beam_deformations(const BeamConfiguration& beam) {
  const Vector6 b = beam_basic_deformations(beam);
  return b + beam_second_order_terms(b, beam.l0, beam.torsion_coupling);
}

Derivative6x12 beam_basic_derivative(const BeamConfiguration& b) {
  const Eigen::Vector3d d = b.xq - b.xp;
  const double l = d.norm();
  const Eigen::Vector3d e = d / l;
  // de_l = P (ẋ_q − ẋ_p) with P the projection perpendicular to the element, divided by l.
  const Eigen::Matrix3d projection = (Eigen::Matrix3d::Identity() - e * e.transpose()) / l;
  const Eigen::Vector3d yp = b.triad_p.col(1), zp = b.triad_p.col(2), yq = b.triad_q.col(1), zq = b.triad_q.col(2);
  Derivative6x12 g = Derivative6x12::Zero();
  g.block<1, 3>(0, 0) = -e.transpose();
  g.block<1, 3>(0, 6) = e.transpose();
  // d(a·b)/dt = ω_p·(a × b) − ω_q·(a × b) for a on triad p and b on triad q.
  const Eigen::Vector3d twist = b.l0 / 2 * (zp.cross(yq) - yp.cross(zq));
  g.block<1, 3>(1, 3) = twist.transpose();
  g.block<1, 3>(1, 9) = -twist.transpose();
  // ε̄ = s l0 e_l·a with a on triad N: dε̄ = s l0 (aᵀ P (ẋ_q − ẋ_p) + (a × e_l)·ω_N).
  auto bending = [&](int row, double sign, const Eigen::Vector3d& a, int omega_column) {
    const Eigen::RowVector3d translational = sign * b.l0 * (projection * a).transpose();
    g.block<1, 3>(row, 0) = -translational;
    g.block<1, 3>(row, 6) = translational;
    g.block<1, 3>(row, omega_column) = sign * b.l0 * a.cross(e).transpose();
  };
  bending(2, -1.0, zp, 3);
  bending(3, +1.0, zq, 9);
  bending(4, +1.0, yp, 3);
  bending(5, -1.0, yq, 9);
  return g;
}

Eigen::Matrix<double, 6, 6> beam_second_order_jacobian(const Vector6& b, double l0, double c) {
  Eigen::Matrix<double, 6, 6> j = Eigen::Matrix<double, 6, 6>::Identity();
  j(0, 1) = c * b(1) / (l0 * l0 * l0);
  j(0, 2) = (4 * b(2) + b(3)) / (30 * l0);
  j(0, 3) = (b(2) + 4 * b(3)) / (30 * l0);
  j(0, 4) = (4 * b(4) + b(5)) / (30 * l0);
  j(0, 5) = (b(4) + 4 * b(5)) / (30 * l0);
  j(1, 2) = -b(5) / l0;
  j(1, 3) = b(4) / l0;
  j(1, 4) = b(3) / l0;
  j(1, 5) = -b(2) / l0;
  const double s56 = (b(4) + b(5)) / (6 * l0), s34 = (b(2) + b(3)) / (6 * l0), t = b(1) / (6 * l0);
  j(2, 1) = s56;
  j(2, 4) = t;
  j(2, 5) = t;
  j(3, 1) = -s56;
  j(3, 4) = -t;
  j(3, 5) = -t;
  j(4, 1) = -s34;
  j(4, 2) = -t;
  j(4, 3) = -t;
  j(5, 1) = s34;
  j(5, 2) = t;
  j(5, 3) = t;
  return j;
}

Derivative6x12 beam_deformation_derivative(const BeamConfiguration& beam) {
  return beam_second_order_jacobian(beam_basic_deformations(beam), beam.l0, beam.torsion_coupling) *
         beam_basic_derivative(beam);
}

double truss_elongation_second_derivative(const Eigen::Vector3d& xp, const Eigen::Vector3d& xq, const Eigen::Vector3d& rate_p,
                                          const Eigen::Vector3d& rate_q) {
  const Eigen::Vector3d d = xq - xp, rate = rate_q - rate_p;
  const double l = d.norm(), along = d.dot(rate) / l;
  return (rate.squaredNorm() - along * along) / l;
}

Vector6 beam_basic_second_derivative(const BeamConfiguration& b, const NodeRates12& rates) {
  const Eigen::Vector3d d = b.xq - b.xp, rate = rates.segment<3>(6) - rates.segment<3>(0);
  const Eigen::Vector3d omega_p = rates.segment<3>(3), omega_q = rates.segment<3>(9);
  const double l = d.norm();
  const Eigen::Vector3d e = d / l;
  // l̇ = e·ḋ, ė = (ḋ − e l̇)/l, l̈ = ė·ḋ, ë = −(2 ė l̇ + e l̈)/l (d̈ = 0).
  const double l_rate = e.dot(rate);
  const Eigen::Vector3d e_rate = (rate - e * l_rate) / l;
  const double l_acceleration = e_rate.dot(rate);
  const Eigen::Vector3d e_acceleration = -(2 * e_rate * l_rate + e * l_acceleration) / l;
  // A triad vector a turns as ȧ = ω × a, ä = ω × (ω × a).
  struct Turning {
    Eigen::Vector3d value, rate, acceleration;
  };
  auto turning = [](const Eigen::Vector3d& a, const Eigen::Vector3d& omega) {
    const Eigen::Vector3d turning_rate = omega.cross(a);
    return Turning{a, turning_rate, omega.cross(turning_rate)};
  };
  const Turning yp = turning(b.triad_p.col(1), omega_p), zp = turning(b.triad_p.col(2), omega_p);
  const Turning yq = turning(b.triad_q.col(1), omega_q), zq = turning(b.triad_q.col(2), omega_q);
  // (u·v)″ = u″·v + 2 u′·v′ + u·v″.
  auto product = [](const Turning& u, const Turning& v) {
    return u.acceleration.dot(v.value) + 2 * u.rate.dot(v.rate) + u.value.dot(v.acceleration);
  };
  const Turning along{e, e_rate, e_acceleration};
  Vector6 second;
  second << l_acceleration, b.l0 * (product(zp, yq) - product(yp, zq)) / 2, -b.l0 * product(along, zp), b.l0 * product(along, zq),
      b.l0 * product(along, yp), -b.l0 * product(along, yq);
  return second;
}

Vector6 beam_deformation_second_derivative(const BeamConfiguration& beam, const NodeRates12& rates) {
  const Vector6 basic = beam_basic_deformations(beam);
  const Vector6 basic_rate = beam_basic_derivative(beam) * rates;
  // q is a homogeneous quadratic: (q(ε̄))″ = ∇q · ε̄″ + ε̄′ᵀ ∇²q ε̄′ = ∇q · ε̄″ + 2 q(ε̄′).
  return beam_second_order_jacobian(basic, beam.l0, beam.torsion_coupling) * beam_basic_second_derivative(beam, rates) +
         2 * beam_second_order_terms(basic_rate, beam.l0, beam.torsion_coupling);
}

Vector6 rigid_link_second_derivative(const Eigen::Vector3d& x_reference, const Eigen::Vector3d& x_node, const NodeRates12& rates) {
  const Eigen::Vector3d r = x_node - x_reference, r_rate = rates.segment<3>(6) - rates.segment<3>(0);
  const Eigen::Vector3d omega_r = rates.segment<3>(3), omega_j = rates.segment<3>(9);
  Vector6 second;
  second << omega_r.cross(omega_r.cross(r)) - 2 * omega_r.cross(r_rate), -omega_r.cross(omega_j);
  return second;
}

Derivative6x12 rigid_link_derivative(const Eigen::Vector3d& x_reference, const Eigen::Vector3d& x_node) {
  Derivative6x12 g = Derivative6x12::Zero();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // −ω_r × r = r × ω_r = [r]× ω_r.
  g.block<3, 3>(0, 0) = -identity;
  g.block<3, 3>(0, 3) = cross_matrix(x_node - x_reference);
  g.block<3, 3>(0, 6) = identity;
  g.block<3, 3>(3, 3) = -identity;
  g.block<3, 3>(3, 9) = identity;
  return g;
}

}  // namespace kinestat::framework
