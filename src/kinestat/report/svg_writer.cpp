// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/svg_writer.hpp"

#include "kinestat/report/markup_escape.hpp"
#include "kinestat/tolerances.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string_view>
#include <set>

namespace kinestat::report {

namespace {

struct P {
  double x = 0, y = 0;
};
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator*(double s, P a) { return {s * a.x, s * a.y}; }
double norm(P a) { return std::hypot(a.x, a.y); }
P unit(P a) {
  const double n = norm(a);
  return n > 0 ? P{a.x / n, a.y / n} : P{1, 0};
}

std::string f2(double v) { return fixed(v, 2); }
std::string pt(P p) { return f2(p.x) + "," + f2(p.y); }

std::string escape(const std::string& text) { return markup_escape(text); }

std::string header(double width, double height) {
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">\n"
      "<defs>\n"
      "<marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
      "orient=\"auto-start-reverse\" markerUnits=\"userSpaceOnUse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"context-stroke\"/></marker>\n"
      "<marker id=\"arrow-black\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"9\" markerHeight=\"9\" "
      "orient=\"auto\" markerUnits=\"userSpaceOnUse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#222\"/></marker>\n"
      "<marker id=\"arrow-green\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"8\" markerHeight=\"8\" "
      "orient=\"auto\" markerUnits=\"userSpaceOnUse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#1b7837\"/></marker>\n"
      "<marker id=\"arrow-orange\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"9\" markerHeight=\"9\" "
      "orient=\"auto\" markerUnits=\"userSpaceOnUse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#e66101\"/></marker>\n"
      "</defs>\n"
      "<rect x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n",
      fixed(width, 0), fixed(height, 0));
}

void text(std::string& out, P at, const std::string& content, const std::string& anchor = "middle",
          const std::string& extra = "") {
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"{}\"{}>{}</text>\n", f2(at.x), f2(at.y), anchor,
                     extra.empty() ? "" : " " + extra, escape(content));
}

// ---------------------------------------------------------------- graphs

/// A quadratic Bézier from a to b through control point c.
struct Curve {
  P a, c, b;
  P at(double t) const { return (1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b; }
  /// Control point of the piece between t0 and t1 (the curve's blossom).
  P control(double t0, double t1) const { return (1 - t0) * (1 - t1) * a + ((1 - t0) * t1 + t0 * (1 - t1)) * c + t0 * t1 * b; }
};

constexpr double kNodeRadius = 13;
/// A white outline behind edge labels so that lines under them do not hide them.
const std::string kHalo = "paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\"";
constexpr double kParallelSpacing = 26;

/// Curve between the centres of bodies i and j for the k-th of m parallel edges, oriented
/// from i to j.
Curve edge_curve(P pi, P pj, int k, int m, double spacing = kParallelSpacing) {
  const P mid = 0.5 * (pi + pj);
  const P d = unit(pj - pi);
  P normal{-d.y, d.x};
  const double offset = (k - (m - 1) / 2.0) * spacing;
  return {pi, mid + (2 * offset) * normal, pj};
}

/// The part of `curve` outside the two node circles.
Curve trimmed(const Curve& curve) {
  const P a = curve.a + kNodeRadius * unit(curve.c - curve.a);
  const P b = curve.b + (kNodeRadius + 1) * unit(curve.c - curve.b);
  // Keep the control point: the shape changes imperceptibly for short trims.
  return {a, curve.c, b};
}

std::string path_of(const Curve& c) { return "M" + pt(c.a) + " Q" + pt(c.c) + " " + pt(c.b); }

bool segments_cross(P a, P b, P c, P d) {
  const auto side = [](P p, P q, P r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
  const double d1 = side(a, b, c), d2 = side(a, b, d), d3 = side(c, d, a), d4 = side(c, d, b);
  constexpr double z = kDrawnZero;
  return ((d1 > z && d2 < -z) || (d1 < -z && d2 > z)) && ((d3 > z && d4 < -z) || (d3 < -z && d4 > z));
}

/// Bodies on a circle, the ground at the bottom. For up to kPermutedBodies bodies every
/// order of the others around the circle is tried and the first (in lexicographic order)
/// with the fewest crossing edges is taken; larger models keep body order.
constexpr int kPermutedBodies = 8;

std::vector<P> body_layout(const Scene& scene, P centre, double radius) {
  const int n = static_cast<int>(scene.bodies.size());
  std::vector<int> others;
  for (int b = 0; b < n; ++b)
    if (b != scene.ground) others.push_back(b);
  const auto place = [&](const std::vector<int>& order) {
    std::vector<P> at(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const int b = k == 0 ? scene.ground : order[static_cast<std::size_t>(k - 1)];
      const double angle = std::numbers::pi / 2 - 2 * std::numbers::pi * k / n;
      at[static_cast<std::size_t>(b)] = n == 1 ? centre : centre + radius * P{std::cos(angle), std::sin(angle)};
    }
    return at;
  };
  if (n > kPermutedBodies || n < 4) return place(others);
  std::set<std::pair<int, int>> pairs;
  for (const auto& edge : scene.edges) pairs.insert({std::min(edge.from, edge.to), std::max(edge.from, edge.to)});
  const std::vector<std::pair<int, int>> list(pairs.begin(), pairs.end());
  std::vector<int> best = others, order = others;
  int fewest = -1;
  do {
    const auto at = place(order);
    int crossings = 0;
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size(); ++j)
        if (segments_cross(at[static_cast<std::size_t>(list[i].first)], at[static_cast<std::size_t>(list[i].second)],
                           at[static_cast<std::size_t>(list[j].first)], at[static_cast<std::size_t>(list[j].second)]))
          ++crossings;
    if (fewest < 0 || crossings < fewest) fewest = crossings, best = order;
  } while (std::next_permutation(order.begin(), order.end()));
  return place(best);
}

/// For every edge: its index among the edges joining the same two bodies, and how many there are.
std::vector<std::pair<int, int>> parallel_index(const Scene& scene, const std::vector<int>& multiplicity) {
  std::map<std::pair<int, int>, int> total, seen;
  for (std::size_t e = 0; e < scene.edges.size(); ++e) {
    const auto& edge = scene.edges[e];
    total[{std::min(edge.from, edge.to), std::max(edge.from, edge.to)}] += multiplicity[e];
  }
  std::vector<std::pair<int, int>> out;
  for (std::size_t e = 0; e < scene.edges.size(); ++e) {
    const auto& edge = scene.edges[e];
    const auto key = std::make_pair(std::min(edge.from, edge.to), std::max(edge.from, edge.to));
    out.emplace_back(seen[key], total[key]);
    seen[key] += multiplicity[e];
  }
  return out;
}

/// Curve of the k-th parallel edge of `edge`, oriented from `from` to `to`, keeping the side
/// of the offset independent of orientation.
Curve oriented_curve(const std::vector<P>& at, const GraphEdge& edge, int k, int m, double spacing = kParallelSpacing) {
  const int lo = std::min(edge.from, edge.to), hi = std::max(edge.from, edge.to);
  Curve c = edge_curve(at[static_cast<std::size_t>(lo)], at[static_cast<std::size_t>(hi)], k, m, spacing);
  if (edge.from != lo) std::swap(c.a, c.b);
  return c;
}

const std::array<const char*, 8> kGroupColours = {"#ffffff", "#a6cee3", "#b2df8a", "#fdbf6f", "#cab2d6", "#fb9a99", "#ffff99", "#d9d9d9"};

/// Graphs of more bodies than this are drawn without names: on a circle of 0.64 × 380 px, more
/// names overlap one another and the edges (the text report and the HTML labels have them all).
constexpr std::size_t kNamedGraphBodies = 60;
bool graph_names_drawn(const Scene& scene) { return scene.bodies.size() <= kNamedGraphBodies; }

void draw_bodies(std::string& out, const Scene& scene, const std::vector<P>& at) {
  for (std::size_t b = 0; b < at.size(); ++b) {
    std::string fill = "white";
    if (scene.kind == io::ModelKind::structure && b < scene.group_of.size() && scene.group_of[b] > 0)
      fill = kGroupColours[static_cast<std::size_t>(1 + (scene.group_of[b] - 1) % 7)];
    const bool ground = static_cast<int>(b) == scene.ground;
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"#222\" stroke-width=\"{}\"/>\n", f2(at[b].x),
                       f2(at[b].y), fixed(kNodeRadius, 0), ground ? "#e0e0e0" : fill, ground ? "2.5" : "1.5");
    if (!graph_names_drawn(scene)) continue;
    if (scene.bodies[b].size() <= 2) {
      text(out, at[b] + P{0, 4}, scene.bodies[b]);
    } else {
      // Long names go outside the circle, away from the centre of the layout.
      P mean{0, 0};
      for (const P& p : at) mean = mean + p;
      mean = (1.0 / static_cast<double>(at.size())) * mean;
      const P out_dir = unit(at[b] - mean);
      const P anchor = at[b] + (kNodeRadius + 8) * out_dir;
      text(out, anchor + P{0, 4 + 4 * out_dir.y}, scene.bodies[b], out_dir.x > 0.3 ? "start" : (out_dir.x < -0.3 ? "end" : "middle"));
    }
  }
}

