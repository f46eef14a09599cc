// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/finite_motion.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

#include "kinestat/framework/deformation_functions.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

Eigen::MatrixXd jacobian_at(const FrameworkModel& model, const FrameworkResult& a, const DisplacedConfiguration& now) {
  return Eigen::MatrixXd(
      dependent_jacobian(model, a.indexing, a.partition, deformation_derivative_at(model, a.indexing, now), a.length));
}

// Rotation vector (rad) of a rotation matrix.
Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& rotation) {
  const Eigen::AngleAxisd turn(rotation);
  return turn.angle() * turn.axis();
}

// Every deformation of `element` at `now` minus its value in the analysed `model`, in the
// element's deformation order, model units (lengths; rigid bodies' relative rotations in rad).
Eigen::VectorXd element_closure(const FrameworkModel& model, const Element& element, const DisplacedConfiguration& now) {
  const bool planar = model.dimension == 2;
  const auto& x = now.positions;
  Eigen::VectorXd values(static_cast<Eigen::Index>(deformation_count(model.dimension, element)));
  switch (element.type) {
    case ElementType::truss:
      values(0) = (x[element.nodes[1]] - x[element.nodes[0]]).norm() - truss_length(model, element);
      break;
    case ElementType::beam: {
      // Eq (3) between the turned triads, with the analysed length as l0: zero as analysed.
      const Vector6 eps = beam_deformations(beam_at(model, element, now));
      if (planar)
        values << eps(0), eps(4), eps(5);
      else
        values = eps;
      break;
    }
    case ElementType::rigid_body: {
      // The nonlinear coordinates whose rates rigid_link_derivative gives: the relative
      // translation and rotation in the reference node's analysed axes.
      const std::size_t reference = element.nodes[0];
      const Eigen::Matrix3d back = now.turns[reference].transpose();
      const std::vector<Eigen::Index> kept = planar ? std::vector<Eigen::Index>{0, 1, 5} : std::vector<Eigen::Index>{0, 1, 2, 3, 4, 5};
      Eigen::Index row = 0;
      for (std::size_t k = 1; k < element.nodes.size(); ++k) {
        const std::size_t node = element.nodes[k];
        Vector6 relative;
        relative << back * (x[node] - x[reference]) - (model.nodes[node].position - model.nodes[reference].position),
            rotation_vector(back * now.turns[node]);
        for (Eigen::Index slot : kept) values(row++) = relative(slot);
      }
      break;
    }
  }
  return values;
}

// The constraints of the rows of D(c), non-dimensional like D̂: every held deformation at `now`
// minus its value as analysed (lengths over the characteristic length).
Eigen::VectorXd closure(const FrameworkModel& model, const DisplacedConfiguration& now, const FrameworkResult& a) {
  std::vector<Eigen::Index> row_of(a.indexing.deformations.size(), -1);
  for (Eigen::Index r = 0; r < a.m; ++r) row_of[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(r)])] = r;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(a.m);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    const auto first = static_cast<std::size_t>(a.indexing.first_deformation[e]);
    const std::size_t count = deformation_count(model.dimension, element);
    bool held = false;
    for (std::size_t k = 0; k < count; ++k) held = held || row_of[first + k] >= 0;
    if (!held) continue;
    const Eigen::VectorXd values = element_closure(model, element, now);
    for (std::size_t k = 0; k < count; ++k) {
      const Eigen::Index r = row_of[first + k];
      if (r < 0) continue;
      g(r) = deformation_is_length(model.dimension, element, k) ? values(static_cast<Eigen::Index>(k)) / a.length
                                                                : values(static_cast<Eigen::Index>(k));
    }
  }
  return g;
}

// The largest |constraint| (non-dimensional); 0 without constraints.
double largest(const Eigen::VectorXd& g) { return g.size() == 0 ? 0.0 : g.cwiseAbs().maxCoeff(); }

// Moves the dependent coordinates by `step` (D̂'s units: translations per characteristic
// length, rotations in rad): positions add, triads turn by the rotation vector of their node.
void displace(DisplacedConfiguration& now, const FrameworkResult& a, const Eigen::VectorXd& step) {
  std::vector<Eigen::Vector3d> turn(now.turns.size(), Eigen::Vector3d::Zero());
  for (Eigen::Index j = 0; j < a.n; ++j) {
    const CoordinateRef& c = a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(j)])];
    if (is_translation(c.slot))
      now.positions[c.node](c.slot) += step(j) * a.length;
    else
      turn[c.node](c.slot - 3) += step(j);
  }
  for (std::size_t node = 0; node < turn.size(); ++node) {
    const double angle = turn[node].norm();
    if (angle > 0.0) now.turns[node] = Eigen::AngleAxisd(angle, turn[node] / angle).toRotationMatrix() * now.turns[node];
  }
}

// Rank of D(c) by the analysis' rule (on the physically scaled matrix) and an orthonormal basis
// of the null space of D̂ itself, from its SVD.
std::pair<Eigen::Index, Eigen::MatrixXd> rank_and_null_space(const Eigen::MatrixXd& jacobian, const FrameworkResult& a,
                                                             const linalg::RankTolerance& tolerance) {
  if (a.m == 0) return {0, Eigen::MatrixXd::Identity(a.n, a.n)};
  const Eigen::MatrixXd scaled = a.row_scale.asDiagonal() * jacobian * a.column_scale.asDiagonal();
  const Eigen::Index rank = linalg::numerical_rank(scaled, tolerance).rank;
  const linalg::SvdAnalysis svd = linalg::analyse_svd(jacobian, {}, linalg::SvdVectors::right_only);
  return {rank, svd.v.rightCols(a.n - std::min(rank, a.n))};
}

