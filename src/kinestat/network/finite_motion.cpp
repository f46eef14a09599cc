// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/finite_motion.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/circuit_walk.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

namespace {

using Twist = Eigen::Matrix<double, 6, 1>;  // (ω; v), v the velocity of the point at the origin

// A rigid motion x ↦ R x + t.
struct Pose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Pose operator*(const Pose& o) const { return {R * o.R, R * o.t + t}; }
};

Eigen::Matrix3d hat(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

// exp(ξ x) for a unit twist: |ω| = 1 (a rotation or screw) or ω = 0, |v| = 1 (a translation).
// Murray, Li & Sastry, A Mathematical Introduction to Robotic Manipulation (1994), eq. 2.36.
Pose exponential(const Twist& xi, double x) {
  const Eigen::Vector3d w = xi.head<3>(), v = xi.tail<3>();
  Pose p;
  if (w.squaredNorm() == 0.0) {
    p.t = v * x;
    return p;
  }
  const Eigen::Matrix3d W = hat(w);
  p.R = Eigen::Matrix3d::Identity() + std::sin(x) * W + (1.0 - std::cos(x)) * W * W;
  p.t = (Eigen::Matrix3d::Identity() - p.R) * w.cross(v) + w * w.dot(v) * x;
  return p;
}

// Ad(P) ξ: the twist ξ moved by the pose P.
Twist adjoint(const Pose& p, const Twist& xi) {
  Twist out;
  const Eigen::Vector3d w = p.R * xi.head<3>();
  out << w, p.t.cross(w) + p.R * xi.tail<3>();
  return out;
}

// The closure defect of a circuit's product P: (rotation vector; translation), P ≈ exp(error)
// to first order, and its size θ + |t| (scaled frame: relative to L).
std::pair<Twist, double> defect(const Pose& p) {
  const Eigen::Vector3d axis_sin(p.R(2, 1) - p.R(1, 2), p.R(0, 2) - p.R(2, 0), p.R(1, 0) - p.R(0, 1));
  const double s = 0.5 * axis_sin.norm(), c = 0.5 * (p.R.trace() - 1.0);
  const double angle = std::atan2(s, c);
  Twist e;
  e.head<3>() = s > 0.0 ? Eigen::Vector3d(0.5 * axis_sin * (angle / s)) : Eigen::Vector3d::Zero();
  e.tail<3>() = p.t;
  return {e, angle + p.t.norm()};
}

// Everything fixed along a trace: the walks, the scaled unit twists and the coordinate scales.
struct Loops {
  std::vector<std::vector<CircuitFactor>> walks;
  std::vector<Twist> unit;    // scaled frame, unit ω (or unit v)
  Eigen::VectorXd to_scaled;  // s_i = to_scaled_i · θ_i for magnitude rates θ of the analysis
  Eigen::VectorXd to_user;    // x_i = to_user_i · s_i: rad, or file length
  std::vector<int> rows;      // the space's components: the rows kept per circuit
  Eigen::Index F = 0;
};

// The closure Jacobian (d rows per circuit, F columns) and the defects at scaled coordinates s.
struct Evaluation {
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd defect;  // d rows per circuit: −(right-hand side) of the Newton step
  double residual = 0.0;   // largest circuit defect size
};

Evaluation evaluate(const Loops& loops, const Eigen::VectorXd& s) {
  const auto d = static_cast<Eigen::Index>(loops.rows.size());
  const auto l = static_cast<Eigen::Index>(loops.walks.size());
  Evaluation out;
  out.jacobian = Eigen::MatrixXd::Zero(d * l, loops.F);
  out.defect = Eigen::VectorXd::Zero(d * l);
  for (Eigen::Index row = 0; row < l; ++row) {
    Pose p;
    for (const CircuitFactor& f : loops.walks[static_cast<std::size_t>(row)]) {
      const Twist& xi = loops.unit[static_cast<std::size_t>(f.magnitude)];
      const Twist column = f.sign * adjoint(p, xi);
      for (Eigen::Index k = 0; k < d; ++k) out.jacobian(d * row + k, f.magnitude) += column(loops.rows[static_cast<std::size_t>(k)]);
      p = p * exponential(xi, f.sign * s(f.magnitude));
    }
    const auto [e, size] = defect(p);
    for (Eigen::Index k = 0; k < d; ++k) out.defect(d * row + k) = e(loops.rows[static_cast<std::size_t>(k)]);
    out.residual = std::max(out.residual, size);
  }
  return out;
}

// Newton corrector on the hyperplane through the predicted point normal to the tangent:
// minimum-norm least-squares steps, so self-stresses (redundant closure rows) are no obstacle
// while the equations stay consistent. A step that does not lower the residual is halved (up to
// kCorrectorHalvings times): near a branch point, where the Jacobian is nearly singular, full
// steps overshoot. Returns the residual reached.
constexpr int kCorrectorIterations = 40;
constexpr int kCorrectorHalvings = 12;

double correct(const Loops& loops, Eigen::VectorXd& s, const Eigen::VectorXd& tangent) {
  Evaluation here = evaluate(loops, s);
  for (int iteration = 0; iteration < kCorrectorIterations && here.residual > kCorrectorTarget; ++iteration) {
    Eigen::MatrixXd system(here.jacobian.rows() + 1, loops.F);
    system << here.jacobian, tangent.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(system.rows());
    rhs.head(here.defect.size()) = -here.defect;
    const Eigen::VectorXd step = system.completeOrthogonalDecomposition().solve(rhs);
    bool improved = false;
    for (int halving = 0; halving <= kCorrectorHalvings && !improved; ++halving) {
      const Eigen::VectorXd trial = s + std::ldexp(1.0, -halving) * step;
      Evaluation next = evaluate(loops, trial);
      if (next.residual < here.residual) {
        s = trial;
        here = std::move(next);
        improved = true;
      }
    }
    if (!improved) break;  // stagnated at rounding level (or no descent)
  }
  return here.residual;
}

}  // namespace