void panel_title(std::string& out, P at, const std::string& title, const std::string& subtitle) {
  text(out, at, title, "middle", "font-size=\"14\" font-weight=\"bold\"");
  text(out, at + P{0, 16}, subtitle, "middle", "font-size=\"11\" fill=\"#555\"");
}

/// Circuits of the coupling graph: an arc arrow at the centre of their edges (`middle`: the
/// middle of each edge), named by their chord.
void draw_circuits(std::string& out, const Scene& scene, const std::vector<P>& middle) {
  for (Eigen::Index row = 0; row < scene.B.rows(); ++row) {
    P mean{0, 0};
    int count = 0;
    for (Eigen::Index e = 0; e < scene.B.cols(); ++e)
      if (scene.B(row, e) != 0) {
        mean = mean + middle[static_cast<std::size_t>(e)];
        ++count;
      }
    if (count == 0) continue;
    mean = (1.0 / count) * mean;
    const double r = 16;
    const P start = mean + P{r, 0}, end = mean + P{0, -r};
    out += fmt::format("<path d=\"M{} A{},{} 0 1 1 {}\" fill=\"none\" stroke=\"#1b7837\" stroke-width=\"1.5\" marker-end=\"url(#arrow-green)\"/>\n",
                       pt(start), f2(r), f2(r), pt(end));
    std::string name;
    for (std::size_t e = 0; e < scene.edges.size(); ++e)
      if (!scene.edges[e].branch && scene.B(row, static_cast<Eigen::Index>(e)) != 0 && name.empty()) {
        // The circuit of a chord contains only that chord.
        name = scene.edges[e].name;
      }
    if (graph_names_drawn(scene)) text(out, mean + P{0, 4}, name, "middle", "font-size=\"10\" fill=\"#1b7837\"");
  }
}

/// The line a cutset is drawn along, through the middles `points` of its edges (mean `mean`):
/// across the edge for one edge, else ordered along the points' principal direction and
/// extended past both ends.
std::vector<P> cutset_line(const Scene& scene, const std::vector<P>& at, Eigen::Index row, std::vector<P> points, P mean) {
  if (points.size() == 1) {
    std::size_t e = 0;
    for (Eigen::Index c = 0; c < scene.Q.cols(); ++c)
      if (scene.Q(row, c) != 0) e = static_cast<std::size_t>(c);
    const auto& edge = scene.edges[e];
    const P d = unit(at[static_cast<std::size_t>(edge.to)] - at[static_cast<std::size_t>(edge.from)]);
    const P n{-d.y, d.x};
    return {points[0] - 22.0 * n, points[0] + 22.0 * n};
  }
  double sxx = 0, sxy = 0, syy = 0;
  for (const P& p : points) {
    const P q = p - mean;
    sxx += q.x * q.x;
    sxy += q.x * q.y;
    syy += q.y * q.y;
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  const P axis{std::cos(angle), std::sin(angle)};
  std::stable_sort(points.begin(), points.end(), [&](P a, P b) {
    return (a.x - mean.x) * axis.x + (a.y - mean.y) * axis.y < (b.x - mean.x) * axis.x + (b.y - mean.y) * axis.y;
  });
  std::vector<P> line;
  line.push_back(points.front() - 18.0 * unit(points[1] - points[0]));
  for (const P& p : points) line.push_back(p);
  line.push_back(points.back() + 18.0 * unit(points.back() - points[points.size() - 2]));
  return line;
}

/// Cutsets of the coupling graph: a dashed line through the middles of their edges, named by
/// their branch.
void draw_cutsets(std::string& out, const Scene& scene, const std::vector<P>& at, const std::vector<P>& middle) {
  for (Eigen::Index row = 0; row < scene.Q.rows(); ++row) {
    std::vector<P> points;
    std::string name;
    for (Eigen::Index e = 0; e < scene.Q.cols(); ++e)
      if (scene.Q(row, e) != 0) {
        points.push_back(middle[static_cast<std::size_t>(e)]);
        if (scene.edges[static_cast<std::size_t>(e)].branch && name.empty()) name = scene.edges[static_cast<std::size_t>(e)].name;
      }
    if (points.empty()) continue;
    P mean{0, 0};
    for (const P& p : points) mean = mean + p;
    mean = (1.0 / static_cast<double>(points.size())) * mean;
    const std::vector<P> line = cutset_line(scene, at, row, std::move(points), mean);
    std::string d = "M" + pt(line[0]);
    for (std::size_t i = 1; i < line.size(); ++i) d += " L" + pt(line[i]);
    out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#762a83\" stroke-width=\"1.5\" stroke-dasharray=\"6,4\"/>\n", d);
    const P label_at = line.back() + 10.0 * unit(line.back() - line[line.size() - 2]);
    if (graph_names_drawn(scene)) text(out, label_at + P{0, 4}, name, "middle", "font-size=\"10\" fill=\"#762a83\"");
  }
}

/// Coupling graph with tree, chords, circuits and cutsets in the square panel at `origin`.
void coupling_graph_panel(std::string& out, const Scene& scene, P origin, double size) {
  const P centre = origin + P{size / 2, size / 2 + 20};
  const auto at = body_layout(scene, centre, size * 0.32);
  const bool network = scene.kind == io::ModelKind::network;
  panel_title(out, origin + P{size / 2, 22}, network ? "coupling graph" : "bodies and pairs",
              !network        ? "pairs with freedoms f; colour: structural group"
              : scene.sparse  ? "tree from the ground: branches thick, chords thin"
                              : "tree branches thick, chords thin; circuits and cutsets");
  const std::vector<int> ones(scene.edges.size(), 1);
  const auto index = parallel_index(scene, ones);
  std::vector<P> middle(scene.edges.size());
  for (std::size_t e = 0; e < scene.edges.size(); ++e) {
    const auto& edge = scene.edges[e];
    const Curve c = oriented_curve(at, edge, index[e].first, index[e].second);
    middle[e] = c.at(0.5);
    out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#222\" stroke-width=\"{}\"{}/>\n", path_of(trimmed(c)),
                       edge.branch ? "3.5" : "1.2", network ? " marker-end=\"url(#arrow-black)\"" : "");
    const P d = unit(c.b - c.a);
    const P side = P{-d.y, d.x};
    const std::string label = network ? edge.name : edge.name + " (f=" + std::to_string(edge.f) + ")";
    if (graph_names_drawn(scene)) text(out, middle[e] + 11.0 * side + P{0, 4}, label, "middle", "font-style=\"italic\" " + kHalo);
  }
  if (network) {
    draw_circuits(out, scene, middle);
    draw_cutsets(out, scene, at, middle);
  }
  draw_bodies(out, scene, at);
}

