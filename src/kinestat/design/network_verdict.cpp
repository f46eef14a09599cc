// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/network_verdict.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "kinestat/design/screw_text.hpp"
#include "kinestat/graph/coupling_graph.hpp"
#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/mobility_count.hpp"
#include "kinestat/screw/coupling_basis.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

namespace {

using network::Coupling;
using network::Model;
using screw::CouplingType;
using screw::Rational;
using screw::Vec3;
using Screw = Eigen::Matrix<double, 6, 1>;

Eigen::Vector3d to_double(const Vec3& v) { return {v[0].get_d(), v[1].get_d(), v[2].get_d()}; }

// Centroid and RMS radius of the coupling points: screws are compared about the centroid in
// units of the radius, so participation does not change with placement or length unit.
struct Frame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double length = 1.0;
};

Frame frame_of(const Model& model) {
  Frame f;
  if (model.couplings.empty()) return f;
  for (const auto& c : model.couplings) f.centre += to_double(c.geometry.point);
  f.centre /= static_cast<double>(model.couplings.size());
  double sum = 0.0;
  for (const auto& c : model.couplings) sum += (to_double(c.geometry.point) - f.centre).squaredNorm();
  const double rms = std::sqrt(sum / static_cast<double>(model.couplings.size()));
  if (rms > 0.0) f.length = rms;
  return f;
}

double wrench_size(const Screw& w, const Frame& frame) {
  const Eigen::Vector3d f = w.tail<3>();
  const Eigen::Vector3d m = w.head<3>() - frame.centre.cross(f);
  return f.squaredNorm() + (m / frame.length).squaredNorm();
}

double twist_size(const Screw& t, const Frame& frame) {
  const Eigen::Vector3d w = t.head<3>();
  const Eigen::Vector3d v = t.tail<3>() + w.cross(frame.centre);  // velocity of the point at the centre
  return (w * frame.length).squaredNorm() + v.squaredNorm();
}

// Shares of one state from per-coupling sizes.
void add_shares(VerdictState& state, const std::vector<double>& size, const std::vector<std::string>& names,
                const std::vector<std::string>& details) {
  double total = 0.0;
  for (double s : size) total += s;
  if (total <= 0.0) return;
  for (std::size_t e = 0; e < size.size(); ++e)
    if (size[e] / total > kShareZero) state.participants.push_back({"coupling", names[e], size[e] / total, details[e]});
  rank_participants(state.participants);
}

// ---- counting a (changed) network -------------------------------------------------------

struct Standing {
  int FN = 0, CN = 0, idle = 0;
  bool keeps = true;  ///< the carriers of the intended motion can still make all of it (screen only)
};

// Extra motions, motions lost and redundant constraints against `intended` motions.
struct Tally {
  int extra = 0, lost = 0, CN = 0;
  int score() const { return extra + CN; }
};

Tally tally(const Standing& s, int intended) {
  // Idle motions are independent motions of the network, so at most FN of them; more is the
  // rounding of a degenerate geometry.
  const int idle = std::min(s.idle, s.FN);
  const int moving = s.FN - idle;  // motions that are not idle spins
  return {idle + std::max(0, moving - intended), std::max(0, intended - moving), s.CN};
}

int idle_count(const std::vector<IdleMotion>& idle) {
  int n = 0;
  for (const auto& i : idle) n += i.count;
  return n;
}

// ---- screening changed copies -----------------------------------------------------------

// The bases of every coupling the search meets, built once each: in the analysis frame when
// floating point (so numerical ranks are placement- and unit-free), keyed by type and geometry.
class BasisCache {
 public:
  BasisCache(const Model& model, bool exact)
      : space_(model.space), frame_(exact ? network::AnalysisFrame{} : network::AnalysisFrame::of(model)),
        input_rounding_(exact ? 0.0 : frame_.input_rounding(model)) {}

  /// Rounding level of the original model's coordinates in the cache's frame (0 when exact):
  /// raises the default rank threshold of the screen as in the full analysis.
  double input_rounding() const { return input_rounding_; }

  const screw::CouplingBasis& of(const Coupling& c) {
    std::string key = key_of(c);
    auto it = bases_.find(key);
    if (it == bases_.end())
      it = bases_.emplace(std::move(key), screw::coupling_basis(c.type, frame_.to_frame(c.geometry, space_), space_)).first;
    return it->second;  // std::map: stays valid while others are added
  }

  /// The basis of `c` in the user's frame (for the motion spaces, which condition it themselves).
  const screw::CouplingBasis& user_of(const Coupling& c) {
    std::string key = key_of(c);
    auto it = user_bases_.find(key);
    if (it == user_bases_.end()) it = user_bases_.emplace(std::move(key), screw::coupling_basis(c.type, c.geometry, space_)).first;
    return it->second;
  }

 private:
  static std::string key_of(const Coupling& c) {
    const auto& g = c.geometry;
    std::string key = std::string(screw::coupling_type_name(c.type));
    auto add = [&](const auto& values) {
      key += '|';
      for (const auto& x : values) key += linalg::to_string(x) + ',';
    };
    add(g.point);
    for (const auto* v : {&g.axis, &g.axis2, &g.normal})
      if (*v) add(**v);
      else key += "|-";
    key += '|' + linalg::to_string(g.pitch);
    for (const auto& m : g.custom_motions) add(m);
    key += "|actions";
    for (const auto& a : g.custom_actions) add(a);
    return key;
  }

  screw::ScrewSpace space_;
  network::AnalysisFrame frame_;
  double input_rounding_ = 0.0;
  std::map<std::string, screw::CouplingBasis> bases_;
  std::map<std::string, screw::CouplingBasis> user_bases_;
};

// True when a body that hangs on coupling `e` alone is not free on its own: the coupling is a
// declared input (its motion is driven), or the network has no circuit (an open chain or tree,
// such as a serial arm, whose every joint motion is taken as intended).
bool held_leaf(const Model& model, int e) {
  if (model.couplings.size() + 1 <= model.bodies.size()) return true;  // l = e - n + 1 = 0
  return std::find(model.inputs.begin(), model.inputs.end(), model.couplings[static_cast<std::size_t>(e)].name) != model.inputs.end();
}

// A unit motion (axis formation, d coordinates of `space`, user frame) about the centre of
// `frame` in units of its length: (ω; (v + ω × c) / L), so that spaces of motions are compared
// free of placement and length unit.
Eigen::VectorXd conditioned_motion(const Screw& t, const screw::ScrewSpace& space, const Frame& frame) {
  Screw u = t;
  const Eigen::Vector3d w = t.head<3>();
  u.tail<3>() = (Eigen::Vector3d(t.tail<3>()) + w.cross(frame.centre)) / frame.length;
  Eigen::VectorXd out(space.dimension());
  for (int k = 0; k < space.dimension(); ++k) out(k) = u(space.components[static_cast<std::size_t>(k)]);
  return out;
}

// An orthonormal basis of the columns of `a` (d rows), columns whose singular value is at most
// `threshold` dropped.
Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& a, double threshold) {
  if (a.cols() == 0) return Eigen::MatrixXd(a.rows(), 0);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU);
  Eigen::Index rank = 0;
  while (rank < svd.singularValues().size() && svd.singularValues()(rank) > threshold) ++rank;
  return svd.matrixU().leftCols(rank);
}

