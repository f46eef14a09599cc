// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/second_order.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

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

namespace {

// The couplings on some circuit whose finite motion has no product-of-exponentials model (higher
// pairs, custom screws): their circuits need curvatures, so no motion can be classified.
std::vector<std::string> unmodelled_circuit_couplings(const Model& model, const NetworkResult& r) {
  std::vector<std::string> names;
  for (Eigen::Index row = 0; row < r.B.rows(); ++row)
    for (Eigen::Index e = 0; e < r.B.cols(); ++e)
      if (r.B(row, e) != 0 && !has_product_of_exponentials_model(model.couplings[static_cast<std::size_t>(e)].type)) {
        const std::string& name = model.couplings[static_cast<std::size_t>(e)].name;
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
      }
  return names;
}

// The analysis frame of this test: origin at the centroid of the coupling points, lengths over
// the model's extent (a rotation-free Ad, so brackets and closure are those of the user frame).
struct SecondOrderFrame {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double extent = 1.0;

  static SecondOrderFrame of(const Model& model, bool spherical) {
    SecondOrderFrame frame;
    if (spherical || model.couplings.empty()) return frame;  // rotations only: nothing to centre
    const auto point = [](const Coupling& c) {
      return Eigen::Vector3d(c.geometry.point[0].get_d(), c.geometry.point[1].get_d(), c.geometry.point[2].get_d());
    };
    for (const auto& c : model.couplings) frame.centroid += point(c);
    frame.centroid /= static_cast<double>(model.couplings.size());
    double largest = 0.0;
    for (const auto& c : model.couplings) largest = std::max(largest, (point(c) - frame.centroid).norm());
    if (largest > 0.0) frame.extent = largest;
    return frame;
  }

  // The unit twist of every magnitude (user frame) in this frame.
  std::vector<Twist> unit_twists(const Model& model, const NetworkResult& r) const {
    const std::vector<int>& components = model.space.components;
    std::vector<Twist> unit(r.motions.size());
    for (std::size_t i = 0; i < r.motions.size(); ++i) {
      Twist s = Twist::Zero();
      const auto& coordinates = r.motions[i].unit_screw.coordinates;
      for (std::size_t k = 0; k < components.size() && k < coordinates.size(); ++k) s(components[k]) = coordinates[k].get_d();
      const Eigen::Vector3d w = s.head<3>();
      s.tail<3>() = (s.tail<3>() + w.cross(centroid)) / extent;
      unit[i] = s;
    }
    return unit;
  }