/// Motion graph (series) or action graph (parallel) of Fig. 3 in the panel at `origin`.
void expanded_graph_panel(std::string& out, const Scene& scene, P origin, double size, bool motions) {
  const P centre = origin + P{size / 2, size / 2 + 20};
  const auto at = body_layout(scene, centre, size * 0.32);
  panel_title(out, origin + P{size / 2, 22}, motions ? "motion graph" : "action graph",
              motions ? "each coupling as f edges in series" : "each coupling as c edges in parallel");
  std::vector<int> multiplicity;
  for (const auto& edge : scene.edges) multiplicity.push_back(motions ? 1 : std::max(edge.c, 0));
  const auto index = parallel_index(scene, multiplicity);
  for (std::size_t e = 0; e < scene.edges.size(); ++e) {
    const auto& edge = scene.edges[e];
    const auto& names = motions ? edge.motion_names : edge.action_names;
    if (motions) {
      const Curve c = oriented_curve(at, edge, index[e].first, index[e].second);
      const Curve t = trimmed(c);
      const int f = std::max(edge.f, 1);
      for (int s = 0; s < f; ++s) {
        const double t0 = static_cast<double>(s) / f, t1 = static_cast<double>(s + 1) / f;
        const Curve piece{t.at(t0), t.control(t0, t1), t.at(t1)};
        out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.3\"{}/>\n", path_of(piece),
                           edge.f > 0 ? "" : " stroke-dasharray=\"2,3\"");
        if (s + 1 < f)
          out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"#222\"/>\n", f2(piece.b.x), f2(piece.b.y));
        const P m = piece.at(0.5);
        const P d = unit(piece.b - piece.a);
        const std::string label = s < static_cast<int>(names.size()) ? names[static_cast<std::size_t>(s)] : edge.name;
        if (graph_names_drawn(scene)) text(out, m + 9.0 * P{-d.y, d.x} + P{0, 4}, label, "middle", "font-size=\"10\" font-style=\"italic\" " + kHalo);
      }
    } else {
      for (int s = 0; s < edge.c; ++s) {
        const int k = index[e].first + s;
        const Curve c = oriented_curve(at, edge, k, index[e].second, 14);
        out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.1\"/>\n", path_of(trimmed(c)));
        const P m = c.at(0.5 + 0.14 * (k % 3 - 1));
        const std::string label = s < static_cast<int>(names.size()) ? names[static_cast<std::size_t>(s)] : edge.name;
        out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"22\" height=\"12\" fill=\"white\"/>\n", f2(m.x - 11), f2(m.y - 7));
        if (graph_names_drawn(scene)) text(out, m + P{0, 3}, label, "middle", "font-size=\"10\" font-style=\"italic\" " + kHalo);
      }
    }
  }
  draw_bodies(out, scene, at);
}

// ---------------------------------------------------------------- mechanisms

struct View {
  int dimension = 2;
  double cy = std::cos(-0.6), sy = std::sin(-0.6);  // yaw about z
  double cp = std::cos(0.45), sp = std::sin(0.45);  // pitch
  /// Screen coordinates with y up, before fitting.
  P project(const Eigen::Vector3d& v) const {
    if (dimension == 2) return {v.x(), v.y()};
    const double x = cy * v.x() - sy * v.y();
    const double depth = sy * v.x() + cy * v.y();
    return {x, v.z() * cp + depth * sp};
  }
};

struct Fit {
  double scale = 1, ox = 0, oy = 0;
  P operator()(P p) const { return {ox + scale * p.x, oy - scale * p.y}; }
};

/// Colours of the kinds of generalised stress resultant (Scene::SceneStress::kind). Elongation
/// follows the sign (tension positive: red; compression: blue); the other kinds are named in the
/// legend with their own hue, the width giving the magnitude.
std::string stress_colour(const std::string& kind, double value) {
  if (kind == "bending") return "#7b3294";
  if (kind == "torsion") return "#1b9e77";
  if (kind == "rigid") return "#8c510a";
  return value > 0 ? "#c0392b" : "#2166ac";
}