// The motion of every body relative to the ground in a (changed) network with FN motions, as
// orthonormal bases (d rows, conditioned about `frame`): FN columns of the null space of M^N
// (its smallest right singular vectors) mapped along a breadth-first tree from the ground. The
// screen's view of what the bodies carrying the intended motion can do; the proposed set is
// verified on the full analysis's body motions.
std::vector<Eigen::MatrixXd> motion_spaces(const Model& model, BasisCache& cache, const Frame& frame, int FN) {
  const int d = model.space.dimension();
  const int n = static_cast<int>(model.bodies.size());
  const int ground = model.ground.value_or(0);
  std::vector<graph::Edge> edges;
  std::vector<Eigen::MatrixXd> unit;  // d x f_e per coupling, conditioned
  std::vector<Eigen::Index> first{0};
  for (const auto& c : model.couplings) {
    edges.push_back({c.from, c.to});
    const auto& basis = cache.user_of(c);
    Eigen::MatrixXd u(d, static_cast<Eigen::Index>(basis.motions.size()));
    for (std::size_t j = 0; j < basis.motions.size(); ++j) {
      std::vector<double> coordinates;
      for (const auto& x : basis.motions[j].coordinates) coordinates.push_back(x.get_d());
      u.col(static_cast<Eigen::Index>(j)) = conditioned_motion(embed(coordinates, model.space), model.space, frame);
    }
    first.push_back(first.back() + u.cols());
    unit.push_back(std::move(u));
  }
  const Eigen::Index F = first.back();
  const graph::CouplingGraph graph(n, edges);
  const graph::SpanningTree tree = graph.breadth_first_tree(ground);
  const graph::TreeWalk walk = graph.walk(tree, ground);
  const Eigen::MatrixXi B = graph.circuit_matrix(tree);
  Eigen::MatrixXd mn = Eigen::MatrixXd::Zero(d * B.rows(), F);
  for (Eigen::Index i = 0; i < B.rows(); ++i)
    for (std::size_t e = 0; e < unit.size(); ++e)
      if (B(i, static_cast<Eigen::Index>(e)) != 0)
        mn.block(i * d, first[e], d, unit[e].cols()) = B(i, static_cast<Eigen::Index>(e)) * unit[e];
  const Eigen::Index kept = std::clamp<Eigen::Index>(FN, 0, F);
  Eigen::MatrixXd null = Eigen::MatrixXd::Identity(F, F).rightCols(kept);
  if (mn.rows() > 0 && kept > 0 && kept < F) null = linalg::analyse_svd(mn, {}, linalg::SvdVectors::right_only).v.rightCols(kept);
  std::vector<Eigen::MatrixXd> along(static_cast<std::size_t>(n), Eigen::MatrixXd::Zero(d, F));
  for (const int b : walk.order) {
    const int e = walk.parent_edge[static_cast<std::size_t>(b)];
    if (e < 0) continue;
    auto& t = along[static_cast<std::size_t>(b)];
    t = along[static_cast<std::size_t>(walk.parent_body[static_cast<std::size_t>(b)])];
    t.middleCols(first[static_cast<std::size_t>(e)], unit[static_cast<std::size_t>(e)].cols()) +=
        walk.sign[static_cast<std::size_t>(b)] * unit[static_cast<std::size_t>(e)];
  }
  // Ranked against the largest motion of any body (kPairRankRelative, as the pair systems).
  std::vector<Eigen::MatrixXd> motion(static_cast<std::size_t>(n));
  double largest = 0.0;
  for (int b = 0; b < n; ++b) {
    motion[static_cast<std::size_t>(b)] = along[static_cast<std::size_t>(b)] * null;
    largest = std::max(largest, motion[static_cast<std::size_t>(b)].norm());
  }
  std::vector<Eigen::MatrixXd> spaces;
  for (int b = 0; b < n; ++b) spaces.push_back(orthonormal_columns(motion[static_cast<std::size_t>(b)], kPairRankRelative * largest));
  return spaces;
}

// True when every motion of `kept` (orthonormal columns) lies in the span of `now` (orthonormal).
bool contains(const Eigen::MatrixXd& now, const Eigen::MatrixXd& kept) {
  if (kept.cols() == 0) return true;
  if (now.cols() < kept.cols()) return false;
  const Eigen::MatrixXd residual = kept - now * (now.transpose() * kept);
  return residual.colwise().norm().maxCoeff() <= kMotionSpaceResidual;
}

// What the screen needs to know of the bodies carrying the intended motion.
struct Carriers {
  std::vector<int> bodies;              ///< carriers of the intended motion (see carrier_bodies)
  std::vector<Eigen::MatrixXd> spaces;  ///< their motion spaces in the original design (screen frame)
  Frame frame;                          ///< the original model's frame (kept for every copy)
  bool same_space = false;              ///< the intended motion is all the design's motion: keep it exactly
};

// FN, CN and idle spins of a changed copy from cached bases: one rank of M^N and one small rank
// per body, instead of a full analysis. The search compares hundreds of copies this way; the
// change set it settles on is verified by a full analysis (network_verdict). A body held by one
// coupling is free on its own with that coupling's freedoms (unless the coupling is a declared
// input). With `carriers`, also whether each carrier can still make every motion it made in the
// original design (`keeps`).
Standing screen(const Model& model, BasisCache& cache, bool exact, const Tolerances& tolerances, double& work,
                const Carriers* carriers = nullptr) {
  const int d = model.space.dimension();
  std::vector<graph::Edge> edges;
  std::vector<const screw::CouplingBasis*> bases;
  for (const auto& c : model.couplings) {
    edges.push_back({c.from, c.to});
    bases.push_back(&cache.of(c));
  }
  const auto count = network::count_mobility(static_cast<int>(model.bodies.size()), edges, bases, d, exact, tolerances,
                                             cache.input_rounding());
  const double equations = d * count.l, unknowns = count.F;
  work += equations * unknowns * std::min(equations, unknowns);
  Standing s{count.FN, count.CN, 0, true};
  // Idle spins: the motions common to every coupling of a body, d less the rank of their actions.
  const int ground = model.ground.value_or(0);
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    std::vector<const std::vector<Rational>*> actions;
    int couplings = 0, last = -1;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (b == ground || (edges[e].from != b && edges[e].to != b)) continue;
      ++couplings;
      last = static_cast<int>(e);
      for (const auto& a : bases[e]->actions) actions.push_back(&a.coordinates);
    }
    if (couplings == 0 || (couplings == 1 && held_leaf(model, last))) continue;
    const auto rows = static_cast<Eigen::Index>(actions.size());
    if (rows == 0) {
      s.idle += d;
      continue;
    }
    Eigen::MatrixXd a(rows, exact ? 0 : d);
    for (Eigen::Index r = 0; !exact && r < rows; ++r)
      for (int k = 0; k < d; ++k) a(r, k) = (*actions[static_cast<std::size_t>(r)])[static_cast<std::size_t>(k)].get_d();
    if (!exact && a.allFinite()) {
      s.idle += d - static_cast<int>(linalg::numerical_rank(a, {tolerances.rank, cache.input_rounding()}).rank);
    } else {
      // Exact arithmetic, or actions beyond the range of doubles (a candidate's integral
      // directions from a 120-digit coordinate reached 1e309; fuzz_model_file): decided exactly.
      linalg::RationalMatrix exact_actions(rows, d);
      for (Eigen::Index r = 0; r < rows; ++r)
        for (int k = 0; k < d; ++k) exact_actions(r, k) = (*actions[static_cast<std::size_t>(r)])[static_cast<std::size_t>(k)];
      s.idle += d - static_cast<int>(linalg::exact_rank(exact_actions));
    }
  }
  if (carriers && carriers->same_space && !carriers->bodies.empty()) {
    const auto spaces = motion_spaces(model, cache, carriers->frame, count.FN);
    for (std::size_t i = 0; i < carriers->bodies.size() && s.keeps; ++i)
      s.keeps = contains(spaces[static_cast<std::size_t>(carriers->bodies[i])], carriers->spaces[i]);
  }
  return s;
}