const char* trace_refusal_text(TraceRefusal refusal) {
  switch (refusal) {
    case TraceRefusal::none: return "";
    case TraceRefusal::unmodelled_coupling:
      return "a circuit passes a higher pair or custom screw (point_on_plane, point_on_line, custom), whose finite motion needs "
             "curvatures the model does not give";
    case TraceRefusal::space_not_modelled: return "the screw space is not spatial, planar or spherical";
    case TraceRefusal::too_large: return "the network has more magnitudes or closure rows than are traced (300)";
    case TraceRefusal::open_circuit: return "a circuit of the analysis is not a closed walk of the model";
    case TraceRefusal::not_a_motion: return "the direction is not a first-order motion of the network";
  }
  return "";
}

namespace {

// Why `direction` cannot be traced on this network, before any circuit is walked: a screw space
// without a Lie group model, a circuit through a coupling without a product-of-exponentials
// model (named in `trace`), too many magnitudes or rows for dense SVDs, or no usable direction.
TraceRefusal refusal_of(const Model& model, const NetworkResult& r, const Eigen::VectorXd& direction,
                        const NetworkTraceOptions& options, NetworkTrace& trace) {
  const auto F = static_cast<Eigen::Index>(r.motions.size());
  const auto l = static_cast<Eigen::Index>(r.B.rows());
  const bool spherical = model.space.components == std::vector<int>{0, 1, 2};
  if (!(model.space.is_spatial() || model.space.is_planar() || spherical)) return TraceRefusal::space_not_modelled;
  for (Eigen::Index row = 0; row < l; ++row)
    for (Eigen::Index e = 0; e < r.B.cols(); ++e) {
      const auto& c = model.couplings[static_cast<std::size_t>(e)];
      if (r.B(row, e) != 0 && !has_product_of_exponentials_model(c.type) &&
          std::find(trace.unmodelled_couplings.begin(), trace.unmodelled_couplings.end(), c.name) == trace.unmodelled_couplings.end())
        trace.unmodelled_couplings.push_back(c.name);
    }
  if (!trace.unmodelled_couplings.empty()) return TraceRefusal::unmodelled_coupling;
  const auto d = static_cast<Eigen::Index>(model.space.components.size());
  if (F > kNetworkTraceSizeLimit || d * l > kNetworkTraceSizeLimit) return TraceRefusal::too_large;
  if (direction.size() != F || F == 0 || !direction.allFinite() || direction.norm() == 0.0 || options.steps <= 0 ||
      !(options.amplitude_fraction > 0.0))
    return TraceRefusal::not_a_motion;
  return TraceRefusal::none;
}

// The unit twist of every magnitude in the analysis frame (origin and L; spherical screw spaces:
// rotations about the user's origin) with the factors between its coordinate and the user's:
// rotations in rad about the unit axis, translations in lengths of L. False when a magnitude has
// a zero screw (no motion to follow).
bool scale_unit_twists(const Model& model, const NetworkResult& r, Loops& loops, double& L) {
  const std::vector<int>& components = model.space.components;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  L = 1.0;
  if (components != std::vector<int>{0, 1, 2}) {
    const AnalysisFrame frame = AnalysisFrame::of(model);
    origin = Eigen::Vector3d(frame.origin[0].get_d(), frame.origin[1].get_d(), frame.origin[2].get_d());
    L = frame.scale.get_d();
  }
  const Eigen::Index F = loops.F;
  loops.to_scaled.resize(F);
  loops.to_user.resize(F);
  for (Eigen::Index i = 0; i < F; ++i) {
    Twist full = Twist::Zero();
    const auto& coordinates = r.motions[static_cast<std::size_t>(i)].unit_screw.coordinates;
    for (std::size_t k = 0; k < components.size() && k < coordinates.size(); ++k) full(components[k]) = coordinates[k].get_d();
    const Eigen::Vector3d w = full.head<3>(), v = full.tail<3>();
    Twist unit;
    if (w.squaredNorm() > 0.0) {  // a rotation or screw: x in rad about the unit axis
      const double n = w.norm();
      unit << w / n, (v + w.cross(origin)) / (n * L);
      loops.to_scaled(i) = n;
      loops.to_user(i) = 1.0;
    } else if (v.squaredNorm() > 0.0) {  // a translation: x in length, s = x / L
      const double n = v.norm();
      unit << Eigen::Vector3d::Zero(), v / n;
      loops.to_scaled(i) = n / L;
      loops.to_user(i) = L;
    } else {
      return false;
    }
    loops.unit.push_back(unit);
  }
  return true;
}

// Records the point `s` of the path (rank of the closure Jacobian there, residual, arc length,
// user coordinates) and returns the null space of the Jacobian, along which the tangent goes on.
Eigen::MatrixXd record_point(const Loops& loops, const Eigen::VectorXd& s, double arc, double L,
                             const NetworkTraceOptions& options, NetworkTrace& trace) {
  const Evaluation here = evaluate(loops, s);
  Eigen::Index rank = 0;
  Eigen::MatrixXd null_space = Eigen::MatrixXd::Identity(loops.F, loops.F);
  if (here.jacobian.rows() > 0) {
    linalg::RankTolerance tolerance = options.tolerance;
    tolerance.input_rounding = std::max(tolerance.input_rounding, here.residual);
    const linalg::SvdAnalysis svd = linalg::analyse_svd(here.jacobian, tolerance, linalg::SvdVectors::right_only);
    rank = svd.rank.rank;
    null_space = svd.null_space();
  }
  trace.rank_along_path.push_back(rank);
  trace.residual_along_path.push_back(here.residual);
  trace.arc_length_along_path.push_back(arc * L);
  trace.coordinates.push_back(s.cwiseProduct(loops.to_user));
  trace.max_residual = std::max(trace.max_residual, here.residual);
  return null_space;
}

// Predictor-corrector steps from s = 0 along the unit `tangent` (scaled coordinates) for
// options.steps steps: closed unless the tangent leaves the null space or the corrector loses
// closure (then the failed step).
void follow_motion(const Loops& loops, Eigen::VectorXd tangent, double L, const NetworkTraceOptions& options, NetworkTrace& trace) {
  const double step_length = options.amplitude_fraction / options.steps;  // scaled arc length per step
  Eigen::VectorXd s = Eigen::VectorXd::Zero(loops.F);
  double arc = 0.0;
  trace.closed = true;
  for (int step = 0;; ++step) {
    const Eigen::MatrixXd null_space = record_point(loops, s, arc, L, options, trace);
    if (step == options.steps) break;
    // The tangent follows the motion: the previous one projected on the null space here.
    const Eigen::VectorXd projected = null_space * (null_space.transpose() * tangent);
    if (projected.norm() < kTangentKept) {
      trace.closed = false;
      trace.failed_step = static_cast<std::size_t>(step) + 1;
      break;
    }
    tangent = projected.normalized();
    const Eigen::VectorXd before = s;
    s += step_length * tangent;
    const double residual = correct(loops, s, tangent);
    if (residual > kTraceResidual) {
      trace.closed = false;
      trace.failed_step = static_cast<std::size_t>(step) + 1;
      trace.max_residual = std::max(trace.max_residual, residual);
      break;
    }
    arc += (s - before).norm();
  }
  trace.amplitude = arc * L;
}

}  // namespace