/// A round length (1, 2 or 5 times a power of ten) near `target`.
double round_length(double target) {
  if (!(target > 0) || !std::isfinite(target)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (double step : {1.0, 2.0, 5.0})
    if (step * decade >= target * 0.75) return step * decade;
  return 10 * decade;
}

/// Splits `content` into lines of at most about `width` characters at spaces.
std::vector<std::string> wrapped(const std::string& content, std::size_t width) {
  std::vector<std::string> lines;
  std::string line, word;
  const auto flush_word = [&] {
    if (word.empty()) return;
    if (!line.empty() && line.size() + 1 + word.size() > width) lines.push_back(line), line.clear();
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (char c : content) {
    if (c == ' ') flush_word();
    else word += c;
  }
  flush_word();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

/// The verdict line(s) under a picture's title: the verdict's summary, or without one the
/// classification of the summary facts.
std::vector<std::string> verdict_lines(const Scene& scene) {
  std::string content;
  if (scene.verdict) {
    content = "Verdict: " + scene.verdict->summary;
    if (!scene.verdict->changes.empty()) {
      std::string changes;
      for (const auto& change : scene.verdict->changes) {
        // "remove bar 8", "add bar E–G (a bar of length 2)", "release T1a -> spherical".
        std::string text = change.action + " " + change.target;
        if (change.action == "remove" || change.action == "add") text = change.action + " " + change.target_kind + " " + change.target;
        if (change.action == "add" && !change.becomes.empty()) text += " (" + change.becomes + ")";
        else if (change.action != "remove" && !change.becomes.empty()) text += " -> " + change.becomes;
        changes += (changes.empty() ? "" : "; ") + text;
      }
      content += " Change: " + changes + (scene.verdict->changes_verified ? " (verified by re-analysis)." : ".");
    }
  } else {
    for (const auto& fact : scene.summary)
      if (fact.key == "class") content = fact.value;
  }
  return wrapped(content, 95);
}

}  // namespace

std::string graph_svg(const Scene& scene) {
  const double size = 380;
  const bool network = scene.kind == io::ModelKind::network;
  const double width = network ? 3 * size : size + 160;
  // The verdict, when the analysis gave one, under the model's name.
  const std::vector<std::string> verdict = scene.verdict ? verdict_lines(scene) : std::vector<std::string>{};
  const bool named = graph_names_drawn(scene);
  const double height = size + 40 + 16.0 * static_cast<double>(verdict.size() + (named ? 0 : 1));
  std::string out = header(width, height);
  text(out, P{width / 2, size + 28}, scene.name, "middle", "font-size=\"12\" fill=\"#333\"");
  for (std::size_t i = 0; i < verdict.size(); ++i)
    text(out, P{width / 2, size + 46 + 16.0 * static_cast<double>(i)}, verdict[i], "middle", "class=\"verdict\" font-size=\"12\" fill=\"#333\"");
  if (!named)
    text(out, P{width / 2, size + 46 + 16.0 * static_cast<double>(verdict.size())},
         fmt::format("{} bodies: names left out, they would overlap (all names: text report; HTML report: labels)", scene.bodies.size()),
         "middle", "font-size=\"11\" fill=\"#555\"");
  coupling_graph_panel(out, scene, P{network ? 0.0 : 80.0, 0}, size);
  if (network) {
    expanded_graph_panel(out, scene, P{size, 0}, size, true);
    expanded_graph_panel(out, scene, P{2 * size, 0}, size, false);
  }
  out += "</svg>\n";
  return out;
}

namespace {

/// Support symbols at node `p` (screen coordinates): fixed (clamped) a block with hatching,
/// pinned a triangle, roller a triangle on wheels with a double arrow along the free direction.
void draw_support(std::string& out, const SceneNode& node, P p, const View& view) {
  if (node.support.empty()) return;
  out += fmt::format("<g class=\"support\" data-node=\"{}\" data-support=\"{}\">", escape(node.name), node.support);
  if (node.support == "fixed") {
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"18\" height=\"9\" fill=\"#bbb\" stroke=\"#222\" stroke-width=\"1\"/>", f2(p.x - 9), f2(p.y + 4));
    for (int i = 0; i < 4; ++i)
      out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#222\" stroke-width=\"0.8\"/>", f2(p.x - 9 + 5 * i),
                         f2(p.y + 18), f2(p.x - 5 + 5 * i), f2(p.y + 13));
  } else {
    out += fmt::format("<path d=\"M{} L{} L{} z\" fill=\"#ddd\" stroke=\"#222\" stroke-width=\"1\"/>", pt(p), pt(p + P{-7, 12}),
                       pt(p + P{7, 12}));
    if (node.support == "roller") {
      out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"2.5\" fill=\"white\" stroke=\"#222\" stroke-width=\"1\"/>", f2(p.x - 4), f2(p.y + 15));
      out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"2.5\" fill=\"white\" stroke=\"#222\" stroke-width=\"1\"/>", f2(p.x + 4), f2(p.y + 15));
      for (const auto& direction : node.free_directions) {
        P d = view.project(direction);
        if (norm(d) < kDrawnZero) continue;
        d = unit(P{d.x, -d.y});
        const P a = p + P{0, 24} - 12.0 * d, b = p + P{0, 24} + 12.0 * d;
        out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#222\" stroke-width=\"1\" marker-start=\"url(#arrow)\" "
                           "marker-end=\"url(#arrow)\"/>", f2(a.x), f2(a.y), f2(b.x), f2(b.y));
      }
    }
  }
  out += "</g>\n";
}

/// Boxes of the labels and marks placed so far in a drawing: a label takes the first of its
/// candidate places whose box meets none of them, and is left out (counted) when every place is
/// taken, rather than drawn over another label or a node.
class LabelSpace {
 public:
  struct Place {
    P at;                ///< the text's anchor point (baseline)
    const char* anchor;  ///< "start", "middle" or "end"
  };
  /// Mean advance of a glyph in Helvetica-like fonts, in em (most labels are lower-case and digits).
  static constexpr double kAdvance = 0.6;

  /// Labels stay inside x0..x1, y0..y1 (the drawing area): a place that would cross the edge is
  /// moved in.
  LabelSpace(double x0, double y0, double x1, double y1) : area_{x0, y0, x1, y1} {}

  /// A mark (node circle, coupling square) of half-size `half` at `centre` that labels avoid.
  void block(P centre, double half) { boxes_.push_back({centre.x - half, centre.y - half, centre.x + half, centre.y + half}); }

  /// A line of the model (element `id`) that labels keep clear of when they can.
  void avoid(P a, P b, int id) { segments_.push_back({a, b, id}); }

  /// The first free place for `content` at `font_size`, which is then taken; none when all are.
  /// Places clear of the model's lines (other than line `own`) come first.
  std::optional<Place> place(const std::vector<Place>& candidates, const std::string& content, double font_size, int own = -1) {
    for (const bool clear_of_lines : {true, false}) {
      for (Place candidate : candidates) {
        Box b = box(candidate, content, font_size);
        // Moved inside the drawing area (a label wider than the area keeps its left edge in).
        const double dx = b.x1 > area_.x1 ? area_.x1 - b.x1 : 0.0, dx0 = b.x0 + dx < area_.x0 ? area_.x0 - (b.x0 + dx) : 0.0;
        const double dy = b.y1 > area_.y1 ? area_.y1 - b.y1 : (b.y0 < area_.y0 ? area_.y0 - b.y0 : 0.0);
        candidate.at = candidate.at + P{dx + dx0, dy};
        b = box(candidate, content, font_size);
        if (std::any_of(boxes_.begin(), boxes_.end(), [&](const Box& o) { return b.meets(o); })) continue;
        if (clear_of_lines && std::any_of(segments_.begin(), segments_.end(), [&](const Segment& s) { return s.id != own && b.crosses(s.a, s.b); }))
          continue;
        boxes_.push_back(b);
        return candidate;
      }
    }
    ++left_out_;
    return std::nullopt;
  }
  int left_out() const { return left_out_; }

 private:
  struct Box {
    double x0, y0, x1, y1;
    bool meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
    // Whether segment a-b enters the box (Liang-Barsky clipping).
    bool crosses(P a, P b) const {
      double t0 = 0, t1 = 1;
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
      for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
          if (q[k] < 0) return false;
        } else {
          const double t = q[k] / p[k];
          if (p[k] < 0) t0 = std::max(t0, t);
          else t1 = std::min(t1, t);
          if (t0 > t1) return false;
        }
      }
      return true;
    }
  };
  struct Segment {
    P a, b;
    int id;
  };
  Box area_;
  std::vector<Segment> segments_;
  static Box box(const Place& p, const std::string& content, double size) {
    // Glyphs, not bytes: UTF-8 continuation bytes (10xxxxxx) do not start a glyph.
    const auto glyphs = std::count_if(content.begin(), content.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
    const double w = kAdvance * size * static_cast<double>(glyphs);
    const std::string_view anchor = p.anchor;
    const double x0 = anchor == "middle" ? p.at.x - w / 2 : (anchor == "end" ? p.at.x - w : p.at.x);
    return {x0, p.at.y - 0.8 * size, x0 + w, p.at.y + 0.25 * size};
  }
  std::vector<Box> boxes_;
  int left_out_ = 0;
};

}  // namespace

