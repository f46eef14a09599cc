#include "kinestat/framework/finite_motion.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

// One point of the path: the model at that configuration and D̂ there.
struct PathPoint {
  FrameworkModel model;
  Eigen::MatrixXd jacobian;  // D̂ (non-dimensional, unscaled)
};

Eigen::MatrixXd jacobian_at(const FrameworkModel& model, const FrameworkResult& a) {
  return Eigen::MatrixXd(dependent_jacobian(model, a.indexing, a.partition, deformation_derivative(model, a.indexing), a.length));
}

// The constraints of the rows of D(c), non-dimensional: bar length now minus bar length in the
// analysed model, over the characteristic length.
Eigen::VectorXd closure(const FrameworkModel& reference, const FrameworkModel& now, const FrameworkResult& a) {
  Eigen::VectorXd g(a.m);
  for (Eigen::Index r = 0; r < a.m; ++r) {
    const DeformationRef& d = a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(r)])];
    const Element& e = reference.elements[d.element];
    const double l0 = (reference.nodes[e.nodes[1]].position - reference.nodes[e.nodes[0]].position).norm();
    g(r) = truss_length(now, e) - l0;
  }
  return g / a.length;
}

// The largest |constraint| (non-dimensional); 0 without constraints.
double largest(const Eigen::VectorXd& g) { return g.size() == 0 ? 0.0 : g.cwiseAbs().maxCoeff(); }

// Moves the translational dependent coordinates by `step` (D̂'s units: translations per
// characteristic length). Rotational slots carry no geometry in a bar framework.
void displace(FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& step) {
  for (Eigen::Index j = 0; j < a.n; ++j) {
    const CoordinateRef& c = a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(j)])];
    if (is_translation(c.slot)) model.nodes[c.node].position(c.slot) += step(j) * a.length;
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
// D(c) (self-stresses) is no obstacle as long as the constraints stay consistent.
double correct(FrameworkModel& model, const FrameworkModel& reference, const FrameworkResult& a, const Eigen::VectorXd& tangent) {
  double residual = largest(closure(reference, model, a));
  for (int iteration = 0; iteration < 20 && residual > kCorrectorTarget; ++iteration) {
    Eigen::MatrixXd system(a.m + 1, a.n);
    system << jacobian_at(model, a), tangent.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(a.m + 1);
    rhs.head(a.m) = -closure(reference, model, a);
    const Eigen::VectorXd step = system.completeOrthogonalDecomposition().solve(rhs);
    FrameworkModel trial = model;
    displace(trial, a, step);
    const double next = largest(closure(reference, trial, a));
    if (!(next < residual)) break;  // stagnated at rounding level (or diverging)
    model = std::move(trial);
    residual = next;
  }
  return residual;
}

}  // namespace

double truss_length(const FrameworkModel& model, const Element& element) {
  return (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
}

bool bars_only(const FrameworkModel& model) {
  return std::all_of(model.elements.begin(), model.elements.end(), [](const Element& e) { return e.type == ElementType::truss; });
}

FiniteTrace trace_motion(const FrameworkModel& model, const FrameworkResult& a, const Eigen::VectorXd& direction,
                         const TraceOptions& options) {
  FiniteTrace trace;
  if (!bars_only(model) || direction.size() != a.n || a.n == 0 || direction.norm() == 0.0 || options.steps <= 0) return trace;
  const double step_length = options.amplitude_fraction / options.steps;  // non-dimensional arc length
  auto positions = [](const FrameworkModel& m) {
    Eigen::MatrixXd p(3, static_cast<Eigen::Index>(m.nodes.size()));
    for (std::size_t k = 0; k < m.nodes.size(); ++k) p.col(static_cast<Eigen::Index>(k)) = m.nodes[k].position;
    return p;
  };
  FrameworkModel now = model;
  Eigen::VectorXd tangent = direction.normalized();
  trace.closed = true;
  for (int step = 0;; ++step) {
    const auto [rank, null_space] = rank_and_null_space(jacobian_at(now, a), a, options.tolerance);
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
    const FrameworkModel before = now;
    displace(now, a, step_length * tangent);
    const double residual = correct(now, model, a, tangent);
    if (residual > kTraceResidual) {
      trace.closed = false;
      trace.failed_step = static_cast<std::size_t>(step) + 1;
      trace.max_residual = std::max(trace.max_residual, residual);
      break;
    }
    // Arc length by chords, in the norm of the modes (translations over the characteristic length).
    Eigen::VectorXd moved(a.n);
    for (Eigen::Index j = 0; j < a.n; ++j) {
      const CoordinateRef& c = a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(j)])];
      moved(j) = is_translation(c.slot) ? (now.nodes[c.node].position(c.slot) - before.nodes[c.node].position(c.slot)) / a.length : 0.0;
    }
    trace.amplitude += moved.norm() * a.length;
  }
  const Eigen::Index top = *std::max_element(trace.rank_along_path.begin(), trace.rank_along_path.end());
  for (std::size_t k = 0; k < trace.rank_along_path.size(); ++k)
    if (trace.rank_along_path[k] < top) trace.rank_drops.push_back(k);
  return trace;
}

}  // namespace kinestat::framework
