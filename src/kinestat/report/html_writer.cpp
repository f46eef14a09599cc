// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/html_writer.hpp"

#include "kinestat/report/json_text.hpp"
#include "kinestat/report/markup_escape.hpp"
#include "kinestat/report/verdict_report.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "kinestat/report/viewer_assets.hpp"

namespace kinestat::report {

namespace {

/// Rounds to `digits` decimals so that the JSON text is deterministic and short.
double scene_rounded(double value, int digits = 6) {
  if (!std::isfinite(value)) return 0.0;
  const double scale = std::pow(10.0, digits);
  const double r = std::round(value * scale) / scale;
  return r == 0.0 ? 0.0 : r;
}

nlohmann::ordered_json vector_json(const Eigen::Vector3d& v) { return {scene_rounded(v.x()), scene_rounded(v.y()), scene_rounded(v.z())}; }

nlohmann::ordered_json screws_json(const std::vector<std::vector<double>>& screws) {
  auto out = nlohmann::ordered_json::array();
  for (const auto& s : screws) {
    auto row = nlohmann::ordered_json::array();
    for (double v : s) row.push_back(scene_rounded(v));
    out.push_back(row);
  }
  return out;
}

nlohmann::ordered_json screw_json(const SceneScrew& s) {
  return {{"name", s.name},       {"anchor", vector_json(s.anchor)}, {"point", vector_json(s.point)},
          {"direction", vector_json(s.direction)}, {"magnitude", scene_rounded(s.magnitude)}, {"pitch", scene_rounded(s.pitch)},
          {"pure", s.pure}};
}

// The verdict as the JSON report writes it (report::verdict_json), plus the participant lists
// the viewer's side panel reads, rounded to four digits.
nlohmann::ordered_json viewer_verdict_json(const design::Verdict& v) {
  nlohmann::ordered_json j = verdict_json(v);
  const auto participants = [](const std::vector<design::Participant>& list) {
    auto out = nlohmann::ordered_json::array();
    for (const auto& p : list) out.push_back({{"kind", p.kind}, {"name", p.name}, {"participation", scene_rounded(p.participation, 4)}});
    return out;
  };
  j["motion_participants"] = participants(v.motion_participants);
  j["constraint_participants"] = participants(v.constraint_participants);
  return j;
}

/// Text that may sit inside <script>: no "</" and no HTML comment openers.
std::string script_safe(std::string text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '!')) {
      out += "\\u003c";
    } else {
      out += text[i];
    }
  }
  return out;
}

std::string html_escape(const std::string& text) { return markup_escape(text); }

// `value` to `digits` significant digits (deterministic: through fixed text).
double significant_digits(double value, int digits) {
  if (!std::isfinite(value) || value == 0.0) return 0.0;
  return std::stod(fmt::format("{:.{}g}", value, digits));
}

// Output precision of traced positions (not a tolerance: how many digits the scene keeps).
// Node offsets are whole multiples of a quantum of at most this fraction of the shortest bar at
// a moving node, so rounding changes a bar's length by at most √3 times it (two ends, half a
// quantum per coordinate), far inside the 1e-6 of issue 13.
constexpr double kTraceQuantum = 1e-8;

// A traced path, compactly: only the nodes that move, as integer offsets (in `quantum` length
// units) from their positions in the model's configuration, per point of the path.
nlohmann::ordered_json trace_json(const Scene& scene, const SceneTrace& trace) {
  const std::size_t n = scene.nodes.size();
  std::vector<bool> moves(n, false);
  for (const auto& points : trace.positions)
    for (std::size_t i = 0; i < n && i < points.size(); ++i) moves[i] = moves[i] || points[i] != scene.nodes[i].position;
  double shortest = 0.0;
  for (const auto& e : scene.elements) {
    const auto a = static_cast<std::size_t>(e.a), b = static_cast<std::size_t>(e.b);
    if (a >= n || b >= n || !(moves[a] || moves[b])) continue;
    const double l = (scene.nodes[a].position - scene.nodes[b].position).norm();
    if (l > 0.0 && (shortest == 0.0 || l < shortest)) shortest = l;
  }
  if (shortest == 0.0) shortest = 1.0;
  const double quantum = std::pow(10.0, std::floor(std::log10(shortest * kTraceQuantum)));
  // Offsets of every point; a node moves when some offset is not zero after rounding.
  std::vector<std::vector<std::array<long long, 3>>> offsets(trace.positions.size(), std::vector<std::array<long long, 3>>(n));
  std::vector<bool> kept(n, false);
  for (std::size_t p = 0; p < trace.positions.size(); ++p)
    for (std::size_t i = 0; i < n && i < trace.positions[p].size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const long long q = std::llround((trace.positions[p][i](c) - scene.nodes[i].position(c)) / quantum);
        offsets[p][i][static_cast<std::size_t>(c)] = q;
        kept[i] = kept[i] || q != 0;
      }
  auto nodes = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < n; ++i)
    if (kept[i]) nodes.push_back(i);
  auto points = nlohmann::ordered_json::array();
  for (const auto& point : offsets) {
    auto row = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < n; ++i)
      if (kept[i])
        for (long long q : point[i]) row.push_back(q);
    points.push_back(std::move(row));
  }
  auto arc = nlohmann::ordered_json::array();
  for (double s : trace.arc) arc.push_back(significant_digits(s, 6));
  return {{"max_residual", significant_digits(trace.max_residual, 3)}, {"note", trace.note}, {"start", trace.start}, {"arc", arc},
          {"nodes", nodes}, {"quantum", quantum}, {"offsets", points}};
}

}  // namespace