namespace {
// "of 3", or "first 8 of 43" when the scene holds only the first of the model's states.
std::string out_of(std::size_t drawn, std::size_t total) {
  return total > drawn ? fmt::format("first {} of {}", drawn, total) : fmt::format("of {}", drawn);
}

// Sections of mechanism_svg: the layout first, then the drawing in painting order (lines,
// labels, couplings, screw axes, nodes, arrows, axes and scale bar, legend).

// What mechanism_svg draws and where: the mode and self-stress drawn, the nodes projected, the
// mode's arrows and the fit of the drawing to the canvas (pixels, y down).
struct MechanismLayout {
  View view;
  const SceneMode* mode = nullptr;
  const SceneStress* stress = nullptr;
  std::vector<std::string> verdict;
  double largest_stress = 0;
  std::set<std::string> kinds;  ///< kinds of resultant the self-stress loads
  double width = 640, margin = 50, top = 0, drawing_height = 420, height = 0;
  std::vector<P> at;     ///< nodes projected, before fitting
  std::vector<P> arrow;  ///< mode arrows, before fitting
  double extent = 0;     ///< the model's projected size
  Fit fit;
  // A mode alone: the undeformed shape in light grey under the displaced shape drawn in full.
  // A mode with a self-stress: the stress colours stay on the undeformed shape and the
  // displaced shape is a thin dashed orange outline.
  bool displaced_in_full = false;
  double shift = 0;  ///< 1 when the shape is drawn displaced by the arrows
};

struct Bounds {
  P lo{1e300, 1e300}, hi{-1e300, -1e300};
  void include(P p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
};

// Mode arrows: the largest is a fifth of the drawing; the displaced shape ends at the tips.
void scale_mode_arrows(MechanismLayout& l, const Scene& scene, Bounds& bounds) {
  double largest = 0;
  for (std::size_t i = 0; i < l.at.size(); ++i) {
    l.arrow[i] = l.view.project(scene.nodes[i].position + l.mode->velocity[i]) - l.at[i];
    largest = std::max(largest, norm(l.arrow[i]));
  }
  for (std::size_t i = 0; i < l.at.size(); ++i) {
    l.arrow[i] = largest > 0 && norm(l.arrow[i]) > kDrawnZero * largest ? (0.2 * l.extent / largest) * l.arrow[i] : P{0, 0};
    bounds.include(l.at[i] + l.arrow[i]);
  }
}

// Screw axes (networks) are drawn 0.3 of the model size to either side of their point:
// keep them inside the drawing.
void include_screws(const MechanismLayout& l, const std::vector<SceneScrew>& screws, Bounds& bounds) {
  for (const auto& screw : screws) {
    const std::vector<Eigen::Vector3d> ends =
        screw.pure ? std::vector<Eigen::Vector3d>{screw.anchor, screw.anchor + 0.15 * l.extent * screw.direction}
                   : std::vector<Eigen::Vector3d>{screw.point - 0.3 * l.extent * screw.direction, screw.point + 0.3 * l.extent * screw.direction};
    for (const auto& end : ends) bounds.include(l.view.project(end));
  }
}

MechanismLayout mechanism_layout(const Scene& scene, const MechanismDrawing& drawing) {
  MechanismLayout l;
  l.view.dimension = scene.dimension;
  l.verdict = verdict_lines(scene);
  l.mode = drawing.mode >= 1 && drawing.mode <= static_cast<int>(scene.modes.size())
               ? &scene.modes[static_cast<std::size_t>(drawing.mode - 1)]
               : nullptr;
  l.stress = drawing.stress >= 1 && drawing.stress <= static_cast<int>(scene.stresses.size())
                 ? &scene.stresses[static_cast<std::size_t>(drawing.stress - 1)]
                 : nullptr;
  if (scene.large) l.mode = nullptr, l.stress = nullptr;
  // Legend lines, known before the layout so the drawing can make room for them.
  if (l.stress) {
    for (std::size_t e = 0; e < l.stress->value.size(); ++e) {
      l.largest_stress = std::max(l.largest_stress, std::abs(l.stress->value[e]));
      if (e < l.stress->kind.size() && !l.stress->kind[e].empty() && l.stress->value[e] != 0.0) l.kinds.insert(l.stress->kind[e]);
    }
  }
  l.top = 40 + 16.0 * static_cast<double>(l.verdict.size());
  bool any_sheet = false;
  for (const auto& element : scene.elements) any_sheet = any_sheet || element.sheet_across.has_value();
  const double legend = 48 + 20.0 * ((l.mode ? 3 : 0) + (l.stress ? 3 : 0) + (any_sheet ? 1 : 0));
  l.height = l.top + l.drawing_height + legend;
  for (const auto& node : scene.nodes) l.at.push_back(l.view.project(node.position));
  Bounds bounds;
  for (const P& p : l.at) bounds.include(p);
  if (l.at.empty()) bounds.lo = bounds.hi = P{0, 0};
  l.extent = std::max({bounds.hi.x - bounds.lo.x, bounds.hi.y - bounds.lo.y, kCoincident});
  l.arrow.assign(l.at.size(), P{0, 0});
  if (l.mode) scale_mode_arrows(l, scene, bounds);
  if (l.mode) include_screws(l, l.mode->twists, bounds);
  if (l.stress) include_screws(l, l.stress->wrenches, bounds);
  const P lo = bounds.lo, hi = bounds.hi;
  const double span_x = std::max(hi.x - lo.x, kCoincident * l.extent), span_y = std::max(hi.y - lo.y, kCoincident * l.extent);
  l.fit.scale = std::min((l.width - 2 * l.margin) / span_x, (l.drawing_height - 2 * l.margin) / span_y);
  if (!std::isfinite(l.fit.scale) || l.fit.scale <= 0) l.fit.scale = 1;
  l.fit.ox = l.width / 2 - l.fit.scale * (lo.x + hi.x) / 2;
  l.fit.oy = l.top + l.drawing_height / 2 + l.fit.scale * (lo.y + hi.y) / 2;
  l.displaced_in_full = l.mode && !l.stress;
  l.shift = l.displaced_in_full ? 1.0 : 0.0;
  return l;
}

// A model too large to label: every element in one path, and a note.
void draw_large_model(std::string& out, const Scene& scene, const MechanismLayout& l) {
  std::string d;
  for (const auto& element : scene.elements)
    d += "M" + pt(l.fit(l.at[static_cast<std::size_t>(element.a)])) + "L" + pt(l.fit(l.at[static_cast<std::size_t>(element.b)]));
  out += "<path d=\"" + d + "\" fill=\"none\" stroke=\"#333\" stroke-width=\"0.5\"/>\n";
  text(out, P{l.width / 2, l.height - 20},
       fmt::format("{} elements: drawn as one path without labels, modes or stresses", scene.elements.size()), "middle",
       "font-size=\"11\" fill=\"#555\"");
}

void svg_line(std::string& out, P a, P b, const std::string& colour, const std::string& stroke, const std::string& extra) {
  out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\"{}/>\n", f2(a.x),
                     f2(a.y), f2(b.x), f2(b.y), colour, stroke, extra);
}

// Lines in their configuration style: rigid bodies as wide light bands, flexures (beams) as
// thin dark lines, trusses as lines, network links grey.
std::pair<std::string, std::string> element_style(const SceneElement& element) {
  if (element.type == "rigid") return {"#9fb3c8", "8"};
  if (element.type == "beam") return {"#222", "2.5"};
  if (element.type == "link") return {"#555", "3"};
  return {"#333", "2"};
}

// Sheets (leaf springs) as light quadrilaterals under their centre lines; whether there are any.
bool draw_sheets(std::string& out, const Scene& scene, const MechanismLayout& l) {
  bool sheets = false;
  for (const auto& element : scene.elements) {
    if (!element.sheet_across) continue;
    sheets = true;
    const auto ia = static_cast<std::size_t>(element.a), ib = static_cast<std::size_t>(element.b);
    const Eigen::Vector3d pa = scene.nodes[ia].position, pb = scene.nodes[ib].position;
    const Eigen::Vector3d half = 0.5 * kSheetWidth * (pb - pa).norm() * *element.sheet_across;
    const P a1 = l.fit(l.view.project(pa + half) + l.shift * l.arrow[ia]), a2 = l.fit(l.view.project(pa - half) + l.shift * l.arrow[ia]);
    const P b1 = l.fit(l.view.project(pb + half) + l.shift * l.arrow[ib]), b2 = l.fit(l.view.project(pb - half) + l.shift * l.arrow[ib]);
    out += fmt::format("<path class=\"sheet\" data-element=\"{}\" d=\"M{} L{} L{} L{} z\" fill=\"#efe3c8\" fill-opacity=\"0.85\" stroke=\"#b59b6a\" stroke-width=\"0.8\"/>\n",
                       escape(element.name), pt(a1), pt(b1), pt(b2), pt(a2));
  }
  return sheets;
}

// The elements: the undeformed shape under a displaced one, sheets, the elements coloured by
// the self-stress, the dashed displaced outline. Returns whether there are sheets.
bool draw_elements(std::string& out, const Scene& scene, const MechanismLayout& l) {
  if (l.displaced_in_full) {
    for (const auto& element : scene.elements)
      svg_line(out, l.fit(l.at[static_cast<std::size_t>(element.a)]), l.fit(l.at[static_cast<std::size_t>(element.b)]), "#cccccc",
               element.type == "rigid" ? "6" : "2", " class=\"undeformed\"");
  }
  const bool sheets = draw_sheets(out, scene, l);
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const auto& element = scene.elements[e];
    const auto ia = static_cast<std::size_t>(element.a), ib = static_cast<std::size_t>(element.b);
    const P a = l.fit(l.at[ia] + l.shift * l.arrow[ia]), b = l.fit(l.at[ib] + l.shift * l.arrow[ib]);
    auto [colour, width_text] = element_style(element);
    std::string extra = " data-element=\"" + escape(element.name) + "\"";
    if (l.stress && l.largest_stress > 0 && e < l.stress->value.size()) {
      const double v = l.stress->value[e];
      const std::string kind = e < l.stress->kind.size() ? l.stress->kind[e] : "";
      if (std::abs(v) > kDrawnZero * l.largest_stress) {
        colour = stress_colour(kind, v);
        width_text = fixed(1.5 + 3.5 * std::abs(v) / l.largest_stress, 2);
        extra += " data-kind=\"" + kind + "\" data-value=\"" + fixed(v, 6) + "\"";
      } else {
        colour = "#bbbbbb";
      }
    }
    svg_line(out, a, b, colour, width_text, extra);
  }
  if (l.mode && !l.displaced_in_full) {
    for (const auto& element : scene.elements) {
      const auto ia = static_cast<std::size_t>(element.a), ib = static_cast<std::size_t>(element.b);
      svg_line(out, l.fit(l.at[ia] + l.arrow[ia]), l.fit(l.at[ib] + l.arrow[ib]), "#e66101", "1",
               " stroke-dasharray=\"4,3\" class=\"displaced\"");
    }
  }
  return sheets;
}

