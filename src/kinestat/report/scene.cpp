// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/scene.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kinestat/graph/coupling_graph.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/rank_status_text.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/screw/coupling_type.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::report {

namespace {

using Eigen::Vector3d;

Vector3d to_vector(const screw::Vec3& v) { return {v[0].get_d(), v[1].get_d(), v[2].get_d()}; }

// Status and distance of a rank decision, as the text report prints them (rank_status_text).
std::string rank_evidence(const linalg::RankDecision& rank) { return rank_status_text(rank); }

std::vector<double> screw_doubles(const std::vector<screw::Rational>& coordinates) {
  std::vector<double> out;
  out.reserve(coordinates.size());
  for (const auto& value : coordinates) out.push_back(value.get_d());
  return out;
}

/// The two 3-vectors of a d-coordinate screw: (ω, velocity of the point at the origin) of a
/// motion in axis formation, (moment at the origin, force) of an action in ray formation.
std::pair<Vector3d, Vector3d> twist_of(const screw::ScrewSpace& space, const Eigen::VectorXd& motion) {
  std::array<double, 6> full{};
  for (int i = 0; i < space.dimension(); ++i) full[static_cast<std::size_t>(space.components[static_cast<std::size_t>(i)])] = motion(i);
  return {Vector3d(full[0], full[1], full[2]), Vector3d(full[3], full[4], full[5])};
}


/// The axis of a screw whose "line" part is `line` (ω of a twist, force of a wrench) and whose
/// "moment" part is `moment` (velocity of the origin point, moment about the origin); both
/// formations give the axis point line × moment / |line|². `length` makes the two comparable.
SceneScrew screw_axis(const std::string& name, const Vector3d& anchor, const Vector3d& line, const Vector3d& moment,
                      double length) {
  SceneScrew screw;
  screw.name = name;
  screw.anchor = anchor;
  screw.point = anchor;
  const double size = line.norm() * length + moment.norm();
  if (line.norm() * length > kScrewZero * size) {
    screw.direction = line.normalized();
    screw.magnitude = line.norm();
    screw.pitch = line.dot(moment) / line.squaredNorm();
    const Vector3d nearest_origin = line.cross(moment) / line.squaredNorm();
    screw.point = nearest_origin + (anchor - nearest_origin).dot(screw.direction) * screw.direction;
  } else {
    screw.pure = true;
    screw.direction = moment.norm() > 0 ? Vector3d(moment.normalized()) : Vector3d::UnitZ();
    screw.magnitude = moment.norm();
  }
  return screw;
}

/// Kind of a framework deformation for colouring: elongation, torsion, bending or rigid.
std::string deformation_kind(framework::ElementType type, const std::string& name) {
  if (type == framework::ElementType::rigid_body) return "rigid";
  if (name.rfind("bending", 0) == 0) return "bending";
  if (name == "torsion") return "torsion";
  return "elongation";
}

/// A spatial beam is a sheet when its deformation roles say so (seed 002, folded-sheet
/// flexures): elongation and bending in one element plane held, torsion and bending in the other
/// plane free. The sheet lies in the held plane: returns its in-plane direction across the beam.
std::optional<Vector3d> sheet_across(const framework::FrameworkModel& model, const framework::Element& element) {
  if (model.dimension != 3 || element.type != framework::ElementType::beam || element.roles.size() != 6) return std::nullopt;
  const auto held = [&](std::size_t k) { return element.roles[k] == framework::DeformationRole::fixed; };
  if (!held(0) || held(1)) return std::nullopt;
  // Deformations: elongation, torsion, bending_xz_p, bending_xz_q, bending_xy_p, bending_xy_q.
  if (held(2) && held(3) && !held(4) && !held(5)) return Vector3d(element.frame.col(2));  // sheet in the x-z plane
  if (held(4) && held(5) && !held(2) && !held(3)) return Vector3d(element.frame.col(1));  // sheet in the x-y plane
  return std::nullopt;
}

}  // namespace

std::string length_unit(const Scene& scene) { return scene.units.empty() ? std::string("model units") : scene.units; }