namespace {

// Sections of scene_json, in the order of their keys.

using SceneJson = nlohmann::ordered_json;

// Node positions (x, y, z flat), fixed flags and names (none for a large scene).
SceneJson scene_nodes_json(const Scene& scene) {
  auto position = SceneJson::array();
  auto fixed_nodes = SceneJson::array();
  auto names = SceneJson::array();
  for (const auto& node : scene.nodes) {
    for (int k = 0; k < 3; ++k) position.push_back(scene_rounded(node.position(k)));
    fixed_nodes.push_back(node.fixed ? 1 : 0);
    if (!scene.large) names.push_back(node.name);
  }
  return {{"position", position}, {"fixed", fixed_nodes}, {"name", names}};
}

// Element node pairs (flat), and for a scene that is not large their names, types, labels and sheets.
SceneJson scene_elements_json(const Scene& scene) {
  auto pairs = SceneJson::array();
  auto element_names = SceneJson::array();
  for (const auto& element : scene.elements) {
    pairs.push_back(element.a);
    pairs.push_back(element.b);
    if (!scene.large) element_names.push_back(element.name);
  }
  auto element_types = SceneJson::array();
  auto element_labels = SceneJson::array();
  auto sheets = SceneJson::array();
  if (!scene.large)
    for (std::size_t e = 0; e < scene.elements.size(); ++e) {
      const auto& element = scene.elements[e];
      element_types.push_back(element.type);
      element_labels.push_back(element.label ? 1 : 0);
      if (element.sheet_across) sheets.push_back({{"element", e}, {"across", vector_json(*element.sheet_across)}});
    }
  return {{"count", scene.elements.size()}, {"pairs", pairs}, {"name", element_names}, {"type", element_types},
          {"label", element_labels}, {"sheets", sheets}, {"sheet_width", kSheetWidth}};
}

SceneJson scene_supports_json(const Scene& scene) {
  auto supports = SceneJson::array();
  if (scene.large) return supports;
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    const auto& node = scene.nodes[i];
    if (node.support.empty()) continue;
    auto free = SceneJson::array();
    for (const auto& d : node.free_directions) free.push_back(vector_json(d));
    supports.push_back({{"node", i}, {"kind", node.support}, {"free", free}});
  }
  return supports;
}

SceneJson scene_glyph_json(const SceneGlyph& g) {
  SceneJson glyph;
  glyph["name"] = g.name;
  glyph["type"] = g.type;
  glyph["from"] = g.from;
  glyph["to"] = g.to;
  glyph["f"] = g.f;
  glyph["c"] = g.c;
  glyph["point"] = vector_json(g.point);
  if (g.axis) glyph["axis"] = vector_json(*g.axis);
  if (g.axis2) glyph["axis2"] = vector_json(*g.axis2);
  if (g.normal) glyph["normal"] = vector_json(*g.normal);
  glyph["motions"] = screws_json(g.motions);
  glyph["actions"] = screws_json(g.actions);
  return glyph;
}

SceneJson scene_mode_json(const Scene& scene, const SceneMode& mode) {
  auto velocity = SceneJson::array();
  for (const auto& v : mode.velocity)
    for (int k = 0; k < 3; ++k) velocity.push_back(scene_rounded(v(k)));
  auto twists = SceneJson::array();
  for (const auto& t : mode.twists) twists.push_back(screw_json(t));
  SceneJson entry = {{"label", mode.label}, {"velocity", velocity}, {"moving", mode.moving}, {"twists", twists}};
  if (mode.trace) entry["trace"] = trace_json(scene, *mode.trace);
  if (!mode.first_order_reason.empty()) entry["first_order"] = mode.first_order_reason;
  if (!mode.kind.empty()) entry["kind"] = mode.kind;
  return entry;
}

SceneJson scene_stress_json(const SceneStress& stress) {
  auto value = SceneJson::array();
  for (double v : stress.value) value.push_back(scene_rounded(v));
  auto resultants = SceneJson::array();
  for (const auto& r : stress.resultants) resultants.push_back({r.element, r.deformation, scene_rounded(r.value)});
  auto wrenches = SceneJson::array();
  for (const auto& w : stress.wrenches) wrenches.push_back(screw_json(w));
  SceneJson entry = {{"label", stress.label}, {"value", value}, {"kind", stress.kind}, {"resultants", resultants}, {"wrenches", wrenches}};
  if (!stress.unit.empty()) entry["unit"] = stress.unit;  // a misfit stress (issue 38), not a unit-norm state
  return entry;
}

}  // namespace