// Labels never cover each other, a node or a coupling's square: the marks and lines are
// blocked first, then node names take their places (the four corners around the node). The
// node labels are drawn later, over the nodes.
std::vector<std::optional<LabelSpace::Place>> place_node_labels(LabelSpace& labels, const Scene& scene, const MechanismLayout& l) {
  const bool label_nodes = scene.nodes.size() <= 200;
  const std::size_t labelled = scene.kind == io::ModelKind::network ? scene.bodies.size() : scene.nodes.size();
  for (std::size_t i = 0; i < scene.nodes.size(); ++i)
    if (scene.kind != io::ModelKind::network || i < scene.bodies.size()) labels.block(l.fit(l.at[i] + l.shift * l.arrow[i]), 4.5);
  for (const auto& glyph : scene.glyphs) labels.block(l.fit(l.view.project(glyph.point)), 5.5);
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const auto ia = static_cast<std::size_t>(scene.elements[e].a), ib = static_cast<std::size_t>(scene.elements[e].b);
    labels.avoid(l.fit(l.at[ia] + l.shift * l.arrow[ia]), l.fit(l.at[ib] + l.shift * l.arrow[ib]), static_cast<int>(e));
  }
  std::vector<std::optional<LabelSpace::Place>> node_label(scene.nodes.size());
  for (std::size_t i = 0; label_nodes && i < std::min(labelled, scene.nodes.size()); ++i) {
    const P p = l.fit(l.at[i]);
    node_label[i] = labels.place({{p + P{-7, -7}, "end"}, {p + P{7, -7}, "start"}, {p + P{-7, 15}, "end"}, {p + P{7, 15}, "start"}},
                                 scene.nodes[i].name, 11);
  }
  return node_label;
}

// Element labels beside the element (mid-length first, then towards either end), for readable sizes.
void draw_element_labels(std::string& out, LabelSpace& labels, const Scene& scene, const MechanismLayout& l) {
  if (scene.kind != io::ModelKind::framework || scene.elements.size() > 60) return;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const auto& element = scene.elements[e];
    if (!element.label) continue;
    const auto ia = static_cast<std::size_t>(element.a), ib = static_cast<std::size_t>(element.b);
    const P a = l.fit(l.at[ia]), b = l.fit(l.at[ib]);
    const P d = unit(b - a);
    std::vector<LabelSpace::Place> places;
    for (double t : {0.5, 0.35, 0.65, 0.2, 0.8})
      for (double side : {8.0, -8.0}) places.push_back({a + t * (b - a) + side * P{-d.y, d.x} + P{0, 3}, "middle"});
    if (const auto place = labels.place(places, element.name, 9, static_cast<int>(e)))
      text(out, place->at, element.name, place->anchor, "class=\"element-label\" font-size=\"9\" font-style=\"italic\" fill=\"#666\" " + kHalo);
  }
}

// Coupling glyphs: a square at the point, the axis as a dash-dotted line.
void draw_glyphs(std::string& out, LabelSpace& labels, const Scene& scene, const MechanismLayout& l) {
  for (const auto& glyph : scene.glyphs) {
    const P p = l.fit(l.view.project(glyph.point));
    const auto axis = glyph.axis ? glyph.axis : glyph.normal;
    if (axis && axis->norm() > 0) {
      const Eigen::Vector3d u = axis->normalized() * 0.18 * l.extent;
      const P a = l.fit(l.view.project(glyph.point - u)), b = l.fit(l.view.project(glyph.point + u));
      if (norm(b - a) > 2)
        out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#1b7837\" stroke-width=\"1\" stroke-dasharray=\"8,3,2,3\"/>\n",
                           f2(a.x), f2(a.y), f2(b.x), f2(b.y));
    }
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"10\" height=\"10\" fill=\"white\" stroke=\"#1b7837\" stroke-width=\"1.5\"/>\n",
                       f2(p.x - 5), f2(p.y - 5));
    // Couplings at the same point get their labels one below the other.
    const std::string name = glyph.name + " (" + glyph.type + ")";
    std::vector<LabelSpace::Place> places;
    for (int k = 0; k < 4; ++k) places.push_back({p + P{8, 14.0 + 12.0 * k}, "start"});
    for (int k = 0; k < 4; ++k) places.push_back({p + P{-8, 14.0 + 12.0 * k}, "end"});
    if (const auto place = labels.place(places, name, 10))
      text(out, place->at, name, place->anchor, "class=\"coupling-label\" font-size=\"10\" fill=\"#1b7837\" " + kHalo);
  }
}

