// SPDX-License-Identifier: BSD-3-Clause
// The structural diagram of seed 004 as SVG (declared in structure_report.hpp): one circle per
// structural group labelled (N_m, n_c) and with its bodies, arrows from the group that gives
// DOF to the group that receives it. An arrow that would pass under a circle it does not end
// at is bent around it, so that a frame -> SG-II arrow is never read as frame -> SG-I -> SG-II.

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "kinestat/report/markup_escape.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/structure/structural_diagram.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::report {

namespace {

struct Point {
  double x = 0, y = 0;
};

/// Point of the quadratic Bézier a -> b with control c at parameter t.
Point bezier(Point a, Point c, Point b, double t) {
  const double u = 1 - t;
  return {u * u * a.x + 2 * u * t * c.x + t * t * b.x, u * u * a.y + 2 * u * t * c.y + t * t * b.y};
}

/// Smallest distance from `p` to the curve a -> b (control c), sampled finely.
double distance_to_curve(Point p, Point a, Point c, Point b) {
  double best = 1e300;
  constexpr int kSamples = 64;
  for (int i = 0; i <= kSamples; ++i) {
    const Point q = bezier(a, c, b, static_cast<double>(i) / kSamples);
    best = std::min(best, std::hypot(q.x - p.x, q.y - p.y));
  }
  return best;
}

// Layout of the diagram, in px: circle radius, spacing of slots and layers, margin, and the
// clearance between an arrow and a circle it passes (beyond the radius).
constexpr double kGroupRadius = 28, kSlotSpacing = 150, kLayerSpacing = 120, kDiagramMargin = 70, kArrowClearance = 8;

// Bodies in no group, said under the diagram (a diagram of the frame alone would otherwise
// look like a mechanism with nothing to assemble): over-constrained, without an input, blocked.
std::vector<std::string> left_out_sentences(const structure::StructureModel& model, const structure::StructureResult& d) {
  std::vector<std::string> left_out;
  const auto& u = d.undecomposed;
  const auto names = [&model](const std::vector<int>& bodies) {
    std::string list;
    for (int body : bodies) list += (list.empty() ? "" : ", ") + structure::body_label(model, body);
    return list;
  };
  if (!u.over_constrained.empty())
    left_out.push_back(fmt::format("in no group, over-constrained ({} constraint(s) or input(s) too many): {}", u.redundant,
                                   names(u.over_constrained)));
  if (!u.under_constrained.empty())
    left_out.push_back(fmt::format("in no group, under-constrained ({} input(s) missing): {}", u.missing, names(u.under_constrained)));
  if (!u.blocked.empty()) left_out.push_back("in no group, waiting for the bodies above: " + names(u.blocked));
  return left_out;
}

// The sentences wrapped at spaces into lines of at most `wrap_chars` characters.
std::vector<std::string> wrapped_sentences(const std::vector<std::string>& sentences, std::size_t wrap_chars) {
  std::vector<std::string> lines;
  for (const auto& note : sentences) {
    std::string line;
    std::size_t start = 0;
    while (start < note.size()) {
      std::size_t end = note.find(' ', start);
      if (end == std::string::npos) end = note.size();
      const std::string word = note.substr(start, end - start);
      if (!line.empty() && line.size() + 1 + word.size() > wrap_chars) {
        lines.push_back(line);
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
      start = end + 1;
    }
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

// The arrow a -> b between two circles: the straight line if it clears every other circle
// (centres `at`, indices `from` and `to` excepted), else the least bend (alternating sides)
// that does; it starts and ends on the circles, toward the control point.
std::string diagram_arrow(const structure::DiagramArrow& arrow, const std::vector<Point>& at, std::size_t from, std::size_t to) {
  const Point a = at[from], b = at[to];
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len <= 2 * kGroupRadius) return {};
  const Point normal{-(b.y - a.y) / len, (b.x - a.x) / len};
  Point control{(a.x + b.x) / 2, (a.y + b.y) / 2};
  for (int attempt = 0; attempt <= 24; ++attempt) {
    const double offset = (attempt + 1) / 2 * 30.0 * (attempt % 2 == 1 ? 1.0 : -1.0);
    const Point c{(a.x + b.x) / 2 + offset * normal.x, (a.y + b.y) / 2 + offset * normal.y};
    bool clear = true;
    for (std::size_t k = 0; k < at.size() && clear; ++k)
      if (k != from && k != to && distance_to_curve(at[k], a, c, b) < kGroupRadius + kArrowClearance) clear = false;
    if (clear) {
      control = c;
      break;
    }
  }
  const auto toward = [&](Point centre, Point target) {
    const double l = std::max(std::hypot(target.x - centre.x, target.y - centre.y), kDrawnZero);
    return Point{centre.x + kGroupRadius * (target.x - centre.x) / l, centre.y + kGroupRadius * (target.y - centre.y) / l};
  };
  const Point start = toward(a, control), end = toward(b, control);
  return fmt::format(
      "  <path class=\"arrow\" data-from=\"{}\" data-to=\"{}\" d=\"M{:.1f},{:.1f} Q{:.1f},{:.1f} {:.1f},{:.1f}\" fill=\"none\" "
      "stroke=\"#333\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>\n",
      arrow.from, arrow.to, start.x, start.y, control.x, control.y, end.x, end.y);
}

// A group's circle at `centre`, its label (N_m, n_c), its name and its bodies under it (the
// frame is named beside its own).
std::string diagram_group(const structure::StructureModel& model, const structure::StructureResult& d, const structure::DiagramNode& n,
                          Point centre) {
  const auto [x, y] = centre;
  const std::string label = n.group == 0 ? "0" : fmt::format("({}, {})", n.Nm, n.nc);
  std::string out = fmt::format(
      "  <circle data-group=\"{}\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.0f}\" fill=\"{}\" stroke=\"#333\" stroke-width=\"1.5\"/>\n", n.group, x,
      y, kGroupRadius, n.group == 0 ? "#e8e8e8" : "#ffffff");
  out += fmt::format("  <text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n", x, y + 5, label);
  out += fmt::format("  <text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"#555\">{}</text>\n", x + kGroupRadius + 4,
                     y - kGroupRadius + 6, n.group == 0 ? "frame" : group_name(n.group));
  std::string bodies;
  for (const auto& group : d.groups)
    if (group.number == n.group)
      for (int body : group.bodies) bodies += (bodies.empty() ? "" : ", ") + structure::body_label(model, body);
  if (n.group != 0)
    out += fmt::format("  <text class=\"bodies\" x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"11\" fill=\"#1f4e79\" "
                       "paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">{}</text>\n",
                       x, y + kGroupRadius + 15, markup_escape(bodies));
  return out;
}

// The SVG header: canvas, arrow marker, white background and the title.
std::string diagram_header(double width, double height, const std::string& title) {
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
      "font-family=\"Helvetica, Arial, sans-serif\">\n",
      width, height, width, height);
  out += "  <defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"8\" markerHeight=\"8\" "
         "orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#333\"/></marker></defs>\n";
  out += "  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += fmt::format("  <text x=\"{:.1f}\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n", width / 2, markup_escape(title));
  return out;
}

}  // namespace