NetworkTrace trace_network_motion(const Model& model, const NetworkResult& r, const Eigen::VectorXd& direction,
                                  const NetworkTraceOptions& options) {
  NetworkTrace trace;
  trace.refusal = refusal_of(model, r, direction, options, trace);
  if (trace.refusal != TraceRefusal::none) return trace;

  Loops loops;
  loops.F = static_cast<Eigen::Index>(r.motions.size());
  loops.rows = model.space.components;
  loops.walks = circuit_walks(model, r);
  for (const auto& walk : loops.walks)
    if (walk.empty()) {
      trace.refusal = TraceRefusal::open_circuit;
      return trace;
    }
  double L = 1.0;
  const bool scaled = scale_unit_twists(model, r, loops, L);
  trace.characteristic_length = L;
  if (!scaled) {
    trace.refusal = TraceRefusal::not_a_motion;
    return trace;
  }

  // The direction must be a first-order motion in this frame (otherwise the walk misread B).
  Eigen::VectorXd tangent = loops.to_scaled.cwiseProduct(direction);
  const Evaluation start = evaluate(loops, Eigen::VectorXd::Zero(loops.F));
  if (start.jacobian.rows() > 0 && (start.jacobian * tangent).norm() > kModeZero * std::max(1.0, start.jacobian.norm() * tangent.norm())) {
    trace.refusal = TraceRefusal::not_a_motion;
    return trace;
  }
  tangent.normalize();
  follow_motion(loops, tangent, L, options, trace);

  // Points where the rank of the closure falls below its largest along the path.
  const Eigen::Index top = *std::max_element(trace.rank_along_path.begin(), trace.rank_along_path.end());
  for (std::size_t k = 0; k < trace.rank_along_path.size(); ++k)
    if (trace.rank_along_path[k] < top) trace.rank_drops.push_back(k);
  return trace;
}

}  // namespace kinestat::network