// Labels of screws near one place are stacked upwards, 12 px apart, to the right or the left.
void screw_label(std::string& out, LabelSpace& labels, P at_point, const std::string& content, const std::string& colour) {
  std::vector<LabelSpace::Place> places;
  for (int k = 0; k < 5; ++k) places.push_back({at_point + P{8, -8.0 - 12.0 * k}, "start"});
  for (int k = 0; k < 5; ++k) places.push_back({at_point + P{-8, -8.0 - 12.0 * k}, "end"});
  if (const auto place = labels.place(places, content, 10))
    text(out, place->at, content, place->anchor, "class=\"screw-label\" font-size=\"10\" fill=\"" + colour + "\" " + kHalo);
}

// How a screw axis is drawn: colour, arrow marker, class, and whether the screws are twists
// (of a mode) or wrenches (of a self-stress).
struct ScrewStyle {
  std::string colour, marker, cls;
  bool twist;
};

// Networks: the screw axes of the mode (body twists) or of the self-stress (coupling wrenches).
void draw_screw_axes(std::string& out, LabelSpace& labels, const MechanismLayout& l, const std::vector<SceneScrew>& screws,
                     const ScrewStyle& style) {
  const std::string& colour = style.colour;
  double largest = 0;
  for (const auto& screw : screws) largest = std::max(largest, screw.magnitude);
  for (const auto& screw : screws) {
    const P anchor = l.fit(l.view.project(screw.point));
    std::string label;
    if (screw.pure) {
      const Eigen::Vector3d u = screw.direction * 0.15 * l.extent;
      const P a = l.fit(l.view.project(screw.anchor)), b = l.fit(l.view.project(screw.anchor + u));
      if (norm(b - a) > 2)
        out += fmt::format("<line class=\"{}\" data-name=\"{}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2.5\" marker-end=\"url(#{})\"/>\n",
                           style.cls, escape(screw.name), f2(a.x), f2(a.y), f2(b.x), f2(b.y), colour, style.marker);
      label = fmt::format("{}: {} {}", screw.name, style.twist ? "translation |v| =" : "couple |M| =", fixed(screw.magnitude, 3));
      screw_label(out, labels, a, label, colour);
      continue;
    }
    const Eigen::Vector3d u = screw.direction * 0.3 * l.extent;
    const P a = l.fit(l.view.project(screw.point - u)), b = l.fit(l.view.project(screw.point + u));
    if (norm(b - a) > 2) {
      out += fmt::format("<line class=\"{}\" data-name=\"{}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"{}\" stroke-dasharray=\"10,3,2,3\" marker-end=\"url(#{})\"/>\n",
                         style.cls, escape(screw.name), f2(a.x), f2(a.y), f2(b.x), f2(b.y), colour,
                         fixed(1.2 + 2.0 * screw.magnitude / std::max(largest, 1e-300), 2), style.marker);
    } else {
      // An axis along the line of sight (planar twists): the instant centre.
      out += fmt::format("<g class=\"{}\" data-name=\"{}\"><circle cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>"
                         "<circle cx=\"{}\" cy=\"{}\" r=\"1.8\" fill=\"{}\"/></g>\n",
                         style.cls, escape(screw.name), f2(anchor.x), f2(anchor.y), colour, f2(anchor.x), f2(anchor.y), colour);
    }
    label = fmt::format("{}: {} = {}{}", screw.name, style.twist ? "|\u03c9|" : "|F|", fixed(screw.magnitude, 3),
                        std::abs(screw.pitch) > kScrewZero * l.extent ? ", pitch " + fixed(screw.pitch, 3) : "");
    screw_label(out, labels, anchor, label, colour);
  }
}

// Supports, node circles (displaced with the mode when drawn in full) and node labels; then the
// mode's arrows.
void draw_nodes_and_arrows(std::string& out, const Scene& scene, const MechanismLayout& l,
                           const std::vector<std::optional<LabelSpace::Place>>& node_label) {
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    const P p = l.fit(l.at[i]);
    if (scene.kind == io::ModelKind::framework) draw_support(out, scene.nodes[i], p, l.view);
    if (scene.kind == io::ModelKind::network && i >= scene.bodies.size()) continue;
    const P q = l.fit(l.at[i] + l.shift * l.arrow[i]);
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3.5\" fill=\"{}\" stroke=\"#222\" stroke-width=\"1.2\"/>\n", f2(q.x), f2(q.y),
                       scene.nodes[i].fixed ? "#222" : "white");
    if (node_label[i]) text(out, node_label[i]->at, scene.nodes[i].name, node_label[i]->anchor, "class=\"node-label\" font-size=\"11\" " + kHalo);
  }
  if (!l.mode) return;
  for (std::size_t i = 0; i < l.at.size(); ++i) {
    if (norm(l.arrow[i]) == 0) continue;
    const P a = l.fit(l.at[i]), b = l.fit(l.at[i] + l.arrow[i]);
    out += fmt::format("<line data-node=\"{}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#e66101\" stroke-width=\"2\" marker-end=\"url(#arrow-orange)\"/>\n",
                       escape(scene.nodes[i].name), f2(a.x), f2(a.y), f2(b.x), f2(b.y));
  }
}

// Axes (bottom left) and a scale bar of a round length (bottom right), in the model's unit.
void draw_axes_and_scale(std::string& out, const Scene& scene, const MechanismLayout& l) {
  const P origin{30, l.top + l.drawing_height + 2};
  const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < (scene.dimension == 2 ? 2 : 3); ++k) {
    P d = l.view.project(Eigen::Vector3d::Unit(k));
    d = P{d.x, -d.y};
    if (norm(d) < kDrawnZero) continue;
    const P tip = origin + 24.0 * unit(d);
    out += fmt::format("<line class=\"axis\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#444\" stroke-width=\"1.2\" marker-end=\"url(#arrow-black)\"/>\n",
                       f2(origin.x), f2(origin.y), f2(tip.x), f2(tip.y));
    text(out, origin + 33.0 * unit(d) + P{0, 4}, names[k], "middle", "font-size=\"10\" fill=\"#444\"");
  }
  const double bar = round_length(100.0 / l.fit.scale);
  const double pixels = bar * l.fit.scale;
  const P right{l.width - 20, l.top + l.drawing_height + 6};
  out += fmt::format("<path class=\"scale-bar\" d=\"M{} L{} M{} L{} M{} L{}\" stroke=\"#444\" stroke-width=\"1.5\" fill=\"none\"/>\n",
                     pt(right - P{pixels, 0}), pt(right), pt(right - P{pixels, 4}), pt(right - P{pixels, -4}), pt(right + P{0, -4}),
                     pt(right + P{0, 4}));
  text(out, right - P{pixels / 2, 8}, fixed(bar, 6) + " " + length_unit(scene), "middle", "class=\"scale-label\" font-size=\"10\" fill=\"#444\"");
}