std::string fixed(double value, int digits) {
  if (!std::isfinite(value)) return "0";
  std::string text = fmt::format("{:.{}f}", value, digits);
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

namespace {

/// Where a network's bodies are drawn: each body's centre (the mean of its coupling points) and
/// the model's size (the largest distance between two drawn points before the markers).
struct NetworkLayout {
  std::vector<Vector3d> centre;
  double size = 1.0;
};

/// The largest distance between two of `points`: exact for pictures of up to
/// kExactExtentPoints points, the diagonal of their bounding box (at most √3 times larger)
/// above, so that large networks are laid out in linear time.
constexpr std::size_t kExactExtentPoints = 4096;
double drawing_extent(const std::vector<SceneNode>& nodes) {
  double extent = 0.0;
  if (nodes.size() <= kExactExtentPoints) {
    for (const auto& a : nodes)
      for (const auto& b : nodes) extent = std::max(extent, (a.position - b.position).norm());
    return extent;
  }
  Vector3d lo = nodes.front().position, hi = lo;
  for (const auto& node : nodes) {
    lo = lo.cwiseMin(node.position);
    hi = hi.cwiseMax(node.position);
  }
  return (hi - lo).norm();
}

/// The geometry every network picture shares, whatever the analysis: bodies as stars (a centre
/// linked to one end node per coupling), a glyph and a graph edge per coupling (without screws
/// or magnitude names), and a small three-armed marker on every body centre — a body rotating
/// about an axis through all its coupling points (Davies' sa, ta) would otherwise not visibly
/// move. At most one arm lies along any axis, so every rotation moves the marker.
NetworkLayout network_drawing(const network::Model& model, int ground, Scene& scene) {
  scene.kind = io::ModelKind::network;
  scene.name = model.name;
  scene.screw_dimension = model.space.dimension();
  scene.dimension = model.space.is_planar() ? 2 : 3;
  scene.bodies = model.bodies;
  scene.ground = ground;
  const std::size_t n = model.bodies.size();
  NetworkLayout layout;
  layout.centre.assign(n, Vector3d::Zero());
  std::vector<int> count(n, 0);
  for (const auto& c : model.couplings) {
    const Vector3d p = to_vector(c.geometry.point);
    for (int b : {c.from, c.to}) {
      layout.centre[static_cast<std::size_t>(b)] += p;
      ++count[static_cast<std::size_t>(b)];
    }
  }
  for (std::size_t b = 0; b < n; ++b) {
    if (count[b] > 0) layout.centre[b] /= count[b];
    scene.nodes.push_back({model.bodies[b], layout.centre[b], static_cast<int>(b), static_cast<int>(b) == ground, {}, {}});
  }
  for (const auto& c : model.couplings) {
    const Vector3d p = to_vector(c.geometry.point);
    for (int b : {c.from, c.to}) {
      scene.nodes.push_back({c.name + "@" + model.bodies[static_cast<std::size_t>(b)], p, b, b == ground, {}, {}});
      scene.elements.push_back({c.name, "link", b, static_cast<int>(scene.nodes.size()) - 1, false, std::nullopt});
    }
    SceneGlyph glyph;
    glyph.name = c.name;
    glyph.type = std::string(screw::coupling_type_name(c.type));
    glyph.from = c.from;
    glyph.to = c.to;
    glyph.point = p;
    if (c.geometry.axis) glyph.axis = to_vector(*c.geometry.axis);
    if (c.geometry.axis2) glyph.axis2 = to_vector(*c.geometry.axis2);
    if (c.geometry.normal) glyph.normal = to_vector(*c.geometry.normal);
    scene.glyphs.push_back(glyph);
    GraphEdge edge;
    edge.name = c.name;
    edge.from = c.from;
    edge.to = c.to;
    scene.edges.push_back(edge);
  }
  const double extent = drawing_extent(scene.nodes);
  const double arm = extent > 0.0 ? 0.1 * extent : 0.1;
  layout.size = extent > 0.0 ? extent : 1.0;  // compares the two halves of a screw
  const int arms = model.space.is_planar() ? 2 : 3;
  for (std::size_t b = 0; b < n; ++b)
    for (int axis = 0; axis < arms; ++axis) {
      scene.nodes.push_back({model.bodies[b] + ".marker" + std::to_string(axis), layout.centre[b] + arm * Vector3d::Unit(axis),
                             static_cast<int>(b), static_cast<int>(b) == ground, {}, {}});
      scene.elements.push_back({model.bodies[b] + ".marker", "link", static_cast<int>(b), static_cast<int>(scene.nodes.size()) - 1, false, std::nullopt});
    }
  return layout;
}

/// Node velocities of a mode from each body's twist relative to the ground (ω, velocity of the
/// point at the user's origin; user frame and length unit; `twists[b]` empty for the ground).
std::vector<Vector3d> node_velocities(const Scene& scene, const std::vector<std::optional<std::pair<Vector3d, Vector3d>>>& twists) {
  std::vector<Vector3d> velocity;
  velocity.reserve(scene.nodes.size());
  for (const auto& node : scene.nodes) {
    const auto& twist = twists[static_cast<std::size_t>(node.body)];
    velocity.push_back(twist ? Vector3d(twist->second + twist->first.cross(node.position)) : Vector3d::Zero());
  }
  return velocity;
}

// The summary table of a dense network result.
void add_network_summary(const network::NetworkResult& r, Scene& scene) {
  scene.summary = {
      {"kind", "coupling network (Davies, seed 000)"},
      {"d", std::to_string(r.d)},
      {"bodies n", std::to_string(r.bodies)},
      {"couplings e", std::to_string(r.e)},
      {"circuits l", std::to_string(r.l)},
      {"cutsets k", std::to_string(r.k)},
      {"gross freedoms F", std::to_string(r.F)},
      {"gross constraints C", std::to_string(r.C)},
      {"rank m of [M]N", rank_evidence(r.circulation.solution.rank)},
      {"rank a of [A]N", rank_evidence(r.cutset_law.solution.rank)},
      {"FN (nett degree of freedom)", std::to_string(r.FN)},
      {"CN (nett degree of constraint)", std::to_string(r.CN)},
      {"class", network::class_description(r.classification)},
      {"arithmetic", r.exact ? "exact" : "floating point"},
  };
}

// Each coupling's unit motions and actions (glyphs and graph edges) and the chords of its tree.
void add_network_glyphs(const network::Model& model, const network::NetworkResult& r, Scene& scene) {
  for (std::size_t e = 0; e < model.couplings.size(); ++e) {
    SceneGlyph& glyph = scene.glyphs[e];
    GraphEdge& edge = scene.edges[e];
    for (const auto& m : r.motions)
      if (m.coupling == static_cast<int>(e)) {
        glyph.motions.push_back(screw_doubles(m.unit_screw.coordinates));
        edge.motion_names.push_back(m.name);
      }
    for (const auto& a : r.actions)
      if (a.coupling == static_cast<int>(e)) {
        glyph.actions.push_back(screw_doubles(a.unit_screw.coordinates));
        edge.action_names.push_back(a.name);
      }
    glyph.f = edge.f = static_cast<int>(glyph.motions.size());
    glyph.c = edge.c = static_cast<int>(glyph.actions.size());
  }
  for (int chord : r.chords) scene.edges[static_cast<std::size_t>(chord)].branch = false;
}

void add_network_modes(const network::Model& model, const network::NetworkResult& r, const NetworkLayout& layout, Scene& scene) {
  // The motion of every body relative to the ground, per motion primary, as the analysis keeps
  // it (NetworkResult::body_motions: user frame and length unit).
  const std::size_t n = model.bodies.size();
  for (std::size_t k = 0; k < r.primary_motion.size(); ++k) {
    SceneMode mode;
    mode.label = "mode " + std::to_string(k + 1) + ": " + r.motions[static_cast<std::size_t>(r.primary_motion[k])].name + " = 1";
    // Network motions are traced (network/finite_motion) but drawn here by their twists only.
    mode.first_order_reason = "network motions are drawn by their twists here; 'kinestat move FILE --mode " + std::to_string(k + 1) +
                              "' traces the finite motion";
    // Sign: primary k = +1, as every report states it; nothing is flipped here.
    for (Eigen::Index row = 0; row < r.motion_magnitudes.values.rows(); ++row)
      if (static_cast<Eigen::Index>(k) < r.motion_magnitudes.values.cols() && r.motion_magnitudes.values(row, static_cast<Eigen::Index>(k)) != 0.0)
        mode.moving.push_back(r.motions[static_cast<std::size_t>(row)].name);
    std::vector<std::optional<std::pair<Vector3d, Vector3d>>> twists(n);
    for (std::size_t b = 0; b < n; ++b) {
      if (static_cast<int>(b) == r.ground || b >= r.body_motions.size()) continue;
      const auto& forms = r.body_motions[b].values;
      if (static_cast<Eigen::Index>(k) >= forms.cols()) continue;
      const Eigen::VectorXd motion = forms.col(static_cast<Eigen::Index>(k));
      twists[b] = twist_of(model.space, motion);
      if (motion.cwiseAbs().maxCoeff() == 0.0) continue;
      mode.twists.push_back(screw_axis(model.bodies[b], layout.centre[b], twists[b]->first, twists[b]->second, layout.size));
    }
    mode.velocity = node_velocities(scene, twists);
    scene.modes.push_back(std::move(mode));
  }
}

void add_network_stresses(const network::Model& model, const network::NetworkResult& r, const NetworkLayout& layout, Scene& scene) {
  // Self-stresses: action primary k = +1; the wrench each coupling transmits (the sum of its
  // unit actions times their magnitudes), in ray formation, as a line of action.
  for (std::size_t k = 0; k < r.primary_action.size(); ++k) {
    SceneStress stress;
    stress.label = "self-stress " + std::to_string(k + 1) + ": " + r.actions[static_cast<std::size_t>(r.primary_action[k])].name + " = 1";
    stress.value.assign(scene.elements.size(), 0.0);
    stress.kind.assign(scene.elements.size(), "");
    const auto& forms = r.action_magnitudes.values;
    for (std::size_t e = 0; e < model.couplings.size(); ++e) {
      Eigen::VectorXd action = Eigen::VectorXd::Zero(model.space.dimension());
      for (std::size_t a = 0; a < r.actions.size(); ++a) {
        if (r.actions[a].coupling != static_cast<int>(e) || static_cast<Eigen::Index>(k) >= forms.cols()) continue;
        const double magnitude = forms(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(k));
        if (magnitude == 0.0) continue;
        const auto unit = screw_doubles(r.actions[a].unit_screw.coordinates);
        for (std::size_t i = 0; i < unit.size(); ++i) action(static_cast<Eigen::Index>(i)) += magnitude * unit[i];
      }
      if (action.size() == 0 || action.cwiseAbs().maxCoeff() == 0.0) continue;
      const auto [moment, force] = twist_of(model.space, action);
      stress.wrenches.push_back(screw_axis(model.couplings[e].name, to_vector(model.couplings[e].geometry.point), force, moment, layout.size));
    }
    scene.stresses.push_back(std::move(stress));
  }
}

// The motion systems of the pairs of bodies, one entry per pair.
void add_network_pairs(const network::NetworkResult& r, Scene& scene) {
  for (const auto& pair : r.pairs) {
    bool seen = false;
    for (const auto& p : scene.pairs) seen = seen || (p.body_i == pair.body_i && p.body_j == pair.body_j);
    if (seen) continue;
    ScenePair sp{pair.body_i, pair.body_j, pair.fij, {}};
    for (int column : pair.motion_primaries) {
      std::vector<double> s;
      for (Eigen::Index row = 0; row < pair.motion_system.values.rows(); ++row) s.push_back(pair.motion_system.values(row, column));
      sp.motions.push_back(std::move(s));
    }
    scene.pairs.push_back(std::move(sp));
  }
}

// The summary table of a sparse network result.
void add_sparse_network_summary(const network::SparseNetworkResult& r, Scene& scene) {
  scene.summary = {
      {"kind", "coupling network (sparse body-twist form)"},
      {"d", std::to_string(r.d)},
      {"bodies n", std::to_string(r.bodies)},
      {"couplings e", std::to_string(r.e)},
      {"circuits l", std::to_string(r.l)},
      {"gross freedoms F", std::to_string(r.F)},
      {"gross constraints C", std::to_string(r.C)},
      {"rank of K", rank_evidence(r.rank)},
      {"FN (nett degree of freedom)", std::to_string(r.FN)},
      {"CN (nett degree of constraint)", std::to_string(r.CN)},
      {"class", network::class_description(r.classification)},
      {"couplings with a self-stress", std::to_string(r.stressed.size())},
      {"couplings that move", std::to_string(r.moving.size())},
      {"arithmetic", "floating point"},
  };
}

void add_sparse_network_glyphs(const network::Model& model, const network::SparseNetworkResult& r, Scene& scene) {
  // Each row of K is one unit action of its coupling (user frame in row_actions); f = d − c.
  for (std::size_t row = 0; row < r.row_coupling.size(); ++row) {
    const auto e = static_cast<std::size_t>(r.row_coupling[row]);
    const auto& action = r.row_actions[row];
    scene.glyphs[e].actions.emplace_back(action.coordinates.begin(), action.coordinates.begin() + r.d);
  }
  for (std::size_t e = 0; e < model.couplings.size(); ++e) {
    scene.glyphs[e].c = scene.edges[e].c = static_cast<int>(scene.glyphs[e].actions.size());
    scene.glyphs[e].f = scene.edges[e].f = r.d - scene.glyphs[e].c;
  }
  // No Davies tree on this path: the picture's tree is the breadth-first one from the ground.
  std::vector<graph::Edge> edges;
  edges.reserve(model.couplings.size());
  for (const auto& c : model.couplings) edges.push_back({c.from, c.to});
  for (int chord : graph::CouplingGraph(static_cast<int>(model.bodies.size()), edges).breadth_first_tree(r.ground).chords)
    scene.edges[static_cast<std::size_t>(chord)].branch = false;
}

void add_sparse_network_modes(const network::Model& model, const network::SparseNetworkResult& r, const NetworkLayout& layout, Scene& scene) {
  // The basis vectors are in the user's frame, per unit of their primary (network::
  // analyse_network_sparse); which bodies move is decided on their sizes in the conditioned
  // analysis frame (placement- and unit-free), as the analysis decides its supports.
  const std::size_t n = model.bodies.size();
  const auto column_of = [&](std::size_t b) { return static_cast<Eigen::Index>(static_cast<int>(b) < r.ground ? b : b - 1) * r.d; };
  for (Eigen::Index j = 0; j < r.motion_basis.cols(); ++j) {
    const Eigen::VectorXd& x = r.motion_basis.col(j);
    SceneMode mode;
    mode.label = fmt::format("mode {} (sparse QR basis)", j + 1);
    mode.first_order_reason = "drawn by its twists (first order): a basis vector of the sparse analysis, not traced";
    std::vector<std::optional<std::pair<Vector3d, Vector3d>>> twists(n);
    Eigen::VectorXd conditioned = Eigen::VectorXd::Zero(x.size());
    double largest = 0.0;
    for (std::size_t b = 0; b < n; ++b) {
      if (static_cast<int>(b) == r.ground) continue;
      twists[b] = twist_of(model.space, x.segment(column_of(b), r.d));
      conditioned.segment(column_of(b), r.d) = r.frame.twist_to_frame(x.segment(column_of(b), r.d), model.space);
      largest = std::max(largest, conditioned.segment(column_of(b), r.d).cwiseAbs().maxCoeff());
    }
    // Bodies and couplings that move: twist entries (conditioned frame) above kSupportZero of the largest.
    const auto moves = [&](std::size_t b) {
      return static_cast<int>(b) != r.ground && conditioned.segment(column_of(b), r.d).cwiseAbs().maxCoeff() > kSupportZero * largest;
    };
    for (std::size_t e = 0; e < model.couplings.size(); ++e) {
      const auto& c = model.couplings[e];
      const auto from = static_cast<std::size_t>(c.from), to = static_cast<std::size_t>(c.to);
      Eigen::VectorXd relative = Eigen::VectorXd::Zero(r.d);
      if (from != static_cast<std::size_t>(r.ground)) relative -= conditioned.segment(column_of(from), r.d);
      if (to != static_cast<std::size_t>(r.ground)) relative += conditioned.segment(column_of(to), r.d);
      if ((moves(from) || moves(to)) && relative.cwiseAbs().maxCoeff() > kSupportZero * largest) mode.moving.push_back(c.name);
    }
    for (std::size_t b = 0; b < n; ++b)
      if (moves(b)) mode.twists.push_back(screw_axis(model.bodies[b], layout.centre[b], twists[b]->first, twists[b]->second, layout.size));
    mode.velocity = node_velocities(scene, twists);
    scene.modes.push_back(std::move(mode));
  }
}

void add_sparse_network_stresses(const network::Model& model, const network::SparseNetworkResult& r, const NetworkLayout& layout, Scene& scene) {
  // Self-stresses: the wrench each coupling transmits (its unit actions times their magnitudes,
  // user frame: the magnitudes are the same in both frames), primary = 1.
  for (Eigen::Index j = 0; j < r.stress_basis.cols(); ++j) {
    const Eigen::VectorXd& lambda = r.stress_basis.col(j);  // per unit of its primary
    const double zero = kSupportZero * lambda.cwiseAbs().maxCoeff();
    SceneStress stress;
    stress.label = fmt::format("self-stress {} (sparse QR basis)", j + 1);
    stress.value.assign(scene.elements.size(), 0.0);
    stress.kind.assign(scene.elements.size(), "");
    std::vector<Eigen::VectorXd> wrench(model.couplings.size());
    for (Eigen::Index row = 0; row < lambda.size(); ++row) {
      if (std::abs(lambda(row)) <= zero) continue;
      const auto e = static_cast<std::size_t>(r.row_coupling[static_cast<std::size_t>(row)]);
      if (wrench[e].size() == 0) wrench[e] = Eigen::VectorXd::Zero(r.d);
      for (Eigen::Index i = 0; i < r.d; ++i) wrench[e](i) += lambda(row) * r.row_actions[static_cast<std::size_t>(row)].coordinates[static_cast<std::size_t>(i)];
    }
    for (std::size_t e = 0; e < model.couplings.size(); ++e) {
      if (wrench[e].size() == 0 || wrench[e].cwiseAbs().maxCoeff() == 0.0) continue;
      const auto [moment, force] = twist_of(model.space, wrench[e]);
      stress.wrenches.push_back(screw_axis(model.couplings[e].name, to_vector(model.couplings[e].geometry.point), force, moment, layout.size));
    }
    scene.stresses.push_back(std::move(stress));
  }
}

}  // namespace

Scene network_scene(const network::Model& model, const network::NetworkResult& result) {
  Scene scene;
  const auto& r = result;
  const NetworkLayout layout = network_drawing(model, r.ground, scene);
  add_network_summary(r, scene);
  add_network_glyphs(model, r, scene);
  scene.B = r.B;
  scene.Q = r.Q;
  add_network_modes(model, r, layout, scene);
  add_network_stresses(model, r, layout, scene);
  add_network_pairs(r, scene);
  scene.large = scene.elements.size() > kLargeSceneElements;
  return scene;
}

Scene sparse_network_scene(const network::Model& model, const network::SparseNetworkResult& r) {
  Scene scene;
  scene.sparse = true;
  scene.mode_total = static_cast<std::size_t>(r.FN);
  scene.stress_total = static_cast<std::size_t>(r.CN);
  const NetworkLayout layout = network_drawing(model, r.ground, scene);
  add_sparse_network_summary(r, scene);
  add_sparse_network_glyphs(model, r, scene);
  add_sparse_network_modes(model, r, layout, scene);
  add_sparse_network_stresses(model, r, layout, scene);
  scene.large = scene.elements.size() > kLargeSceneElements;
  return scene;
}

namespace {

// Node positions (3 × nodes) as scene points.
std::vector<Vector3d> scene_points(const Eigen::MatrixXd& positions) {
  std::vector<Vector3d> points;
  for (Eigen::Index k = 0; k < positions.cols(); ++k) points.emplace_back(positions.col(k));
  return points;
}

// Why one side of a two-way trace stops short, or "".
std::string short_side(const framework::FiniteTrace& side, const char* which, bool retraced) {
  if (side.closed && retraced)
    return fmt::format("the {} side is traced to arc length {} only (with larger steps the corrector lost closure)", which,
                       fixed(side.amplitude, 6));
  if (side.closed) return "";
  return fmt::format("the {} side stops at arc length {}: the corrector lost closure at its step {}", which, fixed(side.amplitude, 6),
                     side.failed_step);
}

// The path of a two-way trace from the far end of the backward side to the far end of the
// forward side; nothing when neither side got past the start.
std::optional<SceneTrace> scene_trace(const framework::TwoWayTrace& both) {
  const auto& f = both.forward;
  const auto& b = both.backward;
  if (f.positions.empty() || b.positions.empty() || f.positions.size() + b.positions.size() < 3) return std::nullopt;
  SceneTrace trace;
  for (std::size_t k = b.positions.size() - 1; k >= 1; --k) {
    trace.positions.push_back(scene_points(b.positions[k]));
    trace.arc.push_back(-b.arc_length_along_path[k]);
  }
  trace.start = trace.positions.size();
  for (std::size_t k = 0; k < f.positions.size(); ++k) {
    trace.positions.push_back(scene_points(f.positions[k]));
    trace.arc.push_back(f.arc_length_along_path[k]);
  }
  trace.max_residual = both.max_residual();
  const std::string forward = short_side(f, "forward (+mode)", both.forward_retraced),
                    backward = short_side(b, "backward (-mode)", both.backward_retraced);
  trace.note = forward.empty() ? backward : backward.empty() ? forward : forward + "; " + backward;
  if (both.rigid_part_removed)
    trace.note = std::string("traced without the mode's rigid motion of the whole model (the internal motion the second-order "
                             "analysis traced)") +
                 (trace.note.empty() ? "" : "; " + trace.note);
  return trace;
}

// Why a framework mode is drawn to first order only.
std::string first_order_reason(const framework::FrameworkResult& a, std::size_t k) {
  using framework::OrderReason;
  if (k >= a.orders.size()) return "second order not computed for this model (not traced)";
  const framework::ModeOrder& o = a.orders[k];
  switch (o.reason) {
    case OrderReason::prestress_stable:
    case OrderReason::blocked_by_stress:
      return "blocked at second order by a self-stress: an infinitesimal mechanism, it does not move finitely";
    case OrderReason::trace_failed: return fmt::format("the trace lost closure at step {} (no finite motion found)", o.trace.failed_step);
    case OrderReason::no_second_order_model: return "no second-order model of some element (not traced)";
    case OrderReason::not_computed: return "second order not computed (model too large, or tracing off)";
    case OrderReason::traced:
    case OrderReason::rigid_motion: return "the finite motion was not traced for this picture";
  }
  return "not traced";
}

// Sections of framework_scene: nodes with their supports, elements as lines, modes, and
// self-stresses per line.

// A node and its support: pinned or fixed when every translation is held (fixed when every
// rotation is too), a roller (with its free directions) when some are.
SceneNode framework_scene_node(const framework::FrameworkModel& model, const framework::Node& node) {
  int translations = 0, held = 0, rotations = 0, held_rotations = 0;
  std::vector<Vector3d> free_directions;
  for (int slot : framework::node_slots(model.dimension, node)) {
    const bool fixed_slot = node.roles[static_cast<std::size_t>(slot)] == framework::CoordinateRole::fixed;
    if (framework::is_translation(slot)) {
      ++translations;
      if (fixed_slot) ++held;
      else free_directions.push_back(Vector3d::Unit(slot));
    } else {
      ++rotations;
      if (fixed_slot) ++held_rotations;
    }
  }
  SceneNode scene_node{node.name, node.position, -1, held == translations && translations > 0, {}, {}};
  if (scene_node.fixed) scene_node.support = rotations > 0 && held_rotations == rotations ? "fixed" : "pinned";
  else if (held > 0) scene_node.support = "roller", scene_node.free_directions = free_directions;
  return scene_node;
}

// The lines of the elements: a rigid body's from its first node to each other node, a beam's
// or a bar's between its two nodes.
std::vector<SceneElement> framework_scene_elements(const framework::FrameworkModel& model) {
  std::vector<SceneElement> lines;
  for (const auto& element : model.elements) {
    if (element.nodes.empty()) continue;
    if (element.type == framework::ElementType::rigid_body) {
      for (std::size_t i = 1; i < element.nodes.size(); ++i)
        lines.push_back({element.name, "rigid", static_cast<int>(element.nodes[0]), static_cast<int>(element.nodes[i]), i == 1, std::nullopt});
    } else if (element.nodes.size() >= 2) {
      lines.push_back({element.name, element.type == framework::ElementType::beam ? "beam" : "truss",
                       static_cast<int>(element.nodes[0]), static_cast<int>(element.nodes[1]), true, sheet_across(model, element)});
    }
  }
  return lines;
}

// Mode k: translations of every node (D(c)'s are divided by the characteristic length; undone
// here), its moving coordinates, and its traced path or why it is drawn to first order.
SceneMode framework_scene_mode(const framework::FrameworkModel& model, const framework::FrameworkResult& a, std::size_t k,
                               const std::vector<std::optional<framework::TwoWayTrace>>& traces) {
  SceneMode mode;
  mode.label = "mode " + std::to_string(k + 1);
  mode.velocity.assign(model.nodes.size(), Vector3d::Zero());
  const auto& v = a.modes[k].velocities;
  for (Eigen::Index col = 0; col < v.size(); ++col) {
    const auto& ref = a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[static_cast<std::size_t>(col)])];
    if (framework::is_translation(ref.slot)) mode.velocity[ref.node](ref.slot) = v(col) * a.length;
  }
  for (Eigen::Index col : a.modes[k].moving) mode.moving.push_back(framework_column_label(model, a, col));
  if (k < traces.size() && traces[k]) mode.trace = scene_trace(*traces[k]);
  if (!mode.trace)
    mode.first_order_reason = k < traces.size() && traces[k] ? "tracing lost closure at the first step both ways" : first_order_reason(a, k);
  return mode;
}

