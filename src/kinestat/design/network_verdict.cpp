#include "kinestat/design/network_verdict.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
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
};

// Extra motions, motions lost and redundant constraints against `intended` motions.
struct Tally {
  int extra = 0, lost = 0, CN = 0;
  int score() const { return extra + CN; }
};

Tally tally(const Standing& s, int intended) {
  const int moving = s.FN - s.idle;  // motions that are not idle spins
  return {s.idle + std::max(0, moving - intended), std::max(0, intended - moving), s.CN};
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
};

// FN, CN and idle spins of a changed copy from cached bases: one rank of M^N and one small rank
// per body, instead of a full analysis. The search compares hundreds of copies this way; the
// change set it settles on is verified by a full analysis (network_verdict).
Standing screen(const Model& model, BasisCache& cache, bool exact, const Tolerances& tolerances,
                double& work) {
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
  Standing s{count.FN, count.CN, 0};
  // Idle spins: the motions common to every coupling of a body, d less the rank of their actions.
  const int ground = model.ground.value_or(0);
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    std::vector<const std::vector<Rational>*> actions;
    int couplings = 0;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (b == ground || (edges[e].from != b && edges[e].to != b)) continue;
      ++couplings;
      for (const auto& a : bases[e]->actions) actions.push_back(&a.coordinates);
    }
    if (couplings < 2) continue;
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

// Replacements of one coupling that add freedoms (along a locked action) or constraints
// (against an idle spin), and its removal (nullopt).
std::vector<std::optional<Coupling>> candidates_for(const Model& model, const Coupling& c) {
  const bool planar = model.space.is_planar();
  const Vec3 z{0, 0, 1};
  std::vector<std::optional<Coupling>> list;
  const auto& g = c.geometry;
  const std::vector<Vec3> directions = directions_near(model, c, planar);
  auto axis_or_z = [&] { return g.axis ? integral(*g.axis) : z; };
  if (planar) {
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
    if (c.type != CouplingType::rigid) list.push_back(with(c, CouplingType::rigid));
    list.push_back(std::nullopt);
    return list;
  }
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
};