  // A circuit wrench covector (6 rows per circuit, this frame) in the user frame, unit norm: a
  // covector on twists transforms with the transpose of Ad.
  Eigen::VectorXd covector_to_user(const Eigen::VectorXd& blocking, const std::vector<int>& components, Eigen::Index l) const {
    Eigen::VectorXd user(static_cast<Eigen::Index>(components.size()) * l);
    for (Eigen::Index row = 0; row < l; ++row) {
      const Eigen::Vector3d moment = blocking.segment<3>(6 * row), force = blocking.segment<3>(6 * row + 3) / extent;
      Twist covector;
      covector << moment + centroid.cross(force), force;
      for (std::size_t c = 0; c < components.size(); ++c)
        user(row * static_cast<Eigen::Index>(components.size()) + static_cast<Eigen::Index>(c)) = covector(components[c]);
    }
    return user.norm() > 0.0 ? Eigen::VectorXd(user / user.norm()) : user;
  }
};

// The closure matrix M′ (6 rows per circuit) of the circuits in walking order; nothing when a
// circuit is not a closed walk (every motion then stays undetermined).
std::optional<Eigen::MatrixXd> closure_matrix(const std::vector<std::vector<CircuitFactor>>& circuits,
                                              const std::vector<Twist>& unit, Eigen::Index l) {
  Eigen::MatrixXd closure = Eigen::MatrixXd::Zero(6 * l, static_cast<Eigen::Index>(unit.size()));
  for (Eigen::Index row = 0; row < l; ++row) {
    if (circuits[static_cast<std::size_t>(row)].empty()) return std::nullopt;
    for (const CircuitFactor& f : circuits[static_cast<std::size_t>(row)]) closure.block(6 * row, f.magnitude, 6, 1) += f.sign * unit[static_cast<std::size_t>(f.magnitude)];
  }
  return closure;
}

// One quadratic form per self-stress (column of W, circuit wrenches) on the magnitudes: K_s(i, j)
// from the ordered brackets of each circuit.
std::vector<Eigen::MatrixXd> stress_forms(const std::vector<std::vector<CircuitFactor>>& circuits, const std::vector<Twist>& unit,
                                          const Eigen::MatrixXd& W) {
  const auto F = static_cast<Eigen::Index>(unit.size());
  std::vector<Eigen::MatrixXd> forms(static_cast<std::size_t>(W.cols()), Eigen::MatrixXd::Zero(F, F));
  for (std::size_t row = 0; row < static_cast<std::size_t>(W.rows() / 6); ++row) {
    const auto& factors = circuits[row];
    for (std::size_t a = 0; a < factors.size(); ++a)
      for (std::size_t b = a + 1; b < factors.size(); ++b) {
        const Twist t = factors[a].sign * factors[b].sign *
                        bracket(unit[static_cast<std::size_t>(factors[a].magnitude)], unit[static_cast<std::size_t>(factors[b].magnitude)]);
        for (Eigen::Index s = 0; s < W.cols(); ++s) {
          const double value = 0.5 * W.col(s).segment<6>(6 * static_cast<Eigen::Index>(row)).dot(t);
          forms[static_cast<std::size_t>(s)](factors[a].magnitude, factors[b].magnitude) += value;
          forms[static_cast<std::size_t>(s)](factors[b].magnitude, factors[a].magnitude) += value;
        }
      }
  }
  return forms;
}

// The size of the bracket terms of a motion θ′: Σ_{j<k} |X_j| |X_k| over the circuits, the scale
// that the work of a self-stress on them is measured against.
double bracket_size(const std::vector<std::vector<CircuitFactor>>& circuits, const std::vector<Twist>& unit,
                    const Eigen::VectorXd& theta) {
  double size = 0.0;
  for (const auto& factors : circuits)
    for (std::size_t a = 0; a < factors.size(); ++a)
      for (std::size_t b = a + 1; b < factors.size(); ++b)
        size += std::abs(theta(factors[a].magnitude) * theta(factors[b].magnitude)) *
                unit[static_cast<std::size_t>(factors[a].magnitude)].norm() * unit[static_cast<std::size_t>(factors[b].magnitude)].norm();
  return size;
}

// What the second-order test works with: the circuits, the unit twists in its frame, the
// self-stresses as circuit wrenches W and their quadratic forms.
struct SecondOrderSystem {
  SecondOrderFrame frame;
  std::vector<std::vector<CircuitFactor>> circuits;
  std::vector<Twist> unit;
  Eigen::MatrixXd W;
  std::vector<Eigen::MatrixXd> forms;
};

// Each primary motion alone: blocked when some self-stress does work on its bracket terms
// (relative to their size), with the blocking circuit wrench; otherwise it passes.
void classify_each_motion(const SecondOrderSystem& system, const Eigen::MatrixXd& phi, const std::vector<int>& components,
                          Eigen::Index l, NetworkSecondOrder& out) {
  const Eigen::Index stresses = system.W.cols();
  for (Eigen::Index k = 0; k < phi.cols(); ++k) {
    const Eigen::VectorXd theta = phi.col(k);
    const double size = bracket_size(system.circuits, system.unit, theta);
    Eigen::VectorXd work(stresses);
    for (Eigen::Index s = 0; s < stresses; ++s) work(s) = theta.dot(system.forms[static_cast<std::size_t>(s)] * theta);
    auto& verdict = out.motions[static_cast<std::size_t>(k)];
    verdict.second_order_work = size > 0.0 ? work.norm() / size : 0.0;
    if (verdict.second_order_work > kSecondOrderWorkZero) {
      verdict.order = NetworkMotionOrder::infinitesimal;
      verdict.reason = NetworkOrderReason::blocked_by_stress;
      verdict.blocking_stress = system.frame.covector_to_user(system.W * (work / work.norm()), components, l);
    } else {
      verdict.reason = NetworkOrderReason::passes_second_order;
    }
  }
}

// Prestress stability of the whole motion space: some combination of the forms definite on it
// (then every motion is infinitesimal).
void test_prestress_stability(const SecondOrderSystem& system, const Eigen::MatrixXd& phi, NetworkSecondOrder& out) {
  const Eigen::Index FN = phi.cols();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(phi);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(FN).triangularView<Eigen::Upper>();
  if (!(std::abs(R.diagonal().prod()) > 0.0)) return;
  const Eigen::MatrixXd basis = phi * R.inverse();  // orthonormal columns spanning the motions
  std::vector<Eigen::MatrixXd> restricted;
  for (const auto& K : system.forms) restricted.push_back(basis.transpose() * K * basis);
  double scale = 0.0;  // the bracket size of the unit motions of the basis
  for (Eigen::Index k = 0; k < FN; ++k) scale = std::max(scale, bracket_size(system.circuits, system.unit, basis.col(k)));
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

}  // namespace

NetworkSecondOrder classify_network_motions(const Model& model, const NetworkResult& r, const NetworkSecondOrderOptions& options) {
  NetworkSecondOrder out;
  const auto FN = static_cast<Eigen::Index>(r.primary_motion.size());
  out.motions.assign(static_cast<std::size_t>(FN), {});
  if (FN == 0) return out;
  const Eigen::MatrixXd& phi = r.motion_magnitudes.values;  // F × FN: θ′ = Φ ξ
  const auto F = static_cast<Eigen::Index>(r.motions.size());
  const auto l = static_cast<Eigen::Index>(r.chords.size());

  // Which networks can be classified: every circuit modelled, a screw space with a Lie group,
  // dense SVDs of a bounded size.
  const std::vector<int>& components = model.space.components;
  const bool spatial = model.space.is_spatial(), planar = model.space.is_planar();
  const bool spherical = components == std::vector<int>{0, 1, 2};
  out.unmodelled_couplings = unmodelled_circuit_couplings(model, r);
  const bool sized = F <= kNetworkSecondOrderSizeLimit && 6 * l <= kNetworkSecondOrderSizeLimit;
  if (!out.unmodelled_couplings.empty() || !(spatial || planar || spherical) || !sized || phi.cols() != FN) return out;
  if (r.CN == 0 || l == 0) {
    for (auto& m : out.motions) m.reason = NetworkOrderReason::no_self_stress;
    trace_passing_motions(model, r, options, out);
    return out;
  }

  SecondOrderSystem system;
  system.frame = SecondOrderFrame::of(model, spherical);
  system.unit = system.frame.unit_twists(model, r);
  system.circuits = circuit_walks(model, r);
  const std::optional<Eigen::MatrixXd> closure = closure_matrix(system.circuits, system.unit, l);
  if (!closure) return out;  // not a closed walk: leave every motion undetermined
  // Every motion must close to first order in this frame; otherwise the walk misread B.
  if ((*closure * phi).norm() > kModeZero * std::max(1.0, closure->norm() * phi.norm())) return out;

  // Left null vectors of M′: the self-stresses as circuit wrenches (the analysis's rank m).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(*closure, Eigen::ComputeFullU);
  const Eigen::Index null_dimension = 6 * l - std::min<Eigen::Index>(r.m, 6 * l);
  system.W = svd.matrixU().rightCols(null_dimension);
  system.forms = stress_forms(system.circuits, system.unit, system.W);

  classify_each_motion(system, phi, components, l, out);
  test_prestress_stability(system, phi, out);
  trace_passing_motions(model, r, options, out);
  return out;
}

}  // namespace kinestat::network
