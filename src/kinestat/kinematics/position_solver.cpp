// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/kinematics/position_solver.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kinestat/tolerances.hpp"

namespace kinestat::kinematics {

namespace {

using Vec2 = Eigen::Vector2d;
using screw::CouplingType;

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

// The quarter turn J: d/dθ R(θ) = J R(θ).
Vec2 quarter(const Vec2& v) { return {-v.y(), v.x()}; }
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 translation(const Pose& pose) { return {pose.x, pose.y}; }
Vec2 apply(const Pose& pose, const Vec2& p) { return rotation(pose.angle) * p + translation(pose); }

// The angle in (−π, π].
double wrapped(double angle) {
  const double w = std::remainder(angle, 2 * std::numbers::pi);
  return w == -std::numbers::pi ? std::numbers::pi : w;
}

// A pose with rotation `angle` that moves material point p to world point P.
Pose pose_through(double angle, const Vec2& p, const Vec2& P) {
  const Vec2 t = P - rotation(angle) * p;
  return {t.x(), t.y(), wrapped(angle)};
}

// The pose that moves material points p, q to world points P, Q (|q − p| = |Q − P|).
Pose pose_through(const Vec2& p, const Vec2& q, const Vec2& P, const Vec2& Q) {
  const Vec2 a = q - p, b = Q - P;
  return pose_through(std::atan2(cross(a, b), a.dot(b)), p, P);
}

Vec2 point_of(const network::Coupling& c) { return {c.geometry.point[0].get_d(), c.geometry.point[1].get_d()}; }

// Unit slide axis of a prismatic coupling in the file's configuration.
Vec2 axis_of(const network::Coupling& c) {
  const Vec2 a{(*c.geometry.axis)[0].get_d(), (*c.geometry.axis)[1].get_d()};
  return a.normalized();
}

bool is_revolute(const network::Coupling& c) { return c.type == CouplingType::revolute; }
char letter(const network::Coupling& c) { return is_revolute(c) ? 'R' : 'P'; }

// The body at the other end of coupling `c` from `body`.
int other(const network::Coupling& c, int body) { return c.from == body ? c.to : c.from; }
bool touches(const network::Coupling& c, int body) { return c.from == body || c.to == body; }

double characteristic_length(const network::Model& model) {
  std::vector<Vec2> points;
  for (const auto& c : model.couplings)
    if (is_revolute(c)) points.push_back(point_of(c));
  if (points.size() < 2) return 1.0;
  Vec2 centre = Vec2::Zero();
  for (const Vec2& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  double sum = 0.0;
  for (const Vec2& p : points) sum += (p - centre).squaredNorm();
  const double rms = std::sqrt(sum / static_cast<double>(points.size()));
  return rms > 0.0 ? rms : 1.0;
}

// ---- Closed forms of the dyads: the branch indicator and the solution --------------------------

struct DyadParts {
  const network::Coupling* j1;
  const network::Coupling* j2;
  const network::Coupling* j3;
  int b1, b2, a, b;  // dyad bodies (b1 on J1, b2 on J3) and the solved bodies A (J1), B (J3)
};

DyadParts dyad_parts(const network::Model& model, const GroupPlan& group) {
  DyadParts d{&model.couplings[static_cast<std::size_t>(group.chain[0])], &model.couplings[static_cast<std::size_t>(group.chain[1])],
              &model.couplings[static_cast<std::size_t>(group.chain[2])], 0, 0, 0, 0};
  d.b1 = touches(*d.j1, group.bodies[0]) ? group.bodies[0] : group.bodies[1];
  d.b2 = d.b1 == group.bodies[0] ? group.bodies[1] : group.bodies[0];
  d.a = other(*d.j1, d.b1);
  d.b = other(*d.j3, d.b2);
  return d;
}

// What a closed form gives: the poses of b1 and b2, the discriminant and the indicator value of
// each branch is not needed: the solver picks the branch by sign.
struct ClosedForm {
  AssemblyStatus status = AssemblyStatus::assembled;
  double discriminant = 0.0;
  std::string reason;
  Pose pose1, pose2;
};

// Classifies a relative discriminant.
AssemblyStatus judge(double discriminant) {
  if (discriminant < -kAssemblyDiscriminant) return AssemblyStatus::not_assembled;
  if (discriminant <= kAssemblyDiscriminant) return AssemblyStatus::singular;
  return AssemblyStatus::assembled;
}

std::string quoted(const network::Coupling& c) { return "'" + c.name + "'"; }

// The closed form of each dyad type for branch `s` (±1), with A at `pa` and B at `pb`
// (solve_dyad chooses by type).
ClosedForm solve_rrr(const DyadParts& d, const Pose& pa, const Pose& pb, double s, double length) {
  ClosedForm out;
  const Vec2 p1 = point_of(*d.j1), p2 = point_of(*d.j2), p3 = point_of(*d.j3);
  const Vec2 P1 = apply(pa, p1), P3 = apply(pb, p3);
  const double l1 = (p2 - p1).norm(), l2 = (p3 - p2).norm();
  const Vec2 D = P3 - P1;
  const double dist = D.norm();
  const double scale = std::max(l1, l2) * std::max(l1, l2);
  if (dist <= kCoincident * length) {
    out.status = std::abs(l1 - l2) <= kCoincident * length ? AssemblyStatus::singular : AssemblyStatus::not_assembled;
    out.reason = fmt::format("couplings {} and {} coincide", quoted(*d.j1), quoted(*d.j3));
    if (out.status == AssemblyStatus::not_assembled) return out;
  }
  const double along = dist > 0 ? (dist * dist + l1 * l1 - l2 * l2) / (2 * dist) : 0.0;
  const double h2 = l1 * l1 - along * along;
  out.discriminant = h2 / scale;
  if (out.status == AssemblyStatus::assembled) out.status = judge(out.discriminant);
  if (out.status == AssemblyStatus::not_assembled) {
    out.reason = fmt::format("the distance {:.6g} between couplings {} and {} is outside [{:.6g}, {:.6g}] (|l1 - l2|, l1 + l2)",
                             dist, quoted(*d.j1), quoted(*d.j3), std::abs(l1 - l2), l1 + l2);
    return out;
  }
  if (out.status == AssemblyStatus::singular && out.reason.empty())
    out.reason = fmt::format("couplings {}, {} and {} are collinear (two branches meet)", quoted(*d.j1), quoted(*d.j2), quoted(*d.j3));
  const double h = out.status == AssemblyStatus::singular ? 0.0 : std::sqrt(h2);
  const Vec2 e = dist > 0 ? Vec2(D / dist) : Vec2(1, 0);
  const Vec2 P2 = P1 + along * e + s * h * quarter(e);
  out.pose1 = pose_through(p1, p2, P1, P2);
  out.pose2 = pose_through(p2, p3, P2, P3);
  return out;
}

ClosedForm solve_rrp(const DyadParts& d, const Pose& pa, const Pose& pb, double s) {
  ClosedForm out;
  const Vec2 p1 = point_of(*d.j1), p2 = point_of(*d.j2);
  const Vec2 P1 = apply(pa, p1);
  const Vec2 u = rotation(pb.angle) * axis_of(*d.j3);
  const Vec2 Q = apply(pb, p2);  // b2 keeps B's orientation: its point p2 slides on the line through Q along u
  const Vec2 foot = Q + (P1 - Q).dot(u) * u;
  const double l1 = (p2 - p1).norm();
  const double h2 = l1 * l1 - (P1 - foot).squaredNorm();
  out.discriminant = h2 / (l1 * l1);
  out.status = judge(out.discriminant);
  if (out.status == AssemblyStatus::not_assembled) {
    out.reason = fmt::format("coupling {} is {:.6g} from the slide line of {}, more than the length {:.6g} to {}",
                             quoted(*d.j1), (P1 - foot).norm(), quoted(*d.j3), l1, quoted(*d.j2));
    return out;
  }
  if (out.status == AssemblyStatus::singular)
    out.reason = fmt::format("link {}-{} is normal to the slide axis of {} (two branches meet)", quoted(*d.j1), quoted(*d.j2), quoted(*d.j3));
  const double h = out.status == AssemblyStatus::singular ? 0.0 : std::sqrt(h2);
  const Vec2 P2 = foot + s * h * u;
  out.pose1 = pose_through(p1, p2, P1, P2);
  out.pose2 = pose_through(pb.angle, p2, P2);
  return out;
}

ClosedForm solve_rpr(const DyadParts& d, const Pose& pa, const Pose& pb, double s, double length) {
  ClosedForm out;
  const Vec2 p1 = point_of(*d.j1), p3 = point_of(*d.j3);
  const Vec2 a = axis_of(*d.j2), n = quarter(a);
  const Vec2 P1 = apply(pa, p1), P3 = apply(pb, p3);
  const Vec2 D = P3 - P1;
  const double dist = D.norm();
  const double c = n.dot(p3 - p1);  // offset of J3 from the slide line through J1, kept by every position
  if (dist <= kCoincident * length) {
    out.status = std::abs(c) <= kCoincident * length ? AssemblyStatus::singular : AssemblyStatus::not_assembled;
    out.reason = fmt::format("couplings {} and {} coincide", quoted(*d.j1), quoted(*d.j3));
    if (out.status == AssemblyStatus::not_assembled) return out;
  }
  const double ratio = dist > 0 ? c / dist : 0.0;
  out.discriminant = 1 - ratio * ratio;
  if (out.status == AssemblyStatus::assembled) out.status = judge(out.discriminant);
  if (out.status == AssemblyStatus::not_assembled) {
    out.reason = fmt::format("couplings {} and {} are {:.6g} apart, less than the offset {:.6g} of the slide axis of {}",
                             quoted(*d.j1), quoted(*d.j3), dist, std::abs(c), quoted(*d.j2));
    return out;
  }
  if (out.status == AssemblyStatus::singular && out.reason.empty())
    out.reason = fmt::format("the slide axis of {} is normal to {}-{} (two branches meet)", quoted(*d.j2), quoted(*d.j1), quoted(*d.j3));
  // (R(φ) n)·D = c: the angle of R(φ) n from D is ±acos(c / d); (R(φ) a)·D = d sin(that angle).
  const double gamma = std::acos(std::clamp(ratio, -1.0, 1.0));
  const double phi = std::atan2(D.y(), D.x()) - std::atan2(n.y(), n.x()) + s * gamma;
  out.pose1 = pose_through(phi, p1, P1);
  out.pose2 = pose_through(phi, p3, P3);
  return out;
}

// PRP: line–line.
ClosedForm solve_prp(const DyadParts& d, const Pose& pa, const Pose& pb, double length) {
  ClosedForm out;
  const Vec2 p2 = point_of(*d.j2);
  const Vec2 u1 = rotation(pa.angle) * axis_of(*d.j1), u3 = rotation(pb.angle) * axis_of(*d.j3);
  const Vec2 Q1 = apply(pa, p2), Q3 = apply(pb, p2);
  const double sine = cross(u1, u3);
  out.discriminant = std::abs(sine);
  if (std::abs(sine) <= kAssemblyDiscriminant) {
    const bool same_line = std::abs(cross(u1, Q3 - Q1)) <= kCoincident * length;
    out.status = same_line ? AssemblyStatus::singular : AssemblyStatus::not_assembled;
    out.reason = fmt::format("the slide axes of {} and {} are parallel", quoted(*d.j1), quoted(*d.j3));
    if (!same_line) return out;
  }
  const double along = out.status == AssemblyStatus::singular ? 0.0 : cross(Q3 - Q1, u3) / sine;
  const Vec2 P2 = Q1 + along * u1;
  out.pose1 = pose_through(pa.angle, p2, P2);
  out.pose2 = pose_through(pb.angle, p2, P2);
  return out;
}

// Solves a dyad for branch `sign` (±1) at `poses` (A and B placed).
ClosedForm solve_dyad(const std::string& type, const DyadParts& d, const std::vector<Pose>& poses, int sign, double length) {
  const Pose& pa = poses[static_cast<std::size_t>(d.a)];
  const Pose& pb = poses[static_cast<std::size_t>(d.b)];
  const double s = sign < 0 ? -1.0 : 1.0;
  if (type == "RRR") return solve_rrr(d, pa, pb, s, length);
  if (type == "RRP") return solve_rrp(d, pa, pb, s);
  if (type == "RPR") return solve_rpr(d, pa, pb, s, length);
  return solve_prp(d, pa, pb, length);  // one position: no branch
}

// The branch indicator of a dyad at `poses` (whose dyad bodies are placed): RRR the orientation
// cross(J3 − J1, J2 − J1); RRP (J2 − J1)·u3; RPR (R a2)·(J3 − J1). 0 for PRP.
double branch_indicator(const std::string& type, const DyadParts& d, const std::vector<Pose>& poses) {
  const Pose& p1 = poses[static_cast<std::size_t>(d.b1)];
  const Pose& p2 = poses[static_cast<std::size_t>(d.b2)];
  if (type == "RRR") {
    const Vec2 J1 = apply(p1, point_of(*d.j1)), J2 = apply(p1, point_of(*d.j2)), J3 = apply(p2, point_of(*d.j3));
    return cross(J3 - J1, J2 - J1);
  }
  if (type == "RRP") {
    const Vec2 J1 = apply(p1, point_of(*d.j1)), J2 = apply(p1, point_of(*d.j2));
    return (J2 - J1).dot(rotation(p2.angle) * axis_of(*d.j3));
  }
  if (type == "RPR") {
    const Vec2 J1 = apply(p1, point_of(*d.j1)), J3 = apply(p2, point_of(*d.j3));
    return (rotation(p1.angle) * axis_of(*d.j2)).dot(J3 - J1);
  }
  return 0.0;
}

std::string branch_text(const std::string& type, const DyadParts& d, int sign) {
  if (type == "RRR") {
    // cross(J3 − J1, J2 − J1) > 0: J2 left of J1→J3, so (J1, J3, J2) counter-clockwise and (J1, J2, J3) clockwise.
    return fmt::format("triangle ({}, {}, {}) {}", d.j1->name, d.j2->name, d.j3->name, sign > 0 ? "clockwise" : "counter-clockwise");
  }
  if (type == "RRP")
    return fmt::format("{} on the {} side of {} along the slide axis of {}", d.j2->name, sign > 0 ? "positive" : "negative", d.j1->name,
                       d.j3->name);
  if (type == "RPR")
    return fmt::format("{} on the {} side of {} along the slide axis of {}", d.j3->name, sign > 0 ? "positive" : "negative", d.j1->name,
                       d.j2->name);
  return "single solution";
}

// ---- Newton on a group's closure equations ---------------------------------------------------

struct Equations {
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;  // columns: x/L, y/L, θ of each group body
};

// Closure of `couplings` (drivers with their values) at `poses`; derivatives with respect to the
// group bodies listed in `column_of` (−1: solved, constant).
Equations closure(const network::Model& model, const std::vector<int>& couplings, const std::vector<int>& drivers,
                  const std::vector<double>& values, const std::vector<Pose>& poses, const std::vector<int>& column_of,
                  Eigen::Index unknowns, double length) {
  Eigen::Index rows = 0;
  for (int c : couplings) {
    rows += 2;
    if (std::find(drivers.begin(), drivers.end(), c) != drivers.end()) ++rows;
  }
  Equations e{Eigen::VectorXd::Zero(rows), Eigen::MatrixXd::Zero(rows, unknowns)};
  Eigen::Index r = 0;
  auto col = [&](int body) { return column_of[static_cast<std::size_t>(body)]; };
  for (int index : couplings) {
    const network::Coupling& c = model.couplings[static_cast<std::size_t>(index)];
    const Pose& pi = poses[static_cast<std::size_t>(c.from)];
    const Pose& pj = poses[static_cast<std::size_t>(c.to)];
    const int ci = col(c.from), cj = col(c.to);
    const Vec2 ti = translation(pi), tj = translation(pj);
    const auto driver = std::find(drivers.begin(), drivers.end(), index);
    const bool driven = driver != drivers.end();
    const double value = driven ? values[static_cast<std::size_t>(driver - drivers.begin())] : 0.0;
    if (is_revolute(c)) {
      const Vec2 p = point_of(c);
      const Vec2 Ri = rotation(pi.angle) * p, Rj = rotation(pj.angle) * p;
      e.residual.segment<2>(r) = (Ri + ti - Rj - tj) / length;
      if (ci >= 0) {
        e.jacobian.block<2, 2>(r, ci) += Eigen::Matrix2d::Identity();
        e.jacobian.block<2, 1>(r, ci + 2) += quarter(Ri) / length;
      }
      if (cj >= 0) {
        e.jacobian.block<2, 2>(r, cj) -= Eigen::Matrix2d::Identity();
        e.jacobian.block<2, 1>(r, cj + 2) -= quarter(Rj) / length;
      }
      r += 2;
      if (driven) {
        e.residual(r) = wrapped(pj.angle - pi.angle - value);
        if (cj >= 0) e.jacobian(r, cj + 2) += 1;
        if (ci >= 0) e.jacobian(r, ci + 2) -= 1;
        ++r;
      }
    } else {
      const Vec2 a = rotation(pi.angle) * axis_of(c), n = quarter(a);
      const Vec2 gap = tj - ti;
      e.residual(r) = wrapped(pj.angle - pi.angle);
      if (cj >= 0) e.jacobian(r, cj + 2) += 1;
      if (ci >= 0) e.jacobian(r, ci + 2) -= 1;
      ++r;
      std::vector<std::pair<Vec2, double>> rows_of{{n, 0.0}};
      if (driven) rows_of.push_back({a, value});
      for (const auto& [direction, target] : rows_of) {
        e.residual(r) = (direction.dot(gap) - target) / length;
        if (cj >= 0) e.jacobian.block<1, 2>(r, cj) += direction.transpose();
        if (ci >= 0) {
          e.jacobian.block<1, 2>(r, ci) -= direction.transpose();
          e.jacobian(r, ci + 2) += quarter(direction).dot(gap) / length;
        }
        ++r;
      }
    }
  }
  return e;
}

double largest(const Eigen::VectorXd& v) { return v.size() == 0 ? 0.0 : v.cwiseAbs().maxCoeff(); }

GroupSolution solve_by_newton(const network::Model& model, const PositionPlan& plan, const GroupPlan& group,
                              const std::vector<double>& values, std::vector<Pose>& poses) {
  GroupSolution out;
  std::vector<int> column_of(model.bodies.size(), -1);
  for (std::size_t k = 0; k < group.bodies.size(); ++k) column_of[static_cast<std::size_t>(group.bodies[k])] = static_cast<int>(3 * k);
  const auto unknowns = static_cast<Eigen::Index>(3 * group.bodies.size());
  auto evaluate = [&](const std::vector<Pose>& at) {
    return closure(model, group.couplings, plan.drivers, values, at, column_of, unknowns, plan.length);
  };
  auto moved = [&](const std::vector<Pose>& from, const Eigen::VectorXd& step) {
    std::vector<Pose> to = from;
    for (int body : group.bodies) {
      const auto c = column_of[static_cast<std::size_t>(body)];
      Pose& p = to[static_cast<std::size_t>(body)];
      p.x += step(c) * plan.length;
      p.y += step(c + 1) * plan.length;
      p.angle += step(c + 2);
    }
    return to;
  };
  Equations e = evaluate(poses);
  double residual = largest(e.residual);
  int iteration = 0;
  for (; iteration < 50 && residual > kCorrectorTarget; ++iteration) {
    const Eigen::VectorXd step = e.jacobian.completeOrthogonalDecomposition().solve(-e.residual);
    // Halve the step until the residual decreases (at most 20 times).
    double factor = 1.0;
    bool improved = false;
    for (int halving = 0; halving < 20; ++halving, factor /= 2) {
      std::vector<Pose> trial = moved(poses, factor * step);
      Equations next = evaluate(trial);
      const double r = largest(next.residual);
      if (r < residual) {
        poses = std::move(trial);
        e = std::move(next);
        residual = r;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  for (int body : group.bodies) poses[static_cast<std::size_t>(body)].angle = wrapped(poses[static_cast<std::size_t>(body)].angle);
  out.iterations = iteration;
  out.discriminant = residual;
  if (residual > kPositionResidual) {
    out.status = AssemblyStatus::not_assembled;
    out.reason = fmt::format("Newton's method did not close the group (residual {:.3g} after {} iterations): no assembly near the "
                             "previous configuration",
                             residual, iteration);
    return out;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(e.jacobian);
  const Eigen::VectorXd sigma = svd.singularValues();
  const bool singular = sigma.size() == 0 || sigma(sigma.size() - 1) <= kSingularPosition * sigma(0) ||
                        e.jacobian.rows() < e.jacobian.cols();
  out.status = singular ? AssemblyStatus::singular : AssemblyStatus::assembled;
  if (singular) out.reason = "the group's closure equations are singular here (branches meet or the group can move)";
  return out;
}

}  // namespace

const char* group_method_name(GroupMethod method) {
  switch (method) {
    case GroupMethod::driving_link: return "driving_link";
    case GroupMethod::closed_form: return "closed_form";
    case GroupMethod::newton: return "newton";
  }
  return "newton";
}

const char* assembly_status_name(AssemblyStatus status) {
  switch (status) {
    case AssemblyStatus::assembled: return "assembled";
    case AssemblyStatus::singular: return "singular";
    case AssemblyStatus::not_assembled: return "not_assembled";
    case AssemblyStatus::not_reached: return "not_reached";
  }
  return "not_reached";
}

namespace {

// Position solving handles planar revolute and prismatic couplings (a prismatic one with an axis
// in the plane); anything else is a PositionModelError at the coupling.
void refuse_unsolvable_couplings(const network::Model& model) {
  if (!model.space.is_planar()) throw PositionModelError("position solving needs a planar model (dimension: planar)");
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const auto& c = model.couplings[i];
    if (c.type != CouplingType::revolute && c.type != CouplingType::prismatic)
      throw PositionModelError(fmt::format("coupling '{}' is {}: position solving handles revolute and prismatic couplings only",
                                           c.name, screw::coupling_type_name(c.type)),
                               static_cast<int>(i));
    if (c.type == CouplingType::prismatic && (!c.geometry.axis || ((*c.geometry.axis)[0] == 0 && (*c.geometry.axis)[1] == 0)))
      throw PositionModelError(fmt::format("prismatic coupling '{}' needs an axis in the plane", c.name), static_cast<int>(i));
  }
}

// The coupling index of each of the model's inputs, in order; each coupling driven once.
std::vector<int> driving_couplings(const network::Model& model) {
  std::vector<int> drivers;
  for (const std::string& name : model.inputs) {
    const auto it = std::find_if(model.couplings.begin(), model.couplings.end(), [&](const auto& c) { return c.name == name; });
    if (it == model.couplings.end()) throw PositionModelError(fmt::format("input '{}' names no coupling", name));
    const int index = static_cast<int>(it - model.couplings.begin());
    if (std::find(drivers.begin(), drivers.end(), index) != drivers.end())
      throw PositionModelError(fmt::format("coupling '{}' is driven twice; a revolute or prismatic coupling takes one input", name), index);
    drivers.push_back(index);
  }
  return drivers;
}

// A decomposition that leaves bodies out cannot be solved group by group: says why.
void refuse_incomplete(const structure::StructureResult& decomposition) {
  if (decomposition.complete()) return;
  const auto& u = decomposition.undecomposed;
  std::string why;
  if (u.missing > 0) why = fmt::format("{} more input{} needed", u.missing, u.missing == 1 ? " is" : "s are");
  else if (u.redundant > 0) why = fmt::format("{} input{} or pair{} too many", u.redundant, u.redundant == 1 ? "" : "s", u.redundant == 1 ? "" : "s");
  else why = "some bodies are not connected to the frame";
  throw PositionModelError(fmt::format("the inputs do not decompose the mechanism into structural groups ({}); position solving needs as many "
                          "inputs as the mobility, placed so that every body is driven",
                          why));
}

// Structure bodies → network bodies, by name.
std::vector<int> network_bodies(const network::Model& model, const structure::StructureModel& structure) {
  std::vector<int> body_of(structure.body_names.size(), -1);
  for (std::size_t k = 0; k < structure.body_names.size(); ++k) {
    const auto it = std::find(model.bodies.begin(), model.bodies.end(), structure.body_names[k]);
    if (it == model.bodies.end()) throw PositionModelError("structure model and network model name different bodies");
    body_of[k] = static_cast<int>(it - model.bodies.begin());
  }
  return body_of;
}

// A group of two bodies and three couplings, none driven: a dyad J1 (to A) – J2 – J3 (to B),
// solved in closed form when its type has one and no link of it is degenerate, else by Newton.
// Leaves `group.type` empty when the couplings do not form such a chain.
void plan_dyad(const network::Model& model, const PositionPlan& plan, GroupPlan& group) {
  auto C = [&](int i) -> const network::Coupling& { return model.couplings[static_cast<std::size_t>(i)]; };
  const int b1 = group.bodies[0], b2 = group.bodies[1];
  std::vector<int> internal, on1, on2;
  for (int c : group.couplings) {
    const bool t1 = touches(C(c), b1), t2 = touches(C(c), b2);
    (t1 && t2 ? internal : t1 ? on1 : on2).push_back(c);
  }
  if (internal.size() != 1 || on1.size() != 1 || on2.size() != 1) return;
  group.chain = {on1[0], internal[0], on2[0]};
  if (!is_revolute(C(group.chain[0])) && is_revolute(C(group.chain[2]))) std::swap(group.chain[0], group.chain[2]);
  const std::string type{letter(C(group.chain[0])), letter(C(group.chain[1])), letter(C(group.chain[2]))};
  group.type = "dyad " + type;
  const bool closed = type == "RRR" || type == "RRP" || type == "RPR" || type == "PRP";
  // Coincident joints on a link give it no direction: such a dyad goes to Newton.
  bool degenerate = false;
  if (type == "RRR" || type == "RRP")
    degenerate = (point_of(C(group.chain[1])) - point_of(C(group.chain[0]))).norm() <= kCoincident * plan.length;
  if (type == "RRR")
    degenerate = degenerate || (point_of(C(group.chain[2])) - point_of(C(group.chain[1]))).norm() <= kCoincident * plan.length;
  group.method = closed && !degenerate ? GroupMethod::closed_form : GroupMethod::newton;
  if (group.method == GroupMethod::closed_form) {
    const DyadParts parts = dyad_parts(model, group);
    const std::vector<Pose> file(model.bodies.size());  // the configuration as written
    const double indicator = branch_indicator(type, parts, file);
    group.branch_sign = indicator < 0 ? -1 : 1;
    group.branch = branch_text(type, parts, group.branch_sign);
    if (type != "PRP" && indicator == 0) group.branch += " (chosen: the file's configuration is itself singular)";
  }
}

// The plan of structural group `sg` (bodies already in network numbering through `body_of`):
// its couplings (within it, or to a body `solved` before it), the groups it comes after, and
// how it is solved — a driving link, a dyad in closed form, or Newton's method.
GroupPlan plan_group(const network::Model& model, const PositionPlan& plan, const structure::StructuralGroup& sg,
                     const std::vector<int>& body_of, const std::vector<std::size_t>& index_of_number,
                     const std::vector<bool>& solved) {
  GroupPlan group;
  group.number = sg.number;
  for (int b : sg.bodies) group.bodies.push_back(body_of[static_cast<std::size_t>(b)]);
  for (int a : sg.after)
    if (a > 0 && static_cast<std::size_t>(a) < index_of_number.size()) group.after.push_back(index_of_number[static_cast<std::size_t>(a)]);
  auto in_group = [&](int body) { return std::find(group.bodies.begin(), group.bodies.end(), body) != group.bodies.end(); };
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const auto& c = model.couplings[i];
    const bool from = in_group(c.from), to = in_group(c.to);
    if ((from && (to || solved[static_cast<std::size_t>(c.to)])) || (to && solved[static_cast<std::size_t>(c.from)]))
      group.couplings.push_back(static_cast<int>(i));
  }
  auto driven = [&](int c) { return std::find(plan.drivers.begin(), plan.drivers.end(), c) != plan.drivers.end(); };
  const bool any_driver = std::any_of(group.couplings.begin(), group.couplings.end(), driven);
  auto C = [&](int i) -> const network::Coupling& { return model.couplings[static_cast<std::size_t>(i)]; };
  if (group.bodies.size() == 1 && group.couplings.size() == 1 && driven(group.couplings[0])) {
    group.method = GroupMethod::driving_link;
    group.type = fmt::format("driving link {}", letter(C(group.couplings[0])));
    group.branch = "single solution";
  } else if (group.bodies.size() == 2 && group.couplings.size() == 3 && !any_driver) {
    plan_dyad(model, plan, group);
  }
  if (group.type.empty()) {
    // Four bodies and six couplings: a triad (a ternary link and three binary links, three
    // internal couplings) or a tetrad (a closed loop of four links, four internal couplings).
    const auto internal = std::count_if(group.couplings.begin(), group.couplings.end(),
                                        [&](int c) { return in_group(C(c).from) && in_group(C(c).to); });
    std::string name = "group";
    if (group.bodies.size() == 4 && group.couplings.size() == 6 && internal == 3) name = "triad (class III)";
    if (group.bodies.size() == 4 && group.couplings.size() == 6 && internal == 4) name = "tetrad (class IV)";
    if (group.bodies.size() == 2 && group.couplings.size() == 3 && internal == 1) name = "dyad";
    group.type = fmt::format("{} of {} bodies and {} couplings", name, group.bodies.size(), group.couplings.size());
  }
  if (group.method == GroupMethod::newton) group.branch = "the one Newton's method reaches from the previous configuration";
  return group;
}

}  // namespace

PositionPlan plan_positions(const network::Model& model, const structure::StructureModel& structure,
                            const structure::StructureResult& decomposition) {
  refuse_unsolvable_couplings(model);
  PositionPlan plan;
  plan.frame = model.ground.value_or(0);
  plan.length = characteristic_length(model);
  plan.drivers = driving_couplings(model);
  refuse_incomplete(decomposition);
  const std::vector<int> body_of = network_bodies(model, structure);
  std::vector<bool> solved(model.bodies.size(), false);
  solved[static_cast<std::size_t>(plan.frame)] = true;
  std::vector<std::size_t> index_of_number(decomposition.groups.size() + 1, 0);
  for (std::size_t g = 0; g < decomposition.groups.size(); ++g) {
    const structure::StructuralGroup& sg = decomposition.groups[g];
    if (static_cast<std::size_t>(sg.number) < index_of_number.size()) index_of_number[static_cast<std::size_t>(sg.number)] = g;
    GroupPlan group = plan_group(model, plan, sg, body_of, index_of_number, solved);
    for (int b : group.bodies) solved[static_cast<std::size_t>(b)] = true;
    plan.groups.push_back(std::move(group));
  }
  return plan;
}

namespace {

// A revolute input far beyond one turn (1e20 rad) loses its angle in `pj − pi − value` and in
// std::remainder by the double nearest 2π (the error grows as value × 2.4e-16). sin and cos
// reduce their argument exactly, so the angle within one turn is atan2(sin, cos). Values of up
// to a million turns keep their written value: the residuals lose at most 1e-9 rad there.
constexpr double kExactlyReducedAngle = 2 * std::numbers::pi * 1e6;
std::vector<double> within_one_turn(const network::Model& model, const PositionPlan& plan, std::vector<double> values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (is_revolute(model.couplings[static_cast<std::size_t>(plan.drivers[i])]) && std::abs(values[i]) > kExactlyReducedAngle)
      values[i] = std::atan2(std::sin(values[i]), std::cos(values[i]));
  return values;
}

}  // namespace

PositionResult solve_positions(const network::Model& model, const PositionPlan& plan, const std::vector<double>& given_values,
                               const std::vector<Pose>& start) {
  if (given_values.size() != plan.drivers.size()) throw Error("one value per input is needed");
  const std::vector<double> values = within_one_turn(model, plan, given_values);
  PositionResult result;
  result.poses = start.size() == model.bodies.size() ? start : std::vector<Pose>(model.bodies.size());
  result.poses[static_cast<std::size_t>(plan.frame)] = Pose{};
  result.groups.resize(plan.groups.size());
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    const GroupPlan& group = plan.groups[g];
    GroupSolution& out = result.groups[g];
    const bool reached = std::all_of(group.after.begin(), group.after.end(), [&](std::size_t a) {
      return a < g && (result.groups[a].status == AssemblyStatus::assembled || result.groups[a].status == AssemblyStatus::singular);
    });
    if (!reached) {
      out.status = AssemblyStatus::not_reached;
      out.reason = "a group it is placed on was not assembled";
      continue;
    }
    if (group.method == GroupMethod::driving_link) {
      const int body = group.bodies[0];
      const int index = group.couplings[0];
      const network::Coupling& c = model.couplings[static_cast<std::size_t>(index)];
      const auto driver = std::find(plan.drivers.begin(), plan.drivers.end(), index) - plan.drivers.begin();
      const double value = values[static_cast<std::size_t>(driver)];
      const double sign = c.to == body ? 1.0 : -1.0;
      const Pose& solved = result.poses[static_cast<std::size_t>(other(c, body))];
      if (is_revolute(c)) {
        result.poses[static_cast<std::size_t>(body)] = pose_through(solved.angle + sign * value, point_of(c), apply(solved, point_of(c)));
      } else {
        const Vec2 t = translation(solved) + sign * value * (rotation(solved.angle) * axis_of(c));
        result.poses[static_cast<std::size_t>(body)] = {t.x(), t.y(), solved.angle};
      }
      out.status = AssemblyStatus::assembled;
    } else if (group.method == GroupMethod::closed_form) {
      const DyadParts parts = dyad_parts(model, group);
      const std::string type = group.type.substr(5);
      const ClosedForm solution = solve_dyad(type, parts, result.poses, group.branch_sign, plan.length);
      out.status = solution.status;
      out.discriminant = solution.discriminant;
      out.reason = solution.reason;
      if (solution.status != AssemblyStatus::not_assembled) {
        result.poses[static_cast<std::size_t>(parts.b1)] = solution.pose1;
        result.poses[static_cast<std::size_t>(parts.b2)] = solution.pose2;
      }
    } else {
      out = solve_by_newton(model, plan, group, values, result.poses);
    }
    if (out.status == AssemblyStatus::not_assembled && !result.failed_group) result.failed_group = g;
  }
  result.assembled = std::all_of(result.groups.begin(), result.groups.end(), [](const GroupSolution& s) {
    return s.status == AssemblyStatus::assembled || s.status == AssemblyStatus::singular;
  });
  if (result.assembled) {
    std::vector<int> all(model.couplings.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    const std::vector<int> none(model.bodies.size(), -1);
    result.max_residual = largest(closure(model, all, plan.drivers, values, result.poses, none, 0, plan.length).residual);
  }
  return result;
}

double coupling_value(const network::Model& model, const std::vector<Pose>& poses, int coupling) {
  const network::Coupling& c = model.couplings[static_cast<std::size_t>(coupling)];
  const Pose& from = poses[static_cast<std::size_t>(c.from)];
  const Pose& to = poses[static_cast<std::size_t>(c.to)];
  if (is_revolute(c)) return wrapped(to.angle - from.angle);
  return (rotation(from.angle) * axis_of(c)).dot(translation(to) - translation(from));
}

std::array<double, 2> coupling_point(const network::Model& model, const std::vector<Pose>& poses, int coupling) {
  const network::Coupling& c = model.couplings[static_cast<std::size_t>(coupling)];
  const Vec2 p = apply(poses[static_cast<std::size_t>(c.to)], point_of(c));
  return {p.x(), p.y()};
}

}  // namespace kinestat::kinematics