// The scene line that carries each deformation: a rigid body's line to node i carries the
// resultants of node i's relative coordinates.
class DeformationLines {
 public:
  explicit DeformationLines(const framework::FrameworkModel& model) : model_(model), first_line_(model.elements.size(), -1) {
    int index = 0;
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      const auto& element = model.elements[e];
      if (element.nodes.empty()) continue;
      if (element.type == framework::ElementType::rigid_body) {
        if (element.nodes.size() > 1) first_line_[e] = index;
        index += static_cast<int>(element.nodes.size()) - 1;
      } else if (element.nodes.size() >= 2) {
        first_line_[e] = index++;
      }
    }
  }
  /// Scene line of deformation `d` of element `e` (rigid bodies: d counts the slots of the
  /// nodes after the reference node); -1 for none.
  int line_of(std::size_t e, std::size_t d) const {
    const auto& element = model_.elements[e];
    if (first_line_[e] < 0) return -1;
    if (element.type != framework::ElementType::rigid_body) return first_line_[e];
    for (std::size_t i = 1; i < element.nodes.size(); ++i) {
      const std::size_t slots = framework::node_slots(model_.dimension, model_.nodes[element.nodes[i]]).size();
      if (d < slots) return first_line_[e] + static_cast<int>(i) - 1;
      d -= slots;
    }
    return -1;
  }

 private:
  const framework::FrameworkModel& model_;
  std::vector<int> first_line_;
};

