#include "kinestat/framework/second_order.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

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

// Deterministic unit directions in R^s to start the search for a positive definite combination:
// a dense circle (s = 2), a Fibonacci sphere (s = 3), otherwise ± the basis vectors and points
// from a fixed linear congruential sequence.
std::vector<Eigen::VectorXd> search_directions(Eigen::Index s) {
  std::vector<Eigen::VectorXd> directions;
  if (s == 1) {
    directions.push_back(Eigen::VectorXd::Constant(1, 1.0));
    directions.push_back(Eigen::VectorXd::Constant(1, -1.0));
  } else if (s == 2) {
    for (int k = 0; k < 720; ++k) {
      const double angle = 2 * std::numbers::pi * k / 720;
      directions.push_back(Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    }
  } else if (s == 3) {
    const int count = 4000;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < count; ++k) {
      const double z = 1.0 - 2.0 * (k + 0.5) / count, radius = std::sqrt(1.0 - z * z);
      directions.push_back(Eigen::Vector3d(radius * std::cos(golden * k), radius * std::sin(golden * k), z));
    }
  } else {
    for (Eigen::Index k = 0; k < s; ++k) {
      directions.push_back(Eigen::VectorXd::Unit(s, k));
      directions.push_back(-Eigen::VectorXd::Unit(s, k));
    }
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    for (int k = 0; k < 500; ++k) {
      Eigen::VectorXd v(s);
      for (Eigen::Index i = 0; i < s; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        v(i) = static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
      }
      if (v.norm() > 0) directions.push_back(v.normalized());
    }
  }
  return directions;
}

// Smallest eigenvalue of Σ c_k Q_k and its eigenvector.
std::pair<double, Eigen::VectorXd> smallest_eigen(const std::vector<Eigen::MatrixXd>& forms, const Eigen::VectorXd& c) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(forms[0].rows(), forms[0].cols());
  for (std::size_t k = 0; k < forms.size(); ++k) sum += c(static_cast<Eigen::Index>(k)) * forms[k];
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(sum);
  return {eigen.eigenvalues()(0), eigen.eigenvectors().col(0)};
}

// Maximises λ_min(Σ c_k Q_k) over unit c: the function is concave and positively homogeneous, so
// the best start of a scan is refined by projected supergradient ascent (the supergradient at c
// is (vᵀ Q_k v)_k with v the eigenvector of λ_min).
std::pair<double, Eigen::VectorXd> most_positive_combination(const std::vector<Eigen::MatrixXd>& forms) {
  const auto s = static_cast<Eigen::Index>(forms.size());
  double best = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_c;
  for (const Eigen::VectorXd& c : search_directions(s)) {
    const double value = smallest_eigen(forms, c).first;
    if (value > best) best = value, best_c = c;
  }
  Eigen::VectorXd c = best_c;
  for (int iteration = 0; iteration < 300 && s > 1; ++iteration) {
    const Eigen::VectorXd v = smallest_eigen(forms, c).second;
    Eigen::VectorXd gradient(s);
    for (Eigen::Index k = 0; k < s; ++k) gradient(k) = v.dot(forms[static_cast<std::size_t>(k)] * v);
    gradient -= c * c.dot(gradient);  // tangent to the sphere
    if (gradient.norm() == 0.0) break;
    c = (c + gradient.normalized() * (0.2 / (1.0 + iteration))).normalized();
    const double value = smallest_eigen(forms, c).first;
    if (value > best) best = value, best_c = c;
  }
  return {best, best_c};
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
      const auto [value, c] = most_positive_combination(forms);
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