// ---- candidate changes ------------------------------------------------------------------

// The same direction with coprime integer components, first non-zero component positive:
// short literals, so a changed model written back to a file is read exactly.
Vec3 integral(const Vec3& a) {
  mpz_class denominators = 1;
  for (const auto& x : a) mpz_lcm(denominators.get_mpz_t(), denominators.get_mpz_t(), x.get_den().get_mpz_t());
  const Vec3 v = screw::scaled(a, Rational(denominators));
  mpz_class divisor = 0;
  for (const auto& x : v) mpz_gcd(divisor.get_mpz_t(), divisor.get_mpz_t(), x.get_num().get_mpz_t());
  if (divisor == 0) return a;
  for (const auto& x : v)
    if (sgn(x) != 0) {
      if (sgn(x) < 0) divisor = -divisor;
      break;
    }
  return screw::scaled(v, Rational(1) / Rational(divisor));
}

void add_direction(std::vector<Vec3>& list, const Vec3& d) {
  if (screw::is_zero(d)) return;
  for (const auto& e : list)
    if (screw::is_zero(screw::cross(e, d))) return;
  list.push_back(integral(d));
}

// Frame axes and the lines from this coupling to the other couplings of its two bodies (the
// axis of an S-S link's idle spin, the line of a two-force member).
std::vector<Vec3> directions_near(const Model& model, const Coupling& c, bool planar) {
  std::vector<Vec3> list;
  add_direction(list, {1, 0, 0});
  add_direction(list, {0, 1, 0});
  if (!planar) add_direction(list, {0, 0, 1});
  for (const auto& other : model.couplings) {
    if (&other == &c) continue;
    if (other.from != c.from && other.from != c.to && other.to != c.from && other.to != c.to) continue;
    const Vec3 d = screw::minus(other.geometry.point, c.geometry.point);
    add_direction(list, d);
    if (planar) add_direction(list, {-d[1], d[0], 0});
  }
  return list;
}

Coupling with(const Coupling& c, CouplingType type, std::optional<Vec3> axis = {}, std::optional<Vec3> axis2 = {},
              std::optional<Vec3> normal = {}) {
  Coupling n = c;
  n.type = type;
  n.geometry = screw::CouplingGeometry{};
  n.geometry.point = c.geometry.point;
  n.geometry.axis = axis;
  n.geometry.axis2 = axis2;
  n.geometry.normal = normal;
  return n;
}

// The planar replacements (d = 3): a pin in a slot along each nearby direction, a slider's
// slot, a pin-in-slot back to a revolute or prismatic.
void add_planar_candidates(const Coupling& c, const std::vector<Vec3>& directions, std::vector<std::optional<Coupling>>& list) {
  const Vec3 z{0, 0, 1};
  const auto& g = c.geometry;
  auto axis_or_z = [&] { return g.axis ? integral(*g.axis) : z; };
  switch (c.type) {
    case CouplingType::revolute:
      for (const auto& n : directions) list.push_back(with(c, CouplingType::point_on_line, {}, {}, n));
      break;
    case CouplingType::prismatic: {
      const Vec3 a = axis_or_z();
      list.push_back(with(c, CouplingType::point_on_line, {}, {}, integral({-a[1], a[0], 0})));
      break;
    }
    case CouplingType::point_on_line: {
      const Vec3 n = *g.normal;
      list.push_back(with(c, CouplingType::revolute, z));
      list.push_back(with(c, CouplingType::prismatic, integral({-n[1], n[0], 0})));
      break;
    }
    default: break;
  }
}

// The spatial replacements (d = 6): the freedoms a lower pair can gain along its locked actions,
// and the constraints that stop an idle spin.
void add_spatial_candidates(const Coupling& c, const std::vector<Vec3>& directions, std::vector<std::optional<Coupling>>& list) {
  const Vec3 z{0, 0, 1};
  const auto& g = c.geometry;
  auto axis_or_z = [&] { return g.axis ? integral(*g.axis) : z; };
  switch (c.type) {
    case CouplingType::revolute: {
      const Vec3 a = axis_or_z();
      list.push_back(with(c, CouplingType::cylindrical, a));
      for (const auto& n : screw::perpendicular_directions(a)) list.push_back(with(c, CouplingType::universal, a, integral(n)));
      list.push_back(with(c, CouplingType::spherical));
      list.push_back(with(c, CouplingType::point_on_plane, {}, {}, a));  // a thrust bearing
      break;
    }
    case CouplingType::prismatic: {
      const Vec3 a = integral(*g.axis);
      list.push_back(with(c, CouplingType::cylindrical, a));
      for (const auto& n : screw::perpendicular_directions(a)) list.push_back(with(c, CouplingType::point_on_plane, {}, {}, integral(n)));
      break;
    }
    case CouplingType::helical:
      list.push_back(with(c, CouplingType::cylindrical, integral(*g.axis)));
      break;
    case CouplingType::cylindrical: {
      const Vec3 a = integral(*g.axis);
      for (const auto& n : screw::perpendicular_directions(a)) list.push_back(with(c, CouplingType::point_on_plane, {}, {}, integral(n)));
      list.push_back(with(c, CouplingType::revolute, a));
      list.push_back(with(c, CouplingType::prismatic, a));
      break;
    }
    case CouplingType::universal:
      list.push_back(with(c, CouplingType::spherical));
      list.push_back(with(c, CouplingType::point_on_plane, {}, {}, integral(screw::cross(*g.axis, *g.axis2))));
      list.push_back(with(c, CouplingType::revolute, integral(*g.axis)));
      list.push_back(with(c, CouplingType::revolute, integral(*g.axis2)));
      break;
    case CouplingType::spherical:
      for (const auto& n : directions) list.push_back(with(c, CouplingType::point_on_plane, {}, {}, n));
      for (const auto& d : directions) {
        const auto p = screw::perpendicular_directions(d);
        list.push_back(with(c, CouplingType::universal, integral(p[0]), integral(p[1])));
      }
      break;
    case CouplingType::planar:
      list.push_back(with(c, CouplingType::point_on_plane, {}, {}, integral(*g.normal)));
      break;
    case CouplingType::point_on_plane:
      list.push_back(with(c, CouplingType::spherical));
      list.push_back(with(c, CouplingType::planar, {}, {}, integral(*g.normal)));
      break;
    case CouplingType::free:
      list.push_back(with(c, CouplingType::spherical));
      for (const auto& n : directions) list.push_back(with(c, CouplingType::point_on_plane, {}, {}, n));
      break;
    default: break;
  }
}