// Stress state k: per scene line, the dominant resultant of its element (largest magnitude, in
// the analysis' non-dimensional units) and its kind; and every non-zero resultant by name.
SceneStress framework_scene_stress(const framework::FrameworkModel& model, const framework::FrameworkResult& a, std::size_t k,
                                   const DeformationLines& lines, std::size_t line_count) {
  SceneStress stress;
  stress.label = "self-stress " + std::to_string(k + 1);
  stress.value.assign(line_count, 0.0);
  stress.kind.assign(line_count, "");
  const auto& s = a.stresses[k].resultants;
  for (Eigen::Index row = 0; row < s.size(); ++row) {
    if (s(row) == 0.0) continue;
    const auto& ref = a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(row)])];
    const auto& element = model.elements[ref.element];
    const std::string name = framework::deformation_names(model, element)[ref.deformation];
    stress.resultants.push_back({element.name, name, s(row)});
    const int line = lines.line_of(ref.element, ref.deformation);
    if (line < 0) continue;
    auto& value = stress.value[static_cast<std::size_t>(line)];
    if (std::abs(s(row)) > std::abs(value)) {
      value = s(row);
      stress.kind[static_cast<std::size_t>(line)] = deformation_kind(element.type, name);
    }
  }
  return stress;
}

}  // namespace