bool html_report_built_in() { return viewer_assets::built_in(); }

nlohmann::ordered_json scene_json(const Scene& scene) {
  nlohmann::ordered_json j;
  j["kind"] = io::kind_name(scene.kind);
  j["name"] = scene.name;
  j["dimension"] = scene.dimension;
  j["screw_components"] = scene.screw_dimension == 3 ? std::vector<int>{2, 3, 4} : std::vector<int>{0, 1, 2, 3, 4, 5};
  j["large"] = scene.large;
  if (scene.sparse) {
    // A sparse network's modes name couplings, and are the first of mode_total.
    j["sparse"] = true;
    j["mode_total"] = scene.mode_total;
    j["stress_total"] = scene.stress_total;
  }
  j["summary"] = nlohmann::ordered_json::array();
  for (const auto& fact : scene.summary) j["summary"].push_back({fact.key, fact.value});
  j["bodies"] = scene.bodies;
  j["group_of"] = scene.group_of;
  j["ground"] = scene.ground;
  j["nodes"] = scene_nodes_json(scene);
  j["elements"] = scene_elements_json(scene);
  j["units"] = length_unit(scene);
  j["verdict"] = scene.verdict ? viewer_verdict_json(*scene.verdict) : nlohmann::ordered_json(nullptr);
  j["supports"] = scene_supports_json(scene);
  j["glyphs"] = nlohmann::ordered_json::array();
  j["modes"] = nlohmann::ordered_json::array();
  j["stresses"] = nlohmann::ordered_json::array();
  j["pairs"] = nlohmann::ordered_json::array();
  if (scene.large) return j;
  for (const auto& g : scene.glyphs) j["glyphs"].push_back(scene_glyph_json(g));
  for (const auto& mode : scene.modes) j["modes"].push_back(scene_mode_json(scene, mode));
  for (const auto& stress : scene.stresses) j["stresses"].push_back(scene_stress_json(stress));
  for (const auto& pair : scene.pairs)
    j["pairs"].push_back({{"i", pair.body_i}, {"j", pair.body_j}, {"fij", pair.fij}, {"motions", screws_json(pair.motions)}});
  return j;
}

std::string html_report(const Scene& scene, const std::string& figure, const std::string& figure_title) {
  std::string html;
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"generator\" content=\"kinestat report\">\n";
  html += "<title>" + html_escape(scene.name.empty() ? std::string("kinestat report") : scene.name) + "</title>\n";
  html += "<style>\n" + viewer_assets::viewer_css() + "</style>\n</head>\n<body>\n";
  html += R"(<div id="side">
<h1 id="title"></h1>
<div id="verdict" class="verdict"></div>
<h2>Modes and self-stress</h2>
<select id="mode" aria-label="view"></select>
<label for="amplitude">Amplitude</label>
<input id="amplitude" type="range" min="0" max="1" step="0.01" value="0.5">
<div id="motion" class="note"></div>
<label id="firstOrderBox" style="display:none"><input id="firstorder" type="checkbox"> first order instead: nodes along their velocities (bars stretch)</label>
<label><input id="labels" type="checkbox"> labels: nodes, elements, couplings</label>
<div id="moving"></div>
<div id="resultants"></div>
<div id="notes"></div>
<h2>Summary</h2>
<table id="summary"></table>
<div id="network" style="display:none">
<h2>Couplings</h2>
<label><input id="screws" type="checkbox"> unit motion screw axes of every coupling (orange)</label>
<h2>Motion system of a pair</h2>
<select id="pair" aria-label="pair of bodies"></select>
<p id="pairinfo" class="note"></p>
</div>
<p class="note">Made by kinestat. Drag to rotate, wheel to zoom.</p>
)";
  if (!figure.empty()) {
    // Inline SVG: drop the XML declaration, keep the drawing.
    const auto start = figure.find("<svg");
    html += "<h2>" + html_escape(figure_title) + "</h2>\n<div class=\"figure\">" +
            (start == std::string::npos ? std::string() : figure.substr(start)) + "</div>\n";
  }
  html += R"(</div>
<div id="main"><canvas id="view"></canvas><div id="labelLayer"></div><div id="legend"></div><div id="scale"></div><div id="message"></div></div>
)";
  html += "<script>\n" + script_safe(viewer_assets::three_js()) + "\n</script>\n";
  html += "<script>\nwindow.KINESTAT_SCENE = " + script_safe(json_text(scene_json(scene), -1)) + ";\n</script>\n";
  html += "<script>\n" + script_safe(viewer_assets::viewer_js()) + "\n</script>\n";
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace kinestat::report