// Replacements of one coupling that add freedoms (along a locked action) or constraints
// (against an idle spin), then a weld and its removal (nullopt).
std::vector<std::optional<Coupling>> candidates_for(const Model& model, const Coupling& c) {
  const bool planar = model.space.is_planar();
  std::vector<std::optional<Coupling>> list;
  const std::vector<Vec3> directions = directions_near(model, c, planar);
  if (planar) add_planar_candidates(c, directions, list);
  else add_spatial_candidates(c, directions, list);
  if (c.type != CouplingType::rigid) list.push_back(with(c, CouplingType::rigid));
  list.push_back(std::nullopt);
  return list;
}

// Changes by index of the original coupling: the replacement, or nullopt for removal.
using ChangeSet = std::map<int, std::optional<Coupling>>;

// The model with `changes` applied; chords, primaries and values are the user's choices for the
// original couplings and are dropped (they need not exist in the changed network).
Model changed_model(const Model& model, const ChangeSet& changes) {
  Model m = model;
  m.chords.clear();
  m.primary.clear();
  m.values.clear();
  m.couplings.clear();
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    const auto it = changes.find(static_cast<int>(i));
    if (it == changes.end()) m.couplings.push_back(model.couplings[i]);
    else if (it->second) m.couplings.push_back(*it->second);
  }
  return m;
}

int freedoms(const Coupling& c, const screw::ScrewSpace& space) {
  return static_cast<int>(screw::coupling_basis(c.type, c.geometry, space).motions.size());
}

std::vector<std::pair<std::string, std::vector<double>>> geometry_of(const Coupling& c) {
  std::vector<std::pair<std::string, std::vector<double>>> g;
  auto add = [&](const char* key, const Vec3& v) { g.push_back({key, {v[0].get_d(), v[1].get_d(), v[2].get_d()}}); };
  add("point", c.geometry.point);
  if (c.geometry.axis) add("axis", *c.geometry.axis);
  if (c.geometry.axis2) add("axis2", *c.geometry.axis2);
  if (c.geometry.normal) add("normal", *c.geometry.normal);
  return g;
}

struct Search {
  ChangeSet changes;
  Tally result;
  int lost_motion = 0;  ///< screened copies turned down because a carrier lost part of its motion
};

// Which changes a search may make. `replace_only`: only couplings of another type (a designer's
// first choice, e.g. the Clavel delta's spherical joints), freedoms added against redundancy and
// constraints against extra motion; `one_way`: also removals and welds, in the same direction;
// `two_way`: any change (a removal that frees a motion and a constraint that takes it back).
enum class SearchMode { lower_pairs, replace_only, one_way, two_way };

// A lower pair (surface contact: revolute, prismatic, helical, cylindrical, universal,
// spherical, planar) is a designer's first choice; a point contact or a removed or welded
// coupling changes the design more.
bool lower_pair(CouplingType type) {
  switch (type) {
    case CouplingType::revolute:
    case CouplingType::prismatic:
    case CouplingType::helical:
    case CouplingType::cylindrical:
    case CouplingType::universal:
    case CouplingType::spherical:
    case CouplingType::planar: return true;
    default: return false;
  }
}

// What every search of one verdict shares.
struct SearchContext {
  const Model& model;
  const network::AnalysisOptions& options;
  bool exact = false;
  int intended = 0;
  Tally start;
  std::vector<int> order;  ///< couplings, those taking the largest part first
  BasisCache& cache;
  const Carriers& carriers;
};

// One greedy search in one mode: the state the steps below share (the design so far, the
// re-analyses spent against the budget).
class GreedySearch {
 public:
  GreedySearch(const SearchContext& x, SearchMode mode, double& work) : x_(x), mode_(mode), work_(work) { s_.result = x.start; }

  Search run() {
    while (s_.result.score() > 0 && within_budget()) {
      Step step;
      try_single_changes(step);
      // No single change helps (e.g. a body between two spheres needs one constraint more at one
      // and one less at the other): try two at once among the couplings taking the largest part.
      if (!step.key) try_paired_changes(step);
      if (!step.key) break;
      s_.changes = step.changes;
      s_.result = step.tally;
    }
    if (s_.result.score() == 0 && s_.result.lost == 0) drop_unneeded_changes();
    return s_;
  }

 private:
  using Key = std::tuple<int, int, int, std::size_t, std::size_t>;  // score, lost, |delta f|, rank, candidate
  using Options = std::vector<std::pair<std::optional<Coupling>, int>>;  // candidates with |delta f|

  // The best change set of one step: the smallest key among the trials that lower the score.
  struct Step {
    std::optional<Key> key;
    ChangeSet changes;
    Tally tally;
  };

  bool within_budget() const { return analyses_ < kNetworkDesignSearchAnalyses && work_ < kNetworkDesignSearchWork; }

  // The tally of a changed copy, or nullopt when it cannot be analysed or a carrier of the
  // intended motion lost part of it (counted in lost_motion).
  std::optional<Tally> evaluate(const ChangeSet& changes) {
    ++analyses_;
    try {
      const Standing standing = screen(changed_model(x_.model, changes), x_.cache, x_.exact, x_.options.tolerances, work_, &x_.carriers);
      if (!standing.keeps) {
        ++s_.lost_motion;
        return std::nullopt;
      }
      return tally(standing, x_.intended);
    } catch (const graph::TreeError&) {
      return std::nullopt;  // a removal that disconnects a body
    } catch (const screw::GeometryError&) {
      return std::nullopt;
    }
  }

  // The candidates of the coupling at `rank` of the order in the current design, with |delta f|,
  // as the mode allows them.
  Options options_at(std::size_t rank) {
    Options out;
    const Model& model = x_.model;
    const int e = x_.order[rank];
    const auto current = s_.changes.find(e);
    if (current != s_.changes.end() && !current->second) return out;  // removed already
    const Coupling& now = current != s_.changes.end() ? *current->second : model.couplings[static_cast<std::size_t>(e)];
    const auto f = [&](const Coupling& c) { return static_cast<int>(x_.cache.of(c).motions.size()); };
    const bool one_way = mode_ != SearchMode::two_way;
    for (auto& candidate : candidates_for(changed_model(model, s_.changes), now)) {
      if (mode_ == SearchMode::replace_only && (!candidate || candidate->type == CouplingType::rigid)) continue;
      if (mode_ == SearchMode::lower_pairs && (!candidate || !lower_pair(candidate->type))) continue;
      try {
        // A removal drops the d - f constraints the coupling imposed.
        const int f_after = candidate ? f(*candidate) : model.space.dimension();
        if (one_way && x_.start.extra == 0 && f_after < f(now)) continue;  // only releases against redundancy
        if (one_way && x_.start.CN == 0 && f_after > f(now)) continue;     // only constraints against extra motion
        out.emplace_back(std::move(candidate), std::abs(f_after - f(now)));
      } catch (const screw::GeometryError&) {
      }
    }
    return out;
  }

  void consider(Step& step, const ChangeSet& trial, int delta, std::size_t rank, std::size_t k) {
    const auto t = evaluate(trial);
    if (!t || t->lost > s_.result.lost || t->score() >= s_.result.score()) return;
    const Key key{t->score(), t->lost, delta, rank, k};
    if (!step.key || key < *step.key) {
      step.key = key;
      step.changes = trial;
      step.tally = *t;
    }
  }

  void try_single_changes(Step& step) {
    for (std::size_t rank = 0; rank < x_.order.size(); ++rank) {
      const Options list = options_at(rank);
      for (std::size_t k = 0; k < list.size() && within_budget(); ++k) {
        ChangeSet trial = s_.changes;
        trial[x_.order[rank]] = list[k].first;
        consider(step, trial, list[k].second, rank, k);
      }
    }
  }