Scene framework_scene(const framework::FrameworkModel& model, const framework::FrameworkResult& a,
                      const std::vector<std::optional<framework::TwoWayTrace>>& traces) {
  Scene scene;
  scene.kind = io::ModelKind::framework;
  scene.name = model.name;
  scene.dimension = model.dimension;
  scene.screw_dimension = model.dimension == 2 ? 3 : 6;
  scene.summary = {
      {"kind", "framework / flexure mechanism (seed 002)"},
      {"dimension", std::to_string(model.dimension)},
      {"nodes", std::to_string(model.nodes.size())},
      {"elements", std::to_string(model.elements.size())},
      {"D(c)", fmt::format("{} x {}", a.m, a.n)},
      {"rank D(c)", rank_evidence(a.decision)},
      {"kinematically indeterminate modes", std::to_string(a.mechanisms)},
      {"statically indeterminate stress states", std::to_string(a.self_stresses)},
      {"class", framework_classification(a)},
  };
  for (const auto& node : model.nodes) scene.nodes.push_back(framework_scene_node(model, node));
  scene.elements = framework_scene_elements(model);
  // Signs are the analysis' own (linalg/sign_convention.hpp): the scene never flips a mode or
  // a stress state.
  for (std::size_t k = 0; k < a.modes.size(); ++k) scene.modes.push_back(framework_scene_mode(model, a, k, traces));
  const DeformationLines lines(model);
  for (std::size_t k = 0; k < a.stresses.size(); ++k)
    scene.stresses.push_back(framework_scene_stress(model, a, k, lines, scene.elements.size()));
  scene.large = scene.elements.size() > kLargeSceneElements || scene.nodes.size() > kLargeSceneElements;
  return scene;
}