// Newton corrector on the constraints, kept on the hyperplane through the predicted point
// normal to the tangent (pseudo-arclength): minimum-norm least-squares steps, so a rank-deficient
// D(c) (self-stresses) is no obstacle as long as the constraints stay consistent. A step that
// does not lower the residual is halved (up to kCorrectorHalvings times, as the network tracer
// does). The steps use the `path_rank` largest singular values of D(c) only (plus the
// tangent's row), the rank on the path where this step began: off the path a self-stress's
// dependent rows become independent with a singular value as small as the distance to the
// path, and steps along it overshoot, while the stress's share of the defect is quadratic in
// that distance and vanishes as the other rows converge. Bricard's octahedron (rank 11 of 12
// rows all along its flex) lost closure at step 4 without both. Adds the steps taken to
// `moved` (D̂'s units).
constexpr int kCorrectorIterations = 40;
constexpr int kCorrectorHalvings = 12;

double correct(DisplacedConfiguration& now, const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& tangent,
               Eigen::Index path_rank, Eigen::VectorXd& moved) {
  Eigen::VectorXd defect = closure(model, now, a);
  double residual = largest(defect);
  for (int iteration = 0; iteration < kCorrectorIterations && residual > kCorrectorTarget; ++iteration) {
    Eigen::MatrixXd system(a.m + 1, a.n);
    system << jacobian_at(model, a, now), tangent.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(a.m + 1);
    rhs.head(a.m) = -defect;
    const linalg::SvdAnalysis svd = linalg::analyse_svd(system);
    const Eigen::Index kept = std::min(svd.rank.rank, path_rank + 1);
    const Eigen::VectorXd step = svd.v.leftCols(kept) *
                                 (svd.u.leftCols(kept).transpose() * rhs).cwiseQuotient(svd.singular_values.head(kept));
    bool improved = false;
    for (int halving = 0; halving <= kCorrectorHalvings && !improved; ++halving) {
      const Eigen::VectorXd scaled_step = std::ldexp(1.0, -halving) * step;
      DisplacedConfiguration trial = now;
      displace(trial, a, scaled_step);
      Eigen::VectorXd next = closure(model, trial, a);
      if (largest(next) < residual) {
        now = std::move(trial);
        moved += scaled_step;
        defect = std::move(next);
        residual = largest(defect);
        improved = true;
      }
    }
    if (!improved) break;  // stagnated at rounding level (or no descent)
  }
  return residual;
}

}  // namespace

double truss_length(const FrameworkModel& model, const Element& element) {
  return (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
}

FiniteTrace trace_motion(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& direction,
                         const TraceOptions& options) {
  FiniteTrace trace;
  if (direction.size() != a.n || a.n == 0 || direction.norm() == 0.0 || options.steps <= 0) return trace;
  const double step_length = options.amplitude_fraction / options.steps;  // non-dimensional arc length
  auto positions = [](const DisplacedConfiguration& c) {
    Eigen::MatrixXd p(3, static_cast<Eigen::Index>(c.positions.size()));
    for (std::size_t k = 0; k < c.positions.size(); ++k) p.col(static_cast<Eigen::Index>(k)) = c.positions[k];
    return p;
  };
  DisplacedConfiguration now = analysed_configuration(model);
  Eigen::VectorXd tangent = direction.normalized();
  trace.closed = true;
  for (int step = 0;; ++step) {
    options.stop.throw_if_requested();
    const auto [rank, null_space] = rank_and_null_space(jacobian_at(model, a, now), a, options.tolerance);
    trace.rank_along_path.push_back(rank);
    trace.positions.push_back(positions(now));
    const double here = largest(closure(model, now, a));
    trace.residual_along_path.push_back(here);
    trace.arc_length_along_path.push_back(trace.amplitude);
    trace.max_residual = std::max(trace.max_residual, here);
    if (step == options.steps) break;
    // The tangent follows the mode: the previous one projected on the null space here.
    const Eigen::VectorXd projected = null_space * (null_space.transpose() * tangent);
    if (projected.norm() < kTangentKept) {
      trace.closed = false;
      trace.failed_step = static_cast<std::size_t>(step) + 1;
      break;
    }
    tangent = projected.normalized();
    Eigen::VectorXd moved = step_length * tangent;  // this step's chord, D̂'s units
    displace(now, a, moved);
    const double residual = correct(now, model, a, tangent, rank, moved);
    if (residual > kTraceResidual) {
      trace.closed = false;
      trace.failed_step = static_cast<std::size_t>(step) + 1;
      trace.max_residual = std::max(trace.max_residual, residual);
      break;
    }
    // Arc length by chords, in the norm of the modes (translations over the characteristic
    // length, rotations in rad), back in length units.
    trace.amplitude += moved.norm() * a.length;
  }
  const Eigen::Index top = *std::max_element(trace.rank_along_path.begin(), trace.rank_along_path.end());
  for (std::size_t k = 0; k < trace.rank_along_path.size(); ++k)
    if (trace.rank_along_path[k] < top) trace.rank_drops.push_back(k);
  return trace;
}

}  // namespace kinestat::framework