// With `one_way`, a design with only redundant constraints is offered only releases and removals,
// and one with only extra motions only added constraints: a designer's change, not a removal
// that frees a motion and a constraint that takes it back.
Search search_changes(const Model& model, const network::AnalysisOptions& options, bool exact, int intended,
                      const Tally& start, const std::vector<int>& order, bool one_way, double& work) {
  Search s;
  s.result = start;
  BasisCache cache(model, exact);
  int analyses = 0;
  const auto within_budget = [&] { return analyses < kNetworkDesignSearchAnalyses && work < kNetworkDesignSearchWork; };
  auto evaluate = [&](const ChangeSet& changes) -> std::optional<Tally> {
    ++analyses;
    try {
      return tally(screen(changed_model(model, changes), cache, exact, options.tolerances, work), intended);
    } catch (const graph::TreeError&) {
      return std::nullopt;  // a removal that disconnects a body
    } catch (const screw::GeometryError&) {
      return std::nullopt;
    }
  };
  using Key = std::tuple<int, int, int, std::size_t, std::size_t>;  // score, lost, |delta f|, rank, candidate
  // The candidates of the coupling at `rank` of `order` in the current design, with |delta f|.
  auto options_at = [&](std::size_t rank) {
    std::vector<std::pair<std::optional<Coupling>, int>> out;
    const int e = order[rank];
    const auto current = s.changes.find(e);
    if (current != s.changes.end() && !current->second) return out;  // removed already
    const Coupling& now = current != s.changes.end() ? *current->second : model.couplings[static_cast<std::size_t>(e)];
    const auto f = [&](const Coupling& c) { return static_cast<int>(cache.of(c).motions.size()); };
    for (auto& candidate : candidates_for(changed_model(model, s.changes), now)) {
      try {
        // A removal drops the d - f constraints the coupling imposed.
        const int f_after = candidate ? f(*candidate) : model.space.dimension();
        if (one_way && start.extra == 0 && f_after < f(now)) continue;  // only releases against redundancy
        if (one_way && start.CN == 0 && f_after > f(now)) continue;     // only constraints against extra motion
        out.emplace_back(std::move(candidate), std::abs(f_after - f(now)));
      } catch (const screw::GeometryError&) {
      }
    }
    return out;
  };
  while (s.result.score() > 0 && within_budget()) {
    std::optional<Key> best_key;
    ChangeSet best;
    Tally best_tally;
    auto consider = [&](const ChangeSet& trial, int delta, std::size_t rank, std::size_t k) {
      const auto t = evaluate(trial);
      if (!t || t->lost > s.result.lost || t->score() >= s.result.score()) return;
      const Key key{t->score(), t->lost, delta, rank, k};
      if (!best_key || key < *best_key) {
        best_key = key;
        best = trial;
        best_tally = *t;
      }
    };
    for (std::size_t rank = 0; rank < order.size(); ++rank) {
      const auto list = options_at(rank);
      for (std::size_t k = 0; k < list.size() && within_budget(); ++k) {
        ChangeSet trial = s.changes;
        trial[order[rank]] = list[k].first;
        consider(trial, list[k].second, rank, k);
      }
    }
    // No single change helps (e.g. a body between two spheres needs one constraint more at one
    // and one less at the other): try two at once among the couplings taking the largest part.
    const std::size_t paired = std::min<std::size_t>(order.size(), kNetworkDesignPairCouplings);
    for (std::size_t r1 = 0; !best_key && r1 < paired; ++r1) {
      const auto first = options_at(r1);
      for (std::size_t r2 = r1 + 1; r2 < paired; ++r2) {
        const auto second = options_at(r2);
        for (std::size_t k1 = 0; k1 < first.size(); ++k1)
          for (std::size_t k2 = 0; k2 < second.size() && within_budget(); ++k2) {
            ChangeSet trial = s.changes;
            trial[order[r1]] = first[k1].first;
            trial[order[r2]] = second[k2].first;
            consider(trial, first[k1].second + second[k2].second, r1 * paired + r2, k1 * second.size() + k2);
          }
      }
    }
    if (!best_key) break;
    s.changes = best;
    s.result = best_tally;
  }
  // Keep the set minimal: drop every change the others do not need.
  if (s.result.score() == 0 && s.result.lost == 0) {
    for (bool dropped = true; dropped;) {
      dropped = false;
      for (const auto& entry : s.changes) {
        ChangeSet without = s.changes;
        without.erase(entry.first);
        const auto t = evaluate(without);
        if (t && t->score() == 0 && t->lost == 0) {
          s.changes = std::move(without);
          dropped = true;
          break;
        }
      }
    }
  }
  return s;
}

}  // namespace

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
    int couplings = 0;
    for (const auto& c : model.couplings) {
      if (c.from != b && c.to != b) continue;
      ++couplings;
      for (const auto& a : screw::coupling_basis(c.type, c.geometry, model.space).actions) actions.push_back(a.coordinates);
    }
    if (couplings < 2) continue;
    IdleMotion idle{b, 0, {}};
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

