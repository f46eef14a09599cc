#include "kinestat/framework/second_order.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "kinestat/linalg/definite_combination.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

// Columns of D(c) of the translational slots of node `node`, −1 where the slot is not a column.
std::array<Eigen::Index, 3> translation_columns(const FrameworkResult& a, const std::vector<Eigen::Index>& column_of,
                                                std::size_t node) {
  std::array<Eigen::Index, 3> columns{-1, -1, -1};
  for (int slot = 0; slot < 3; ++slot) {
    const Eigen::Index coordinate = a.indexing.coordinate_of[node][static_cast<std::size_t>(slot)];
    if (coordinate >= 0) columns[static_cast<std::size_t>(slot)] = column_of[static_cast<std::size_t>(coordinate)];
  }
  return columns;
}

// Calls visit(row, columns of p, columns of q, B) for every bar row of D(c), where
// B = (I − e eᵀ) / l̂ is the Hessian of the non-dimensional bar length with respect to the
// non-dimensional relative position of q from p.
template <typename Visit>
void for_each_bar_row(const FrameworkModel& model, const FrameworkResult& a, Visit visit) {
  std::vector<Eigen::Index> column_of(a.indexing.coordinates.size(), -1);
  for (std::size_t j = 0; j < a.partition.dependent_coordinates.size(); ++j)
    column_of[static_cast<std::size_t>(a.partition.dependent_coordinates[j])] = static_cast<Eigen::Index>(j);
  for (Eigen::Index r = 0; r < a.m; ++r) {
    const DeformationRef& d = a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(r)])];
    const Element& element = model.elements[d.element];
    if (element.type != ElementType::truss) continue;
    const Eigen::Vector3d span = (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position) / a.length;
    const double l = span.norm();
    const Eigen::Vector3d e = span / l;
    const Eigen::Matrix3d hessian = (Eigen::Matrix3d::Identity() - e * e.transpose()) / l;
    visit(r, translation_columns(a, column_of, element.nodes[0]), translation_columns(a, column_of, element.nodes[1]), hessian);
  }
}

// Relative translation of a bar's ends in the rates `u` (columns of D(c)); absent columns are at rest.
Eigen::Vector3d relative_motion(const Eigen::VectorXd& u, const std::array<Eigen::Index, 3>& p, const std::array<Eigen::Index, 3>& q) {
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();
  for (std::size_t s = 0; s < 3; ++s) delta(static_cast<Eigen::Index>(s)) = (q[s] >= 0 ? u(q[s]) : 0.0) - (p[s] >= 0 ? u(p[s]) : 0.0);
  return delta;
}

// ε̂″_r(u, u) for every row of D(c).
Eigen::VectorXd second_derivatives(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& u) {
  Eigen::VectorXd h = Eigen::VectorXd::Zero(a.m);
  for_each_bar_row(model, a, [&](Eigen::Index r, const auto& p, const auto& q, const Eigen::Matrix3d& hessian) {
    const Eigen::Vector3d delta = relative_motion(u, p, q);
    h(r) = delta.dot(hessian * delta);
  });
  return h;
}

// Orthonormal basis of the column space of `a`, by an SVD with a relative cut.
Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& a, double relative_cut) {
  if (a.cols() == 0 || a.rows() == 0) return Eigen::MatrixXd(a.rows(), 0);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < sigma.size() && sigma(rank) > relative_cut * std::max(1.0, sigma(0))) ++rank;
  return svd.matrixU().leftCols(rank);
}

}  // namespace

const char* motion_order_name(MotionOrder order) {
  switch (order) {
    case MotionOrder::infinitesimal: return "infinitesimal";
    case MotionOrder::finite: return "finite";
    case MotionOrder::undetermined: return "undetermined";
  }
  return "undetermined";
}