// The mode's legend lines from height y; returns the next line's height.
double mode_legend(std::string& out, const Scene& scene, const MechanismLayout& l, double y) {
  out += fmt::format("<line x1=\"20\" y1=\"{0}\" x2=\"50\" y2=\"{0}\" stroke=\"#e66101\" stroke-width=\"2\" marker-end=\"url(#arrow-orange)\"/>\n", f2(y - 4));
  text(out, P{58, y}, fmt::format("{} ({}): nodal velocities, largest drawn at 20% of the model size", l.mode->label, out_of(scene.modes.size(), scene.mode_total)), "start");
  y += 20;
  if (l.displaced_in_full)
    out += fmt::format("<line x1=\"20\" y1=\"{0}\" x2=\"50\" y2=\"{0}\" stroke=\"#cccccc\" stroke-width=\"2\"/>\n", f2(y - 4));
  else
    out += fmt::format("<line x1=\"20\" y1=\"{0}\" x2=\"50\" y2=\"{0}\" stroke=\"#e66101\" stroke-width=\"1\" stroke-dasharray=\"4,3\"/>\n", f2(y - 4));
  text(out, P{58, y},
       std::string(l.displaced_in_full ? "grey: undeformed shape; the displaced shape is drawn at the arrow tips"
                                       : "dashed: displaced shape at the arrow tips, over the undeformed shape") +
           "",
       "start");
  y += 20;
  if (!l.mode->twists.empty()) {
    out += fmt::format("<line x1=\"20\" y1=\"{0}\" x2=\"50\" y2=\"{0}\" stroke=\"#e66101\" stroke-width=\"2\" stroke-dasharray=\"10,3,2,3\"/>\n", f2(y - 4));
    text(out, P{58, y}, "twist axis of each moving body (\u03c9 along it; ring: axis along the line of sight)", "start");
    y += 20;
  }
  return y;
}

// The self-stress's legend lines from height y (wrench axes, or one swatch per colour drawn);
// returns the next line's height.
double stress_legend(std::string& out, const Scene& scene, const MechanismLayout& l, double y) {
  const SceneStress& stress = *l.stress;
  if (!stress.wrenches.empty()) {
    out += fmt::format("<line x1=\"20\" y1=\"{0}\" x2=\"50\" y2=\"{0}\" stroke=\"#7b3294\" stroke-width=\"2\" stroke-dasharray=\"10,3,2,3\" marker-end=\"url(#arrow)\"/>\n", f2(y - 4));
    text(out, P{58, y}, fmt::format("{} ({}): line of action of the wrench each coupling transmits", stress.label, out_of(scene.stresses.size(), scene.stress_total)), "start");
    y += 20;
    text(out, P{58, y}, "arrow: force direction for the primary = +1 (sign as in the text report); width by |F|", "start");
    return y + 20;
  }
  if (!(l.largest_stress > 0)) return y;
  std::vector<std::string> swatches;
  if (l.kinds.count("elongation")) swatches = {"#c0392b", "#2166ac"};
  for (const char* kind : {"bending", "torsion", "rigid"})
    if (l.kinds.count(kind)) swatches.push_back(stress_colour(kind, 1.0));
  double x = 20;
  for (const auto& colour : swatches) {
    out += fmt::format("<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\" stroke=\"{3}\" stroke-width=\"5\"/>\n", f2(y - 4), f2(x),
                       f2(x + 22), colour);
    x += 28;
  }
  text(out, P{x + 4, y},
       fmt::format("{} of {}: each element by its dominant resultant; largest = {}", stress.label, scene.stresses.size(),
                   fixed(l.largest_stress, 4)),
       "start");
  y += 20;
  std::string kinds_text = "sign as in the text report (tension positive): elongation tension red, compression blue";
  if (l.kinds.count("bending")) kinds_text += "; bending purple";
  if (l.kinds.count("torsion")) kinds_text += "; torsion green";
  if (l.kinds.count("rigid")) kinds_text += "; rigid-body constraint brown";
  text(out, P{20, y}, kinds_text, "start", "class=\"stress-kinds\" font-size=\"11\"");
  y += 20;
  text(out, P{20, y}, "width by |resultant| (unit-norm stress state, non-dimensional)", "start", "font-size=\"11\" fill=\"#555\"");
  return y + 20;
}

// The legend under the drawing: mode, self-stress, sheets, and how many labels were left out.
void draw_legend(std::string& out, const Scene& scene, const MechanismLayout& l, bool sheets, int labels_left_out) {
  double y = l.top + l.drawing_height + 30;
  if (l.mode) y = mode_legend(out, scene, l, y);
  if (l.stress) y = stress_legend(out, scene, l, y);
  if (sheets) {
    out += fmt::format("<rect x=\"20\" y=\"{}\" width=\"30\" height=\"9\" fill=\"#efe3c8\" stroke=\"#b59b6a\" stroke-width=\"0.8\"/>\n", f2(y - 9));
    text(out, P{58, y}, fmt::format("sheets (beams the model makes leaf springs), drawn {}% of their length wide", fixed(100 * kSheetWidth, 0)), "start");
    y += 20;
  }
  if (!l.mode && !l.stress) {
    text(out, P{20, y}, scene.modes.empty() && scene.stresses.empty() ? "no kinematic modes and no self-stress" : "configuration only", "start");
    y += 20;
  }
  if (labels_left_out > 0) {
    // One more legend line: the canvas grows by it (the header is written for the final height).
    text(out, P{20, y},
         fmt::format("{} label(s) left out where they would overlap (all names: text report; HTML report: labels)", labels_left_out),
         "start", "class=\"labels-left-out\" font-size=\"11\" fill=\"#555\"");
    out.replace(0, header(l.width, l.height).size(), header(l.width, l.height + 20));
  }
}

}  // namespace

std::string mechanism_svg(const Scene& scene, const MechanismDrawing& drawing) {
  const MechanismLayout l = mechanism_layout(scene, drawing);
  std::string out = header(l.width, l.height);
  text(out, P{l.width / 2, 24}, scene.name, "middle", "font-size=\"14\" font-weight=\"bold\"");
  for (std::size_t i = 0; i < l.verdict.size(); ++i)
    text(out, P{l.width / 2, 42 + 16.0 * static_cast<double>(i)}, l.verdict[i], "middle", "class=\"verdict\" font-size=\"12\" fill=\"#333\"");
  if (scene.large) {
    draw_large_model(out, scene, l);
    out += "</svg>\n";
    return out;
  }
  const bool sheets = draw_elements(out, scene, l);
  // Node names are placed first, then element, coupling and screw labels.
  LabelSpace labels(2, l.top, l.width - 2, l.top + l.drawing_height - 4);
  const auto node_label = place_node_labels(labels, scene, l);
  draw_element_labels(out, labels, scene, l);
  draw_glyphs(out, labels, scene, l);
  if (l.mode) draw_screw_axes(out, labels, l, l.mode->twists, {"#e66101", "arrow-orange", "twist", true});
  if (l.stress) draw_screw_axes(out, labels, l, l.stress->wrenches, {"#7b3294", "arrow", "wrench", false});
  draw_nodes_and_arrows(out, scene, l, node_label);
  draw_axes_and_scale(out, scene, l);
  draw_legend(out, scene, l, sheets, labels.left_out());
  out += "</svg>\n";
  return out;
}

}  // namespace kinestat::report
