// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/second_order.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "kinestat/framework/deformation_functions.hpp"
#include "kinestat/framework/element_second_derivatives.hpp"
#include "kinestat/linalg/definite_combination.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

// The columns of D̂ of the six slots of each node (−1 where a slot is not a column) and the row
// of D̂ of each deformation (−1 where released).
struct Placement {
  std::vector<std::array<Eigen::Index, 6>> columns;
  std::vector<Eigen::Index> row_of;
};

Placement place(const FrameworkResult& a) {
  Placement placement;
  std::vector<Eigen::Index> column_of(a.indexing.coordinates.size(), -1);
  for (std::size_t j = 0; j < a.partition.dependent_coordinates.size(); ++j)
    column_of[static_cast<std::size_t>(a.partition.dependent_coordinates[j])] = static_cast<Eigen::Index>(j);
  placement.columns.resize(a.indexing.coordinate_of.size());
  for (std::size_t node = 0; node < a.indexing.coordinate_of.size(); ++node)
    for (std::size_t slot = 0; slot < 6; ++slot) {
      const Eigen::Index coordinate = a.indexing.coordinate_of[node][slot];
      placement.columns[node][slot] = coordinate >= 0 ? column_of[static_cast<std::size_t>(coordinate)] : -1;
    }
  placement.row_of.assign(a.indexing.deformations.size(), -1);
  for (Eigen::Index r = 0; r < a.m; ++r) placement.row_of[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(r)])] = r;
  return placement;
}

// The rates of the six slots of `node` in `u` (columns of D̂, D̂'s units); absent columns at rest.
Vector6 node_rates(const Placement& placement, std::size_t node, const Eigen::VectorXd& u) {
  Vector6 rates = Vector6::Zero();
  for (std::size_t slot = 0; slot < 6; ++slot) {
    const Eigen::Index column = placement.columns[node][slot];
    if (column >= 0) rates(static_cast<Eigen::Index>(slot)) = u(column);
  }
  return rates;
}

// Calls visit(element index, first deformation index, rates of its nodes) for every element
// with at least one row in D̂, the rates taken from `u`.
template <typename Visit>
void for_each_held_element(const FrameworkModel& model, const FrameworkResult& a, const Placement& placement, Visit visit) {
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    const auto first = static_cast<std::size_t>(a.indexing.first_deformation[e]);
    const std::size_t count = deformation_count(model.dimension, element);
    bool held = false;
    for (std::size_t k = 0; k < count; ++k) held = held || placement.row_of[first + k] >= 0;
    if (held) visit(element, first, count);
  }
}

// ε̂″_r(u, u) for every row of D(c).
Eigen::VectorXd second_derivatives(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& u) {
  const Placement placement = place(a);
  const DisplacedConfiguration analysed = analysed_configuration(model);
  Eigen::VectorXd h = Eigen::VectorXd::Zero(a.m);
  for_each_held_element(model, a, placement, [&](const Element& element, std::size_t first, std::size_t count) {
    std::vector<Vector6> rates;
    for (std::size_t node : element.nodes) rates.push_back(node_rates(placement, node, u));
    const Eigen::VectorXd values = element_second_derivatives(model, analysed, element, a.length, rates);
    for (std::size_t k = 0; k < count; ++k)
      if (const Eigen::Index r = placement.row_of[first + k]; r >= 0) h(r) = values(static_cast<Eigen::Index>(k));
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
  const Placement placement = place(a);
  const DisplacedConfiguration analysed = analysed_configuration(model);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(a.n, a.n);
  for_each_held_element(model, a, placement, [&](const Element& element, std::size_t first, std::size_t count) {
    // The element's columns of D̂, as (element node, slot, column).
    struct Slot {
      std::size_t node;
      Eigen::Index slot, column;
    };
    std::vector<Slot> slots;
    for (std::size_t n = 0; n < element.nodes.size(); ++n)
      for (Eigen::Index s = 0; s < 6; ++s)
        if (const Eigen::Index c = placement.columns[element.nodes[n]][static_cast<std::size_t>(s)]; c >= 0) slots.push_back({n, s, c});
    // Σ_r σ_r ε̂″_r(v, v) for v a combination of unit rates of the element's columns: a quadratic
    // form, whose matrix follows exactly by polarisation.
    auto form = [&](const Slot* i, const Slot* j) {
      std::vector<Vector6> rates(element.nodes.size(), Vector6::Zero());
      rates[i->node](i->slot) += 1.0;
      if (j != nullptr) rates[j->node](j->slot) += 1.0;
      const Eigen::VectorXd values = element_second_derivatives(model, analysed, element, a.length, rates);
      double sum = 0.0;
      for (std::size_t d = 0; d < count; ++d)
        if (const Eigen::Index r = placement.row_of[first + d]; r >= 0) sum += stress(r) * values(static_cast<Eigen::Index>(d));
      return sum;
    };
    std::vector<double> diagonal(slots.size());
    for (std::size_t i = 0; i < slots.size(); ++i) diagonal[i] = form(&slots[i], nullptr);
    for (std::size_t i = 0; i < slots.size(); ++i) {
      k(slots[i].column, slots[i].column) += diagonal[i];
      for (std::size_t j = i + 1; j < slots.size(); ++j) {
        const double off = (form(&slots[i], &slots[j]) - diagonal[i] - diagonal[j]) / 2;
        k(slots[i].column, slots[j].column) += off;
        k(slots[j].column, slots[i].column) += off;
      }
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
    options.tracing.stop.throw_if_requested();
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