std::string structure_svg(const structure::StructureModel& model, const structure::StructureResult& d) {
  const auto diagram = structure::structural_diagram(d);
  std::vector<int> per_layer(static_cast<std::size_t>(diagram.layers), 0);
  for (const auto& n : diagram.nodes) ++per_layer[static_cast<std::size_t>(n.layer)];
  const std::string title = model.name.empty() ? "Structural diagram" : model.name;
  const double layers_width = kDiagramMargin * 2 + kSlotSpacing * std::max(1, diagram.widest_layer - 1) + 2 * kGroupRadius;
  // Wide enough for the title too (about 7.5 px per character at 15 px).
  const double width = std::max({layers_width, 40 + 7.5 * static_cast<double>(title.size()), d.undecomposed.empty() ? 0.0 : 400.0});
  // About 6.2 px a character at 11 px: wrap the notes to the diagram's width, at least 60 characters.
  const double note_width = std::max(layers_width, 400.0);
  const auto notes = wrapped_sentences(left_out_sentences(model, d), static_cast<std::size_t>((note_width - 20) / 6.2));
  const double notes_height = notes.empty() ? 0.0 : 10.0 + 15.0 * static_cast<double>(notes.size());
  const double height = kDiagramMargin * 2 + kLayerSpacing * (diagram.layers - 1) + 2 * kGroupRadius + 30 + notes_height;
  std::vector<Point> at(diagram.nodes.size());
  std::vector<int> index_of(d.groups.size() + 1, 0);
  for (std::size_t i = 0; i < diagram.nodes.size(); ++i) {
    const auto& n = diagram.nodes[i];
    // Each layer is centred; slots follow the order of formation.
    const double row = kSlotSpacing * (per_layer[static_cast<std::size_t>(n.layer)] - 1);
    at[i] = {width / 2 - row / 2 + kSlotSpacing * n.slot, kDiagramMargin + 20 + kGroupRadius + kLayerSpacing * n.layer};
    index_of[static_cast<std::size_t>(n.group)] = static_cast<int>(i);
  }
  std::string out = diagram_header(width, height, title);
  for (const auto& arrow : diagram.arrows)
    out += diagram_arrow(arrow, at, static_cast<std::size_t>(index_of[static_cast<std::size_t>(arrow.from)]),
                         static_cast<std::size_t>(index_of[static_cast<std::size_t>(arrow.to)]));
  for (std::size_t i = 0; i < diagram.nodes.size(); ++i) out += diagram_group(model, d, diagram.nodes[i], at[i]);
  const double notes_top = height - notes_height + 12;
  for (std::size_t i = 0; i < notes.size(); ++i)
    out += fmt::format("  <text class=\"left-out\" x=\"20\" y=\"{:.1f}\" font-size=\"11\" fill=\"#8b1a1a\">{}</text>\n",
                       notes_top + 15.0 * static_cast<double>(i), markup_escape(notes[i]));
  out += "</svg>\n";
  return out;
}

}  // namespace kinestat::report