  void try_paired_changes(Step& step) {
    const std::size_t paired = std::min<std::size_t>(x_.order.size(), kNetworkDesignPairCouplings);
    for (std::size_t r1 = 0; !step.key && r1 < paired; ++r1) {
      const Options first = options_at(r1);
      for (std::size_t r2 = r1 + 1; r2 < paired; ++r2) {
        const Options second = options_at(r2);
        for (std::size_t k1 = 0; k1 < first.size(); ++k1)
          for (std::size_t k2 = 0; k2 < second.size() && within_budget(); ++k2) {
            ChangeSet trial = s_.changes;
            trial[x_.order[r1]] = first[k1].first;
            trial[x_.order[r2]] = second[k2].first;
            consider(step, trial, first[k1].second + second[k2].second, r1 * paired + r2, k1 * second.size() + k2);
          }
      }
    }
  }

  // Keep the set minimal: drop every change the others do not need.
  void drop_unneeded_changes() {
    for (bool dropped = true; dropped;) {
      dropped = false;
      for (const auto& entry : s_.changes) {
        ChangeSet without = s_.changes;
        without.erase(entry.first);
        const auto t = evaluate(without);
        if (t && t->score() == 0 && t->lost == 0) {
          s_.changes = std::move(without);
          dropped = true;
          break;
        }
      }
    }
  }

  const SearchContext& x_;
  SearchMode mode_;
  double& work_;  ///< shared by every search of the verdict
  int analyses_ = 0;
  Search s_;
};

Search search_changes(const SearchContext& x, SearchMode mode, double& work) { return GreedySearch(x, mode, work).run(); }

}  // namespace

std::string idle_description(const Model& model, const IdleMotion& idle, const std::string& motion) {
  const std::string& body = model.bodies[static_cast<std::size_t>(idle.body)];
  if (idle.holding_coupling >= 0)
    return fmt::format("body '{}' hangs on coupling {} alone and moves freely: {}", body,
                       model.couplings[static_cast<std::size_t>(idle.holding_coupling)].name, motion);
  return fmt::format("idle spin of body '{}': {}", body, motion);
}

std::vector<IdleMotion> idle_motions(const Model& model, bool exact, const Tolerances& tolerances) {
  const int d = model.space.dimension();
  const Frame frame = frame_of(model);
  // The rounding of the coordinates as written raises the default threshold (as in analyse_network).
  double largest_coordinate = 0.0;
  for (const auto& c : model.couplings)
    for (const auto& x : c.geometry.point) largest_coordinate = std::max(largest_coordinate, std::abs(x.get_d()));
  const double input_rounding = linalg::input_rounding_level(largest_coordinate, frame.length);
  std::vector<IdleMotion> list;
  const int ground = model.ground.value_or(0);
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    if (b == ground) continue;
    std::vector<std::vector<Rational>> actions;
    int couplings = 0, last = -1;
    for (std::size_t e = 0; e < model.couplings.size(); ++e) {
      const auto& c = model.couplings[e];
      if (c.from != b && c.to != b) continue;
      ++couplings;
      last = static_cast<int>(e);
      for (const auto& a : screw::coupling_basis(c.type, c.geometry, model.space).actions) actions.push_back(a.coordinates);
    }
    if (couplings == 0 || (couplings == 1 && held_leaf(model, last))) continue;
    IdleMotion idle{b, 0, {}, couplings == 1 ? last : -1};
    if (actions.empty()) {
      idle.count = d;
    } else if (exact) {
      linalg::RationalMatrix a(static_cast<Eigen::Index>(actions.size()), d);
      for (std::size_t r = 0; r < actions.size(); ++r)
        for (int k = 0; k < d; ++k) a(static_cast<Eigen::Index>(r), k) = actions[r][static_cast<std::size_t>(k)];
      const auto solution = linalg::solve_homogeneous(a);
      idle.count = static_cast<int>(solution.nullity());
      for (Eigen::Index j = 0; j < solution.nullity(); ++j) {
        std::vector<double> s(static_cast<std::size_t>(d));
        for (int k = 0; k < d; ++k) s[static_cast<std::size_t>(k)] = (*solution.exact_coefficients)(k, j).get_d();
        idle.screws.push_back(s);
      }
    } else {
      // About the centroid in units of the model's size, so the tolerance is scale-free:
      // an action (m; f) becomes ((m - c x f) / L; f), and a motion (w; v') of that system is
      // (w; L v' + c x w) in the user's frame (the same power against (m; f)).
      Eigen::MatrixXd a(static_cast<Eigen::Index>(actions.size()), d);
      for (std::size_t r = 0; r < actions.size(); ++r) {
        std::vector<double> coordinates;
        for (const auto& x : actions[r]) coordinates.push_back(x.get_d());
        Screw w = embed(coordinates, model.space);
        w.head<3>() = (w.head<3>() - frame.centre.cross(Eigen::Vector3d(w.tail<3>()))) / frame.length;
        for (int k = 0; k < d; ++k) a(static_cast<Eigen::Index>(r), k) = w(model.space.components[static_cast<std::size_t>(k)]);
      }
      const auto solution = linalg::solve_homogeneous(a, {tolerances.rank, input_rounding}, tolerances.free_variable);
      idle.count = static_cast<int>(solution.nullity());
      for (Eigen::Index j = 0; j < solution.nullity(); ++j) {
        Screw t = Screw::Zero();
        for (int k = 0; k < d; ++k) t(model.space.components[static_cast<std::size_t>(k)]) = solution.coefficients(k, j);
        const Eigen::Vector3d w = t.head<3>();
        t.tail<3>() = Eigen::Vector3d(t.tail<3>()) * frame.length + frame.centre.cross(w);
        std::vector<double> s;
        for (int c : model.space.components) s.push_back(t(c));
        idle.screws.push_back(s);
      }
    }
    if (idle.count > 0) list.push_back(std::move(idle));
  }
  return list;
}

namespace {

// The bodies that carry the intended motion: of the bodies that are not free on their own, those
// whose motion relative to the ground has the most freedoms (they make every intended motion),
// and of these the farthest from the ground along the couplings (the Delta's platform, not its
// rods; a four-bar's coupler). Their motion is what a change set must keep.
Carriers carriers_of(const Model& model, BasisCache& cache, const Frame& frame, int FN, const std::vector<IdleMotion>& idle,
                     const Tally& start) {
  Carriers c;
  c.frame = frame;
  c.same_space = start.lost == 0 && start.extra == std::min(idle_count(idle), FN);  // every motion that is not idle is intended
  if (FN == 0) return c;
  std::vector<Eigen::MatrixXd> spaces;
  try {
    spaces = motion_spaces(model, cache, frame, FN);
  } catch (const graph::TreeError&) {
    return c;
  }
  const int ground = model.ground.value_or(0);
  std::vector<graph::Edge> edges;
  for (const auto& coupling : model.couplings) edges.push_back({coupling.from, coupling.to});
  const graph::CouplingGraph graph(static_cast<int>(model.bodies.size()), edges);
  const graph::TreeWalk walk = graph.walk(graph.breadth_first_tree(ground), ground);
  std::vector<int> depth(model.bodies.size(), 0);
  for (const int b : walk.order)
    if (walk.parent_edge[static_cast<std::size_t>(b)] >= 0)
      depth[static_cast<std::size_t>(b)] = depth[static_cast<std::size_t>(walk.parent_body[static_cast<std::size_t>(b)])] + 1;
  Eigen::Index most = 0;
  int farthest = 0;
  const auto eligible = [&](int b) {
    return b != ground && std::none_of(idle.begin(), idle.end(), [&](const IdleMotion& i) { return i.body == b; });
  };
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b)
    if (eligible(b)) most = std::max(most, spaces[static_cast<std::size_t>(b)].cols());
  if (most == 0) return c;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b)
    if (eligible(b) && spaces[static_cast<std::size_t>(b)].cols() == most) farthest = std::max(farthest, depth[static_cast<std::size_t>(b)]);
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b)
    if (eligible(b) && spaces[static_cast<std::size_t>(b)].cols() == most && depth[static_cast<std::size_t>(b)] == farthest) {
      c.bodies.push_back(b);
      c.spaces.push_back(spaces[static_cast<std::size_t>(b)]);
    }
  return c;
}