Eigen::MatrixXd geometric_stiffness(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& stress) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(a.n, a.n);
  for_each_bar_row(model, a, [&](Eigen::Index r, const auto& p, const auto& q, const Eigen::Matrix3d& hessian) {
    // ε̂_r depends on x_q − x_p: the Hessian enters the pp and qq blocks with +, pq and qp with −.
    const std::array<const std::array<Eigen::Index, 3>*, 2> ends{&p, &q};
    for (std::size_t i = 0; i < 2; ++i)
      for (std::size_t j = 0; j < 2; ++j)
        for (std::size_t s = 0; s < 3; ++s)
          for (std::size_t t = 0; t < 3; ++t) {
            const Eigen::Index row = (*ends[i])[s], column = (*ends[j])[t];
            if (row < 0 || column < 0) continue;
            k(row, column) += (i == j ? 1.0 : -1.0) * stress(r) * hessian(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(t));
          }
  });
  return k;
}

Eigen::MatrixXd rigid_motions(const FrameworkModel& model, const FrameworkResult& a) {
  const bool planar = model.dimension == 2;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Node& node : model.nodes) centroid += node.position;
  if (!model.nodes.empty()) centroid /= static_cast<double>(model.nodes.size());
  // Generators: translations along the axes, then rotations about axes through the centroid
  // (planar: x, y and the rotation about z).
  const std::vector<int> translations = planar ? std::vector<int>{0, 1} : std::vector<int>{0, 1, 2};
  const std::vector<int> rotations = planar ? std::vector<int>{2} : std::vector<int>{0, 1, 2};
  const auto generators = static_cast<Eigen::Index>(translations.size() + rotations.size());
  const auto coordinates = static_cast<Eigen::Index>(a.indexing.coordinates.size());
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(coordinates, generators);
  for (Eigen::Index i = 0; i < coordinates; ++i) {
    const CoordinateRef& c = a.indexing.coordinates[static_cast<std::size_t>(i)];
    const Eigen::Vector3d arm = (model.nodes[c.node].position - centroid) / a.length;
    Eigen::Index k = 0;
    for (int axis : translations) g(i, k++) = c.slot == axis ? 1.0 : 0.0;
    for (int axis : rotations) {
      const Eigen::Vector3d velocity = Eigen::Vector3d::Unit(axis).cross(arm);
      g(i, k++) = is_translation(c.slot) ? velocity(c.slot) : (c.slot - 3 == axis ? 1.0 : 0.0);
    }
  }
  std::vector<Eigen::Index> held = a.partition.fixed_coordinates;
  held.insert(held.end(), a.partition.independent_coordinates.begin(), a.partition.independent_coordinates.end());
  Eigen::MatrixXd combinations = Eigen::MatrixXd::Identity(generators, generators);
  if (!held.empty()) {
    Eigen::MatrixXd at_rest(static_cast<Eigen::Index>(held.size()), generators);
    for (std::size_t i = 0; i < held.size(); ++i) at_rest.row(static_cast<Eigen::Index>(i)) = g.row(held[i]);
    combinations = linalg::analyse_svd(at_rest, {}, linalg::SvdVectors::right_only).null_space();
  }
  Eigen::MatrixXd dependent(a.n, generators);
  for (Eigen::Index j = 0; j < a.n; ++j) dependent.row(j) = g.row(a.partition.dependent_coordinates[static_cast<std::size_t>(j)]);
  return orthonormal_columns(dependent * combinations, kRigidMotionZero);
}