Verdict network_verdict(const Model& model, const network::NetworkResult& r, const network::AnalysisOptions& options) {
  Verdict v;
  const Frame frame = frame_of(model);
  const auto idle = idle_motions(model, r.exact, options.tolerances);
  const Standing standing{r.FN, r.CN, idle_count(idle)};
  const int declared = static_cast<int>(model.inputs.size());
  const int intended = model.inputs.empty() ? standing.FN - standing.idle : declared;
  v.intended_motions = intended;
  v.intended_basis = model.inputs.empty() ? "FN less idle spins (no 'inputs:' declared)" : "the declared 'inputs:'";
  const Tally start = tally(standing, intended);
  v.extra_motions = start.extra;
  v.redundant_constraints = r.CN + start.lost;  // inputs beyond the motions fight each other
  v.exactly_constrained = v.extra_motions == 0 && v.redundant_constraints == 0;
  v.summary = summary_sentence(v.extra_motions, v.redundant_constraints, intended);
  note_near_rank_change(v, r.circulation.solution.rank.distance(), r.FN > 0);

  std::vector<std::string> names;
  for (const auto& c : model.couplings) names.push_back(c.name);
  const auto e_count = model.couplings.size();

  // Extra motions: idle spins, then motions beyond the declared inputs.
  for (const auto& spin : idle) {
    for (const auto& s : spin.screws) {
      const std::string what = motion_text(embed(s, model.space), frame.length);
      VerdictState state{"extra motion",
                         fmt::format("idle spin of body '{}': {}", model.bodies[static_cast<std::size_t>(spin.body)], what), {}};
      state.participants.push_back({"body", model.bodies[static_cast<std::size_t>(spin.body)], 1.0, what});
      std::vector<double> size(e_count, 0.0);
      std::vector<std::string> detail(e_count, "lets the body spin: " + what);
      for (std::size_t e = 0; e < e_count; ++e)
        if (model.couplings[e].from == spin.body || model.couplings[e].to == spin.body) size[e] = 1.0;
      add_shares(state, size, names, detail);
      v.states.push_back(std::move(state));
    }
  }
  const int beyond = std::max(0, standing.FN - standing.idle - intended);
  if (beyond > 0 && r.FN > 0) {
    VerdictState state{"extra motion", fmt::format("{} beyond the {} declared", counted(beyond, "motion", "motions"),
                                                   counted(declared, "input", "inputs")), {}};
    std::vector<double> size(e_count, 0.0);
    std::vector<std::string> detail(e_count, "moves");
    for (std::size_t i = 0; i < r.motions.size(); ++i) {
      const Screw t = embed([&] {
        std::vector<double> c;
        for (const auto& x : r.motions[i].unit_screw.coordinates) c.push_back(x.get_d());
        return c;
      }(), model.space);
      size[static_cast<std::size_t>(r.motions[i].coupling)] += r.motion_magnitudes.values.row(static_cast<Eigen::Index>(i)).squaredNorm() * twist_size(t, frame);
    }
    add_shares(state, size, names, detail);
    v.states.push_back(std::move(state));
  }
  // Self-stresses: the wrench each coupling transmits, one state per action primary.
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
  v.motion_participants = strongest(v.states, "extra motion");
  v.constraint_participants = strongest(v.states, "self-stress");

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
  if (static_cast<int>(e_count) > kNetworkDesignSearchCouplings) {
    v.note = fmt::format("no change set searched: more than {} couplings", kNetworkDesignSearchCouplings);
    return v;
  }
  // Couplings in order of participation, the rest after them in model order.
  std::vector<int> order;
  for (const auto& list : {v.constraint_participants, v.motion_participants})
    for (const auto& p : list)
      for (std::size_t e = 0; e < e_count; ++e)
        if (p.kind == "coupling" && names[e] == p.name && std::find(order.begin(), order.end(), static_cast<int>(e)) == order.end())
          order.push_back(static_cast<int>(e));
  for (std::size_t e = 0; e < e_count; ++e)
    if (std::find(order.begin(), order.end(), static_cast<int>(e)) == order.end()) order.push_back(static_cast<int>(e));

  double work = 0.0;  // shared by both searches
  Search search = search_changes(model, options, r.exact, intended, start, order, true, work);
  if (search.result.score() > 0 || search.result.lost > 0)
    search = search_changes(model, options, r.exact, intended, start, order, false, work);
  // A set that removes some couplings and constrains others moves constraints, it does not
  // only drop them: say so instead of calling the removed coupling redundant.
  const bool constrains = std::any_of(search.changes.begin(), search.changes.end(), [&](const auto& entry) {
    return entry.second && freedoms(*entry.second, model.space) < freedoms(model.couplings[static_cast<std::size_t>(entry.first)], model.space);
  });
  for (const auto& [e, replacement] : search.changes) {
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
    v.changes.push_back(std::move(change));
  }
  if (v.changes.empty()) {
    v.note = work >= kNetworkDesignSearchWork
                 ? "no change set found within the search budget: analyse a smaller part of the network to get one"
                 : "no change of a single coupling type reduces the extra motions or redundant constraints";
    return v;
  }
  // Verified by a full re-analysis of the changed copy, with the user's arithmetic.
  network::AnalysisOptions full = options;
  full.primary.reset();
  full.values.clear();
  try {
    const Model changed = changed_model(model, search.changes);
    const network::NetworkResult after = network::analyse_network(changed, full);
    const Tally t = tally({after.FN, after.CN, idle_count(idle_motions(changed, after.exact, full.tolerances))}, intended);
    v.changes_verified = t.score() == 0 && t.lost == 0;
    v.becomes = fmt::format("FN = {}, CN = {}: {}{}", after.FN, after.CN,
                            v.changes_verified ? (intended == 0 ? std::string("exactly constrained, a structure") : "exactly constrained with " + counted(intended, "intended motion", "intended motions"))
                                               : constraint_words(t.extra, t.CN),
                            after.FN != r.FN ? fmt::format(" (FN was {})", r.FN) : "");
  } catch (const std::exception& error) {
    v.becomes = fmt::format("the changed model could not be analysed: {}", error.what());
  }
  if (!v.changes_verified && v.note.empty())
    v.note = work >= kNetworkDesignSearchWork ? "the change set found removes only part of the problem (search budget spent)"
                                              : "the change set found removes only part of the problem";
  return v;
}

}  // namespace kinestat::design
