// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/second_order.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>

#include "kinestat/linalg/definite_combination.hpp"
#include "kinestat/network/circuit_walk.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

namespace {

using Twist = Eigen::Matrix<double, 6, 1>;  // (ω; v), v the velocity of the point at the origin

// Above this many magnitudes or closure rows the classification is skipped (dense SVDs).
constexpr Eigen::Index kNetworkSecondOrderSizeLimit = 1200;

Twist bracket(const Twist& a, const Twist& b) {
  const Eigen::Vector3d wa = a.head<3>(), va = a.tail<3>(), wb = b.head<3>(), vb = b.tail<3>();
  Twist out;
  out << wa.cross(wb), wa.cross(vb) - wb.cross(va);
  return out;
}

}  // namespace

const char* network_motion_order_name(NetworkMotionOrder order) {
  switch (order) {
    case NetworkMotionOrder::infinitesimal: return "infinitesimal";
    case NetworkMotionOrder::finite: return "finite";
    case NetworkMotionOrder::undetermined: return "undetermined";
  }
  return "undetermined";
}

const char* network_order_reason_name(NetworkOrderReason reason) {
  switch (reason) {
    case NetworkOrderReason::blocked_by_stress: return "blocked_by_stress";
    case NetworkOrderReason::prestress_stable: return "prestress_stable";
    case NetworkOrderReason::passes_second_order: return "passes_second_order";
    case NetworkOrderReason::no_self_stress: return "no_self_stress";
    case NetworkOrderReason::traced: return "traced";
    case NetworkOrderReason::trace_failed: return "trace_failed";
    case NetworkOrderReason::no_second_order_model: return "no_second_order_model";
  }
  return "no_second_order_model";
}

namespace {

// Traces every motion that passes second order (or that nothing can block): finite when the
// trace closes, undetermined (trace_failed) when it does not; refused traces change nothing.
void trace_passing_motions(const Model& model, const NetworkResult& r, const NetworkSecondOrderOptions& options,
                           NetworkSecondOrder& out) {
  if (!options.trace) return;
  for (std::size_t k = 0; k < out.motions.size(); ++k) {
    auto& m = out.motions[k];
    if (m.reason != NetworkOrderReason::passes_second_order && m.reason != NetworkOrderReason::no_self_stress) continue;
    NetworkTrace trace = trace_network_motion(model, r, r.motion_magnitudes.values.col(static_cast<Eigen::Index>(k)), options.tracing);
    if (!trace.traced()) continue;
    m.traced = true;
    m.order = trace.closed ? NetworkMotionOrder::finite : NetworkMotionOrder::undetermined;
    m.reason = trace.closed ? NetworkOrderReason::traced : NetworkOrderReason::trace_failed;
    m.trace = std::move(trace);
  }
}

}  // namespace