SecondOrderResult classify_modes(const FrameworkModel& model, const FrameworkResult& a, const SecondOrderOptions& options) {
  SecondOrderResult result;
  result.orders.resize(a.modes.size());
  if (a.modes.empty()) return result;
  if (!a.vectors || a.method != RankMethod::dense_svd || a.n > kSecondOrderSizeLimit || a.m > kSecondOrderSizeLimit)
    return result;  // not_computed
  if (!bars_only(model)) {
    for (ModeOrder& order : result.orders) order.reason = OrderReason::no_second_order_model;
    return result;
  }
  Eigen::MatrixXd modes(a.n, static_cast<Eigen::Index>(a.modes.size()));
  for (std::size_t k = 0; k < a.modes.size(); ++k) modes.col(static_cast<Eigen::Index>(k)) = a.modes[k].velocities;
  Eigen::MatrixXd stresses(a.m, static_cast<Eigen::Index>(a.stresses.size()));
  for (std::size_t k = 0; k < a.stresses.size(); ++k) stresses.col(static_cast<Eigen::Index>(k)) = a.stresses[k].resultants;

  const Eigen::MatrixXd rigid = rigid_motions(model, a);
  const Eigen::MatrixXd nonrigid = orthonormal_columns(modes - rigid * (rigid.transpose() * modes), kRigidMotionZero);
  const Eigen::MatrixXd stress_basis = orthonormal_columns(stresses, kRigidMotionZero);
  PrestressStability& prestress = result.prestress;
  prestress.rigid_motions = rigid.cols();
  prestress.nonrigid_modes = nonrigid.cols();
  if (nonrigid.cols() > 0 && stress_basis.cols() > 0) {
    prestress.tested = true;
    std::vector<Eigen::MatrixXd> forms;
    double scale = 0.0;
    for (Eigen::Index k = 0; k < stress_basis.cols(); ++k) {
      const Eigen::MatrixXd stiffness = geometric_stiffness(model, a, stress_basis.col(k));
      // The scale is the stiffness on all columns: on the modes alone it may vanish exactly
      // (a finite mechanism), and then only rounding would be left to compare with.
      scale = std::max(scale, stiffness.norm());
      Eigen::MatrixXd q = nonrigid.transpose() * stiffness * nonrigid;
      q = (q + q.transpose()).eval() / 2;
      forms.push_back(std::move(q));
    }
    prestress.exhaustive = stress_basis.cols() <= 3;
    if (scale > 0.0) {
      const auto [value, c] = linalg::most_positive_combination(forms);
      prestress.smallest_eigenvalue = value / scale;
      prestress.stress = stress_basis * c;
      prestress.stable = prestress.smallest_eigenvalue > kPrestressMargin;
    }
  }

  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    ModeOrder& order = result.orders[k];
    const Eigen::VectorXd& u = a.modes[k].velocities;
    const Eigen::VectorXd own = u - rigid * (rigid.transpose() * u);
    if (own.norm() <= kRigidMotionZero * u.norm()) {
      order.order = MotionOrder::finite;
      order.reason = OrderReason::rigid_motion;
      continue;
    }
    const Eigen::VectorXd h = second_derivatives(model, a, own);
    const double size = h.norm();
    if (prestress.stable) {
      order.order = MotionOrder::infinitesimal;
      order.reason = OrderReason::prestress_stable;
      order.blocking_stress = prestress.stress;
      order.second_order_work = size > 0.0 ? prestress.stress.dot(h) / size : 0.0;
      continue;
    }
    const Eigen::VectorXd work = stress_basis.transpose() * h;
    order.second_order_work = size > 0.0 ? work.norm() / size : 0.0;
    if (size > 0.0 && work.norm() > kSecondOrderWorkZero * size) {
      order.order = MotionOrder::infinitesimal;
      order.reason = OrderReason::blocked_by_stress;
      order.blocking_stress = stress_basis * work / work.norm();  // does positive work on the mode
      continue;
    }
    if (!options.trace) continue;  // passes second order, not traced: undetermined, not_computed
    order.traced = true;
    order.trace = trace_motion(model, a, own, options.tracing);
    order.order = order.trace.closed ? MotionOrder::finite : MotionOrder::undetermined;
    order.reason = order.trace.closed ? OrderReason::traced : OrderReason::trace_failed;
  }
  return result;
}

}  // namespace kinestat::framework