Scene structure_scene(const structure::StructureModel& model, const structure::StructureResult& decomposition) {
  Scene scene;
  scene.kind = io::ModelKind::structure;
  scene.name = model.name;
  scene.dimension = 2;
  scene.screw_dimension = model.dimension;
  scene.summary = {
      {"kind", "structural groups (seed 004)"},
      {"bodies", std::to_string(model.body_count())},
      {"pairs", std::to_string(model.pairs.size())},
      {"mobility (Grübler-Kutzbach)", std::to_string(model.mobility())},
      {"inputs", std::to_string(model.input_count())},
      {"structural groups", std::to_string(decomposition.groups.size())},
      {"complete decomposition", decomposition.complete() ? "yes" : "no"},
  };
  for (const auto& group : decomposition.groups) {
    std::string bodies;
    for (int b : group.bodies) bodies += (bodies.empty() ? "" : ", ") + structure::body_label(model, b);
    scene.summary.push_back({group_name(group.number), fmt::format("{} (N_m = {}, n_c = {}, stage {})", bodies, group.Nm, group.nc, group.stage)});
  }
  // No geometry in a structure model: bodies on a circle, the frame at the bottom.
  const int n = model.body_count();
  for (int b = 0; b < n; ++b) {
    scene.bodies.push_back(structure::body_label(model, b));
    const double angle = -std::numbers::pi / 2 + 2 * std::numbers::pi * b / std::max(n, 1);
    scene.nodes.push_back({structure::body_label(model, b), Vector3d(std::cos(angle), std::sin(angle), 0), b, b == 0, {}, {}});
  }
  for (std::size_t p = 0; p < model.pairs.size(); ++p) {
    const auto& pair = model.pairs[p];
    scene.elements.push_back({"pair " + std::to_string(p + 1), "pair", pair.a, pair.b, true, std::nullopt});
    GraphEdge edge;
    edge.name = "p" + std::to_string(p + 1);
    edge.from = pair.a;
    edge.to = pair.b;
    edge.f = pair.freedoms;
    edge.c = model.dimension - pair.freedoms;
    scene.edges.push_back(edge);
  }
  scene.group_of = decomposition.group_of;
  scene.large = scene.elements.size() > kLargeSceneElements;
  return scene;
}

}  // namespace kinestat::report