std::string carrier_names(const Model& model, const Carriers& carriers) {
  std::vector<std::string> names;
  for (const int b : carriers.bodies) names.push_back("'" + model.bodies[static_cast<std::size_t>(b)] + "'");
  return names.empty() ? std::string("the moving bodies") : fmt::format("{}", fmt::join(names, ", "));
}

// "release T1a -> spherical, remove T3a": a change set in one line, in model order.
std::string change_set_text(const Model& model, const ChangeSet& set) {
  std::vector<std::string> parts;
  for (const auto& [e, replacement] : set) {
    const std::string& name = model.couplings[static_cast<std::size_t>(e)].name;
    parts.push_back(replacement ? fmt::format("{} -> {}", name, screw::coupling_type_name(replacement->type)) : "remove " + name);
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

std::vector<DesignChange> design_changes(const Model& model, const ChangeSet& set, const Tally& start) {
  // A set that removes some couplings and constrains others moves constraints, it does not
  // only drop them: say so instead of calling the removed coupling redundant.
  const bool constrains = std::any_of(set.begin(), set.end(), [&](const auto& entry) {
    return entry.second && freedoms(*entry.second, model.space) < freedoms(model.couplings[static_cast<std::size_t>(entry.first)], model.space);
  });
  std::vector<DesignChange> changes;
  for (const auto& [e, replacement] : set) {
    const Coupling& before = model.couplings[static_cast<std::size_t>(e)];
    const int f0 = freedoms(before, model.space);
    DesignChange change;
    change.target_kind = "coupling";
    change.target = before.name;
    change.from = std::string(screw::coupling_type_name(before.type));
    if (!replacement) {
      change.action = "remove";
      change.becomes = "removed";
      change.reason = constrains ? "its constraints move to the couplings this set constrains"
                                 : "the coupling is redundant: the others already impose what it does";
    } else {
      const int f1 = freedoms(*replacement, model.space);
      change.action = f1 > f0 ? "release" : (f1 < f0 ? "constrain" : "replace");
      change.becomes = std::string(screw::coupling_type_name(replacement->type));
      change.geometry = geometry_of(*replacement);
      change.reason = f1 > f0 ? fmt::format("{} along the locked action (f {} -> {})", counted(f1 - f0, "freedom", "freedoms"), f0, f1)
                              : fmt::format("{} against {} (f {} -> {})", counted(f0 - f1, "constraint", "constraints"),
                                            start.extra > 0 ? "the extra motion" : "the motion the other changes would free", f0, f1);
    }
    changes.push_back(std::move(change));
  }
  return changes;
}

// A body's motion relative to the ground from the full analysis, conditioned about `frame`
// (d rows, one column per primary motion).
Eigen::MatrixXd conditioned_body_motion(const network::LinearForms& forms, const screw::ScrewSpace& space, const Frame& frame) {
  Eigen::MatrixXd out(space.dimension(), forms.values.cols());
  for (Eigen::Index j = 0; j < forms.values.cols(); ++j) {
    std::vector<double> coordinates(forms.values.col(j).data(), forms.values.col(j).data() + forms.values.rows());
    out.col(j) = conditioned_motion(embed(coordinates, space), space, frame);
  }
  return out;
}

// Ranks of a carrier's motion before, after, and of both together: exact when both analyses
// were, otherwise numerical (kPairRankRelative of the largest, as the pair freedoms fij).
struct SpaceRanks {
  long before = 0, after = 0, both = 0;
};

SpaceRanks space_ranks(const network::LinearForms& before, const network::LinearForms& after, const screw::ScrewSpace& space,
                       const Frame& frame) {
  if (before.exact && after.exact) {
    const auto rows = before.exact->rows();
    linalg::RationalMatrix both(rows, before.exact->cols() + after.exact->cols());
    for (Eigen::Index i = 0; i < rows; ++i) {
      for (Eigen::Index j = 0; j < before.exact->cols(); ++j) both(i, j) = (*before.exact)(i, j);
      for (Eigen::Index j = 0; j < after.exact->cols(); ++j) both(i, before.exact->cols() + j) = (*after.exact)(i, j);
    }
    return {static_cast<long>(linalg::exact_rank(*before.exact)), static_cast<long>(linalg::exact_rank(*after.exact)),
            static_cast<long>(linalg::exact_rank(both))};
  }
  const Eigen::MatrixXd a = conditioned_body_motion(before, space, frame), b = conditioned_body_motion(after, space, frame);
  Eigen::MatrixXd both(a.rows(), a.cols() + b.cols());
  both << a, b;
  const auto rank = [](const Eigen::MatrixXd& m) -> long {
    if (m.cols() == 0 || !(m.norm() > 0.0)) return 0;
    return static_cast<long>(linalg::numerical_rank(m, {kPairRankRelative}).rank);
  };
  return {rank(a), rank(b), rank(both)};
}

// "3 translations" or "3 motions (2 with rotation)": what a motion space of a carrier is.
std::string space_words(const network::LinearForms& forms, long rank, const screw::ScrewSpace& space) {
  Eigen::MatrixXd rotation = Eigen::MatrixXd::Zero(3, forms.values.cols());
  for (Eigen::Index j = 0; j < forms.values.cols(); ++j) {
    std::vector<double> coordinates(forms.values.col(j).data(), forms.values.col(j).data() + forms.values.rows());
    rotation.col(j) = embed(coordinates, space).head<3>();
  }
  const double size = forms.values.norm();
  const long rotating = rotation.cols() == 0 || !(size > 0.0) ? 0
                        : static_cast<long>(linalg::numerical_rank(rotation / size, {kPairRankRelative}).rank);
  if (rotating == 0) return counted(rank, "translation", "translations");
  if (rotating == rank) return counted(rank, "rotation", "rotations");
  return fmt::format("{} ({} with rotation)", counted(rank, "motion", "motions"), rotating);
}

// The outcome of re-analysing a changed copy in full: what was compared, and why it failed.
struct Verification {
  bool passed = false;
  std::vector<std::string> compared;
  std::string failure;
  std::string becomes;
};

// A change set passes when the full re-analysis of the changed copy (the user's arithmetic) has
// CN = 0, no extra motion, no body free on its own, and each carrier of the intended motion keeps
// the same pair freedoms fij with the ground and the same motion screws (or, when the design has
// more motion than intended, keeps no motion it did not have).
Verification verify_changes(const Model& model, const network::NetworkResult& r, const ChangeSet& changes,
                            const network::AnalysisOptions& options, int intended, const Carriers& carriers) {
  Verification out;
  network::AnalysisOptions full = options;
  full.primary.reset();
  full.values.clear();
  const Model changed = changed_model(model, changes);
  network::NetworkResult after;
  try {
    after = network::analyse_network(changed, full);
  } catch (const std::exception& error) {
    out.failure = fmt::format("the changed model could not be analysed: {}", error.what());
    return out;
  }
  const auto idle = idle_motions(changed, after.exact, full.tolerances);
  const Tally t = tally({after.FN, after.CN, idle_count(idle)}, intended);
  out.becomes = fmt::format("FN = {}, CN = {}: {}{}", after.FN, after.CN,
                            t.score() == 0 && t.lost == 0
                                ? (intended == 0 ? std::string("exactly constrained, a structure")
                                                 : "exactly constrained with " + counted(intended, "intended motion", "intended motions"))
                                : constraint_words(t.extra, t.CN),
                            after.FN != r.FN ? fmt::format(" (FN was {})", r.FN) : "");
  std::vector<std::string> failures;
  out.compared.push_back(fmt::format("re-analysed: FN = {}, CN = {} (was FN = {}, CN = {}); {} intended, {}", after.FN, after.CN,
                                     r.FN, r.CN, counted(intended, "motion", "motions"),
                                     t.extra == 0 && t.lost == 0 ? "no extra motion" : constraint_words(t.extra, 0)));
  if (after.CN > 0) failures.push_back(counted(after.CN, "redundant constraint remains", "redundant constraints remain"));
  if (t.lost > 0) failures.push_back(fmt::format("{} lost", counted(t.lost, "intended motion", "intended motions")));
  if (idle.empty()) {
    out.compared.push_back("no body free on its own (idle spins and bodies held by one coupling looked for)");
  } else {
    const Frame frame = frame_of(changed);
    for (const auto& spin : idle)
      failures.push_back(idle_description(changed, spin, motion_text(embed(spin.screws.front(), changed.space), frame.length)));
  }
  const int ground = model.ground.value_or(0);
  for (const int b : carriers.bodies) {
    const std::string pair = fmt::format("{}–{}", model.bodies[static_cast<std::size_t>(ground)], model.bodies[static_cast<std::size_t>(b)]);
    const auto& was = r.body_motions[static_cast<std::size_t>(b)];
    const auto& now = after.body_motions[static_cast<std::size_t>(b)];
    const SpaceRanks k = space_ranks(was, now, model.space, carriers.frame);
    if (k.before != k.after && carriers.same_space) {
      failures.push_back(fmt::format("{}: fij {} -> {}", pair, k.before, k.after));
    } else if (carriers.same_space ? k.both != k.before : k.both != k.before || k.after != intended) {
      failures.push_back(fmt::format("{}: fij = {}, but other motion screws than before", pair, k.after));
    } else {
      out.compared.push_back(fmt::format("{}: fij = {} before and after, the same motion screws ({})", pair, k.after,
                                         space_words(now, k.after, model.space)));
      if (!carriers.same_space && k.after != k.before) out.compared.back() = fmt::format("{}: fij {} -> {}, motions kept from the design's ({})", pair, k.before, k.after, space_words(now, k.after, model.space));
    }
  }
  out.passed = failures.empty();
  if (!out.passed) out.failure = fmt::format("{}", fmt::join(failures, "; "));
  return out;
}

// One state per idle spin screw: the body, and every coupling at it with an equal share.
void add_idle_spin_states(const Model& model, const std::vector<IdleMotion>& idle, const Frame& frame,
                          const std::vector<std::string>& names, Verdict& v) {
  const auto e_count = model.couplings.size();
  for (const auto& spin : idle) {
    for (const auto& s : spin.screws) {
      const std::string what = motion_text(embed(s, model.space), frame.length);
      VerdictState state{"extra motion", idle_description(model, spin, what), {}};
      state.participants.push_back({"body", model.bodies[static_cast<std::size_t>(spin.body)], 1.0, what});
      std::vector<double> size(e_count, 0.0);
      std::vector<std::string> detail(e_count, "lets the body spin: " + what);
      for (std::size_t e = 0; e < e_count; ++e)
        if (model.couplings[e].from == spin.body || model.couplings[e].to == spin.body) size[e] = 1.0;
      add_shares(state, size, names, detail);
      v.states.push_back(std::move(state));
    }
  }
}

// The motions beyond the declared inputs as one state: each coupling's share of the motion
// magnitudes (over every primary), sized placement-free.
VerdictState beyond_inputs_state(const Model& model, const network::NetworkResult& r, const Frame& frame,
                                 const std::vector<std::string>& names, int beyond, int declared) {
  const auto e_count = model.couplings.size();
  VerdictState state{"extra motion", fmt::format("{} beyond the {} declared", counted(beyond, "motion", "motions"),
                                                 counted(declared, "input", "inputs")), {}};
  std::vector<double> size(e_count, 0.0);
  std::vector<std::string> detail(e_count, "moves");
  for (std::size_t i = 0; i < r.motions.size(); ++i) {
    std::vector<double> c;
    for (const auto& x : r.motions[i].unit_screw.coordinates) c.push_back(x.get_d());
    const Screw t = embed(c, model.space);
    size[static_cast<std::size_t>(r.motions[i].coupling)] += r.motion_magnitudes.values.row(static_cast<Eigen::Index>(i)).squaredNorm() * twist_size(t, frame);
  }
  add_shares(state, size, names, detail);
  return state;
}

// Self-stresses: one state per action primary (that primary = 1), the wrench each coupling
// transmits.
void add_self_stress_states(const Model& model, const network::NetworkResult& r, const Frame& frame,
                            const std::vector<std::string>& names, Verdict& v) {
  const auto e_count = model.couplings.size();
  for (int j = 0; j < r.CN; ++j) {
    std::vector<Screw> wrench(e_count, Screw::Zero());
    for (std::size_t i = 0; i < r.actions.size(); ++i) {
      std::vector<double> c;
      for (const auto& x : r.actions[i].unit_screw.coordinates) c.push_back(x.get_d());
      wrench[static_cast<std::size_t>(r.actions[i].coupling)] += r.action_magnitudes.values(static_cast<Eigen::Index>(i), j) * embed(c, model.space);
    }
    std::vector<double> size(e_count, 0.0);
    std::vector<std::string> detail(e_count);
    for (std::size_t e = 0; e < e_count; ++e) {
      size[e] = wrench_size(wrench[e], frame);
      detail[e] = action_text(wrench[e], frame.length);
    }
    const std::string primary = r.actions[static_cast<std::size_t>(r.primary_action[static_cast<std::size_t>(j)])].name;
    VerdictState state{"self-stress", fmt::format("self-stress {} (action primary {} = 1)", j + 1, primary), {}};
    add_shares(state, size, names, detail);
    v.states.push_back(std::move(state));
  }
}

// The couplings in the order the search tries them: by participation (constraints, then
// motions), the rest after them in model order.
std::vector<int> search_order(const Verdict& v, const std::vector<std::string>& names) {
  const std::size_t e_count = names.size();
  std::vector<int> order;
  for (const auto& list : {v.constraint_participants, v.motion_participants})
    for (const auto& p : list)
      for (std::size_t e = 0; e < e_count; ++e)
        if (p.kind == "coupling" && names[e] == p.name && std::find(order.begin(), order.end(), static_cast<int>(e)) == order.end())
          order.push_back(static_cast<int>(e));
  for (std::size_t e = 0; e < e_count; ++e)
    if (std::find(order.begin(), order.end(), static_cast<int>(e)) == order.end()) order.push_back(static_cast<int>(e));
  return order;
}

// A change set the re-analysis passed.
struct Proposal {
  ChangeSet changes;
  Verification check;
};

// What the searches found: the verified proposals (in the order found), the rejected sets in
// `v.rejected`, the copies turned down for taking intended motion, and the work spent.
struct SearchOutcome {
  std::vector<Proposal> verified;
  int lost_motion = 0;
  double work = 0.0;
};

// The greedy search in each mode (lower pairs first; the two-way search only when nothing was
// verified), every distinct set found verified by re-analysis.
SearchOutcome search_and_verify(const Model& model, const network::NetworkResult& r, const network::AnalysisOptions& options,
                                const SearchContext& context, const Carriers& carriers, Verdict& v) {
  SearchOutcome out;
  std::vector<std::string> seen;
  for (const SearchMode mode : {SearchMode::lower_pairs, SearchMode::replace_only, SearchMode::one_way, SearchMode::two_way}) {
    if (mode == SearchMode::two_way && !out.verified.empty()) break;
    if (out.work >= kNetworkDesignSearchWork) break;
    const Search found = search_changes(context, mode, out.work);
    out.lost_motion += found.lost_motion;
    if (found.changes.empty() || found.result.score() > 0 || found.result.lost > 0) continue;
    const std::string key = change_set_text(model, found.changes);
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    Verification check = verify_changes(model, r, found.changes, options, context.intended, carriers);
    if (check.passed) out.verified.push_back({found.changes, std::move(check)});
    else v.rejected.push_back(key + ": " + check.failure);
  }
  return out;
}

// Simplest first: sets of lower pairs only, then with point contacts, then with removals or
// welds; within each, the fewest changes, then the fewest freedoms changed.
void sort_simplest_first(const Model& model, std::vector<Proposal>& verified) {
  const auto simplicity = [&](const ChangeSet& set) {
    int kind = 0, delta = 0;
    for (const auto& [e, replacement] : set) {
      const int f0 = freedoms(model.couplings[static_cast<std::size_t>(e)], model.space);
      kind = std::max(kind, !replacement || replacement->type == CouplingType::rigid ? 2 : lower_pair(replacement->type) ? 0 : 1);
      delta += std::abs((replacement ? freedoms(*replacement, model.space) : model.space.dimension()) - f0);
    }
    return std::make_tuple(kind, set.size(), delta);
  };
  std::stable_sort(verified.begin(), verified.end(),
                   [&](const Proposal& p, const Proposal& q) { return simplicity(p.changes) < simplicity(q.changes); });
}

// Why no change set is proposed, when the search verified none.
std::string no_change_note(const Model& model, const SearchOutcome& outcome, const Carriers& carriers, const Verdict& v) {
  const std::string turned_down =
      outcome.lost_motion > 0 ? fmt::format("; {} screened {} took part of the intended motion from {}", outcome.lost_motion,
                                            outcome.lost_motion == 1 ? "copy was turned down: it" : "copies were turned down: they",
                                            carrier_names(model, carriers))
                              : "";
  if (!v.rejected.empty())
    return fmt::format("no change set passed the re-analysis ({} tried, none proposed){}", v.rejected.size(), turned_down);
  if (outcome.work >= kNetworkDesignSearchWork)
    return "no change set found within the search budget: analyse a smaller part of the network to get one" + turned_down;
  return "no change of coupling types, removal or weld removes every extra motion and redundant constraint" + turned_down;
}

}  // namespace

Verdict network_verdict(const Model& model, const network::NetworkResult& r, const network::AnalysisOptions& options) {
  // The counts: intended motions (the inputs, or FN less the idle spins), extra and redundant.
  Verdict v;
  const Frame frame = frame_of(model);
  const auto idle = idle_motions(model, r.exact, options.tolerances);
  const Standing standing{r.FN, r.CN, std::min(idle_count(idle), r.FN)};
  const int declared = static_cast<int>(model.inputs.size());
  const int intended = model.inputs.empty() ? standing.FN - standing.idle : declared;
  v.intended_motions = intended;
  v.intended_basis = model.inputs.empty() ? "none declared ('inputs:'): every motion but idle spins (FN less idle spins)" : "the declared 'inputs:'";
  const Tally start = tally(standing, intended);
  v.extra_motions = start.extra;
  v.redundant_constraints = r.CN + start.lost;  // inputs beyond the motions fight each other
  v.exactly_constrained = v.extra_motions == 0 && v.redundant_constraints == 0;
  v.summary = summary_sentence(v.extra_motions, v.redundant_constraints, intended);
  note_near_rank_change(v, r.circulation.solution.rank.distance(), r.FN > 0);

  // Where: idle spins, then motions beyond the declared inputs, then the self-stresses.
  std::vector<std::string> names;
  for (const auto& c : model.couplings) names.push_back(c.name);
  add_idle_spin_states(model, idle, frame, names, v);
  const int beyond = std::max(0, standing.FN - standing.idle - intended);
  if (beyond > 0 && r.FN > 0) v.states.push_back(beyond_inputs_state(model, r, frame, names, beyond, declared));
  add_self_stress_states(model, r, frame, names, v);
  v.motion_participants = strongest(v.states, "extra motion");
  v.constraint_participants = strongest(v.states, "self-stress");

  // What to change: nothing, a note, or the simplest verified change set.
  if (v.exactly_constrained) {
    v.changes_verified = true;
    v.becomes = "unchanged: already exactly constrained";
    return v;
  }
  if (start.lost > 0) {
    v.note = fmt::format("{} declared for {}: drop {} (or add the motions they drive)", counted(declared, "input is", "inputs are"),
                         counted(standing.FN - standing.idle, "motion", "motions"), counted(start.lost, "input", "inputs"));
    return v;
  }
  if (static_cast<int>(model.couplings.size()) > kNetworkDesignSearchCouplings) {
    v.note = fmt::format("no change set searched: more than {} couplings", kNetworkDesignSearchCouplings);
    return v;
  }
  const std::vector<int> order = search_order(v, names);
  BasisCache cache(model, r.exact);
  const Carriers carriers = carriers_of(model, cache, frame, r.FN, idle, start);
  const SearchContext context{model, options, r.exact, intended, start, order, cache, carriers};
  SearchOutcome outcome = search_and_verify(model, r, options, context, carriers, v);
  sort_simplest_first(model, outcome.verified);
  if (outcome.verified.empty()) {
    v.note = no_change_note(model, outcome, carriers, v);
    return v;
  }
  const Proposal& best = outcome.verified.front();
  v.changes = design_changes(model, best.changes, start);
  v.changes_verified = true;
  v.becomes = best.check.becomes;
  v.verification = best.check.compared;
  for (std::size_t i = 1; i < outcome.verified.size(); ++i) v.alternatives.push_back(design_changes(model, outcome.verified[i].changes, start));
  return v;
}

}  // namespace kinestat::design