NetworkSecondOrder classify_network_motions(const Model& model, const NetworkResult& r, const NetworkSecondOrderOptions& options) {
  NetworkSecondOrder out;
  const auto FN = static_cast<Eigen::Index>(r.primary_motion.size());
  out.motions.assign(static_cast<std::size_t>(FN), {});
  if (FN == 0) return out;
  const Eigen::MatrixXd& phi = r.motion_magnitudes.values;  // F × FN: θ′ = Φ ξ
  const auto F = static_cast<Eigen::Index>(r.motions.size());
  const auto l = static_cast<Eigen::Index>(r.chords.size());

  const std::vector<int>& components = model.space.components;
  const bool spatial = model.space.is_spatial(), planar = model.space.is_planar();
  const bool spherical = components == std::vector<int>{0, 1, 2};
  for (Eigen::Index row = 0; row < r.B.rows(); ++row)
    for (Eigen::Index e = 0; e < r.B.cols(); ++e)
      if (r.B(row, e) != 0 && !has_product_of_exponentials_model(model.couplings[static_cast<std::size_t>(e)].type)) {
        const std::string& name = model.couplings[static_cast<std::size_t>(e)].name;
        if (std::find(out.unmodelled_couplings.begin(), out.unmodelled_couplings.end(), name) == out.unmodelled_couplings.end())
          out.unmodelled_couplings.push_back(name);
      }
  const bool sized = F <= kNetworkSecondOrderSizeLimit && 6 * l <= kNetworkSecondOrderSizeLimit;
  if (!out.unmodelled_couplings.empty() || !(spatial || planar || spherical) || !sized || phi.cols() != FN) return out;
  if (r.CN == 0 || l == 0) {
    for (auto& m : out.motions) m.reason = NetworkOrderReason::no_self_stress;
    trace_passing_motions(model, r, options, out);
    return out;
  }

  // The analysis frame of this test: origin at the centroid of the coupling points, lengths over
  // the model's extent (a rotation-free Ad, so brackets and closure are those of the user frame).
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double extent = 1.0;
  if (!spherical && !model.couplings.empty()) {
    for (const auto& c : model.couplings)
      centroid += Eigen::Vector3d(c.geometry.point[0].get_d(), c.geometry.point[1].get_d(), c.geometry.point[2].get_d());
    centroid /= static_cast<double>(model.couplings.size());
    double largest = 0.0;
    for (const auto& c : model.couplings)
      largest = std::max(largest, (Eigen::Vector3d(c.geometry.point[0].get_d(), c.geometry.point[1].get_d(), c.geometry.point[2].get_d()) -
                                   centroid).norm());
    if (largest > 0.0) extent = largest;
  }
  std::vector<Twist> unit(static_cast<std::size_t>(F));
  for (Eigen::Index i = 0; i < F; ++i) {
    Twist s = Twist::Zero();
    const auto& coordinates = r.motions[static_cast<std::size_t>(i)].unit_screw.coordinates;
    for (std::size_t k = 0; k < components.size() && k < coordinates.size(); ++k) s(components[k]) = coordinates[k].get_d();
    const Eigen::Vector3d w = s.head<3>();
    s.tail<3>() = (s.tail<3>() + w.cross(centroid)) / extent;
    unit[static_cast<std::size_t>(i)] = s;
  }

  // The circuits in walking order, and the closure matrix M′ (6 rows per circuit) they give.
  const std::vector<std::vector<CircuitFactor>> circuits = circuit_walks(model, r);
  Eigen::MatrixXd closure = Eigen::MatrixXd::Zero(6 * l, F);
  for (Eigen::Index row = 0; row < l; ++row) {
    if (circuits[static_cast<std::size_t>(row)].empty()) return out;  // not a closed walk: leave every motion undetermined
    for (const CircuitFactor& f : circuits[static_cast<std::size_t>(row)]) closure.block(6 * row, f.magnitude, 6, 1) += f.sign * unit[static_cast<std::size_t>(f.magnitude)];
  }
  // Every motion must close to first order in this frame; otherwise the walk misread B.
  if ((closure * phi).norm() > kModeZero * std::max(1.0, closure.norm() * phi.norm())) return out;

  // Left null vectors of M′: the self-stresses as circuit wrenches (the analysis's rank m).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(closure, Eigen::ComputeFullU);
  const Eigen::Index null_dimension = 6 * l - std::min<Eigen::Index>(r.m, 6 * l);
  const Eigen::MatrixXd W = svd.matrixU().rightCols(null_dimension);

  // One quadratic form per self-stress on the magnitudes: K_s(i, j) from the ordered brackets.
  std::vector<Eigen::MatrixXd> forms(static_cast<std::size_t>(null_dimension), Eigen::MatrixXd::Zero(F, F));
  for (Eigen::Index row = 0; row < l; ++row) {
    const auto& factors = circuits[static_cast<std::size_t>(row)];
    for (std::size_t a = 0; a < factors.size(); ++a)
      for (std::size_t b = a + 1; b < factors.size(); ++b) {
        const Twist t = factors[a].sign * factors[b].sign *
                        bracket(unit[static_cast<std::size_t>(factors[a].magnitude)], unit[static_cast<std::size_t>(factors[b].magnitude)]);
        for (Eigen::Index s = 0; s < null_dimension; ++s) {
          const double value = 0.5 * W.col(s).segment<6>(6 * row).dot(t);
          forms[static_cast<std::size_t>(s)](factors[a].magnitude, factors[b].magnitude) += value;
          forms[static_cast<std::size_t>(s)](factors[b].magnitude, factors[a].magnitude) += value;
        }
      }
  }

  // The size of the bracket terms of a motion θ′: Σ_{j<k} |X_j| |X_k| over the circuits, the
  // scale that the work of a self-stress on them is measured against.
  const auto bracket_size = [&](const Eigen::VectorXd& theta) {
    double size = 0.0;
    for (const auto& factors : circuits)
      for (std::size_t a = 0; a < factors.size(); ++a)
        for (std::size_t b = a + 1; b < factors.size(); ++b)
          size += std::abs(theta(factors[a].magnitude) * theta(factors[b].magnitude)) *
                  unit[static_cast<std::size_t>(factors[a].magnitude)].norm() * unit[static_cast<std::size_t>(factors[b].magnitude)].norm();
    return size;
  };

  // Each primary motion alone: the work of every self-stress on its bracket terms.
  for (Eigen::Index k = 0; k < FN; ++k) {
    const Eigen::VectorXd theta = phi.col(k);
    const double size = bracket_size(theta);
    Eigen::VectorXd work(null_dimension);
    for (Eigen::Index s = 0; s < null_dimension; ++s) work(s) = theta.dot(forms[static_cast<std::size_t>(s)] * theta);
    auto& verdict = out.motions[static_cast<std::size_t>(k)];
    verdict.second_order_work = size > 0.0 ? work.norm() / size : 0.0;
    if (verdict.second_order_work > kSecondOrderWorkZero) {
      verdict.order = NetworkMotionOrder::infinitesimal;
      verdict.reason = NetworkOrderReason::blocked_by_stress;
      // Back to the user frame: a covector on twists transforms with the transpose of Ad.
      const Eigen::VectorXd blocking = W * (work / work.norm());
      Eigen::VectorXd user(static_cast<Eigen::Index>(components.size()) * l);
      for (Eigen::Index row = 0; row < l; ++row) {
        const Eigen::Vector3d moment = blocking.segment<3>(6 * row), force = blocking.segment<3>(6 * row + 3) / extent;
        Twist covector;
        covector << moment + centroid.cross(force), force;
        for (std::size_t c = 0; c < components.size(); ++c)
          user(row * static_cast<Eigen::Index>(components.size()) + static_cast<Eigen::Index>(c)) = covector(components[c]);
      }
      verdict.blocking_stress = user.norm() > 0.0 ? Eigen::VectorXd(user / user.norm()) : user;
    } else {
      verdict.reason = NetworkOrderReason::passes_second_order;
    }
  }

  // Prestress stability of the whole motion space: some combination definite on it.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(phi);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(FN).triangularView<Eigen::Upper>();
  if (std::abs(R.diagonal().prod()) > 0.0) {
    const Eigen::MatrixXd basis = phi * R.inverse();  // orthonormal columns spanning the motions
    std::vector<Eigen::MatrixXd> restricted;
    for (const auto& K : forms) restricted.push_back(basis.transpose() * K * basis);
    double scale = 0.0;  // the bracket size of the unit motions of the basis
    for (Eigen::Index k = 0; k < FN; ++k) scale = std::max(scale, bracket_size(basis.col(k)));
    out.prestress_tested = true;
    if (scale > 0.0) {
      out.smallest_eigenvalue = linalg::most_positive_combination(restricted).first / scale;
      out.prestress_stable = out.smallest_eigenvalue > kPrestressMargin;
    }
    if (out.prestress_stable)
      for (auto& m : out.motions)
        if (m.order != NetworkMotionOrder::infinitesimal) {
          m.order = NetworkMotionOrder::infinitesimal;
          m.reason = NetworkOrderReason::prestress_stable;
        }
  }
  trace_passing_motions(model, r, options, out);
  return out;
}

}  // namespace kinestat::network
