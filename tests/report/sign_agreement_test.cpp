// SPDX-License-Identifier: BSD-3-Clause
// One sign for every mode and self-stress (issue 10, item 3): the text report, the JSON
// report, the SVG drawing and the HTML scene of a framework show the same sign for every
// resultant and every nodal velocity, on every shipped framework example, on a Warren truss
// with an extra diagonal (the case where the scene used to re-decide the sign and drew the
// tension bar blue) and on random planar frameworks. For every network example, the wrench
// each coupling transmits in a self-stress (primary = +1), evaluated from the text and the
// JSON reports' action magnitudes and unit actions, is the one the HTML scene carries and the
// SVG draws. Each output is read back from its text.

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/report/svg_writer.hpp"

namespace {

namespace report = kinestat::report;
namespace framework = kinestat::framework;

// Values smaller than this are not compared: their printed sign may be rounding.
constexpr double kShown = 1e-4;

int sign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

/// "label value" lines (indented) of the text report's section whose heading starts with
/// `head` and mentions `about`: label -> value.
std::map<std::string, double> text_section(const std::string& text, const std::string& head, const std::string& about) {
  std::map<std::string, double> out;
  std::istringstream in(text);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind(head, 0) == 0 && line.find(about) != std::string::npos) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.rfind("  ", 0) != 0) break;
    std::istringstream words(line);
    std::string label;
    double value = 0;
    if (words >> label >> value) out[label] = value;
  }
  return out;
}

/// "element.deformation" -> value of stress state `k` (1-based) in the text report.
std::map<std::string, double> text_resultants(const std::string& text, int k) {
  return text_section(text, "stress state " + std::to_string(k) + " ", "resultants");
}

/// "node.slot" -> velocity of mode `k` (1-based) in the text report.
std::map<std::string, double> text_velocities(const std::string& text, int k) {
  return text_section(text, "mode " + std::to_string(k) + " ", "velocities");
}

struct SvgLine {
  std::string kind, stroke;
  double value = 0;
};

/// Stressed lines of a mechanism SVG: element name -> (kind, value, stroke colour).
std::map<std::string, SvgLine> svg_stressed(const std::string& svg) {
  std::map<std::string, SvgLine> out;
  const std::regex line(R"re(<line [^>]*stroke="(#[0-9a-f]+)"[^>]*data-element="([^"]*)" data-kind="([a-z]+)" data-value="([-0-9.e]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it)
    out[(*it)[2]] = {(*it)[3], (*it)[1], std::stod((*it)[4])};
  return out;
}

/// Mode arrows of a mechanism SVG: node name -> screen vector (x right, y down).
std::map<std::string, std::pair<double, double>> svg_arrows(const std::string& svg) {
  std::map<std::string, std::pair<double, double>> out;
  const std::regex line(R"re(<line data-node="([^"]*)" x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = {std::stod((*it)[4]) - std::stod((*it)[2]), std::stod((*it)[5]) - std::stod((*it)[3])};
  return out;
}

/// Compares the four outputs of one framework; returns the number of signs compared.
int compare_outputs(const framework::FrameworkModel& model, const std::string& what) {
  const auto analysis = framework::analyse_framework(model);
  const std::string text = report::framework_report_text(model, analysis);
  const auto json = report::framework_report_json(model, analysis);
  const auto scene = report::framework_scene(model, analysis);
  const auto html = report::scene_json(scene);
  int compared = 0;
  for (std::size_t k = 0; k < analysis.stresses.size(); ++k) {
    const auto from_text = text_resultants(text, static_cast<int>(k) + 1);
    const std::string svg = report::mechanism_svg(scene, {0, static_cast<int>(k) + 1});
    const auto drawn = svg_stressed(svg);
    // Per element: the dominant resultant according to the JSON report.
    std::map<std::string, std::pair<std::string, double>> dominant;
    std::map<std::string, double> runner_up;
    for (const auto& entry : json["stresses"][k]["resultants"]) {
      const std::string element = entry["element"], deformation = entry["deformation"];
      const double value = entry["value"];
      const std::string label = element + "." + deformation;
      // Text and JSON agree on every resultant shown.
      if (std::abs(value) > kShown) {
        if (!(from_text.count(label))) {
          ADD_FAILURE() << what << ": " << label << " missing from the text report";
          continue;
        }
        EXPECT_EQ(sign(from_text.at(label)), sign(value)) << what << ": text and JSON signs differ for " << label;
        ++compared;
      }
      auto& d = dominant[element];
      if (std::abs(value) > std::abs(d.second)) {
        runner_up[element] = std::abs(d.second);
        d = {deformation, value};
      } else {
        runner_up[element] = std::max(runner_up[element], std::abs(value));
      }
    }
    // HTML: the scene's per-element value, read back from the embedded JSON.
    std::map<std::string, double> in_html;
    for (std::size_t e = 0; e < html["elements"]["name"].size(); ++e)
      in_html[html["elements"]["name"][e]] = html["stresses"][k]["value"][e];
    for (const auto& element : model.elements) {
      if (element.type == framework::ElementType::rigid_body) continue;
      const auto d = dominant[element.name];
      // Skip near-ties of two resultants of one element: which one is "dominant" is rounding.
      if (std::abs(d.second) <= kShown || std::abs(d.second) - runner_up[element.name] < 1e-6) continue;
      if (!(drawn.count(element.name))) {
        ADD_FAILURE() << what << ": element " << element.name << " not coloured in the SVG";
        continue;
      }
      const auto& line = drawn.at(element.name);
      EXPECT_EQ(sign(line.value), sign(d.second)) << what << ": SVG sign differs for " << element.name;
      EXPECT_EQ(sign(in_html.at(element.name)), sign(d.second)) << what << ": HTML sign differs for " << element.name;
      if (d.first == "elongation") {
        EXPECT_EQ(line.kind, "elongation") << what << ": " << element.name;
        EXPECT_EQ(line.stroke, d.second > 0 ? "#c0392b" : "#2166ac")
            << what << ": " << element.name << " is a " << (d.second > 0 ? "tension" : "compression") << " but drawn " << line.stroke;
      }
      compared += 3;
    }
  }
  for (std::size_t k = 0; k < analysis.modes.size(); ++k) {
    const auto from_text = text_velocities(text, static_cast<int>(k) + 1);
    const auto& velocities = json["modes"][k]["velocities"];
    const auto& html_velocity = html["modes"][k]["velocity"];
    const std::string svg = report::mechanism_svg(scene, {static_cast<int>(k) + 1, 0});
    const auto arrows = svg_arrows(svg);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      const auto& node = model.nodes[i];
      if (!velocities.contains(node.name)) continue;
      double largest = 0;
      for (const char* slot : {"x", "y", "z"})
        if (velocities[node.name].contains(slot)) largest = std::max(largest, std::abs(double(velocities[node.name][slot])));
      for (int c = 0; c < 3; ++c) {
        const char* slot = framework::kSlotNames[static_cast<std::size_t>(c)];
        if (!velocities[node.name].contains(slot)) continue;
        const double v = velocities[node.name][slot];
        if (std::abs(v) <= kShown) continue;
        const std::string label = node.name + "." + slot;
        if (!(from_text.count(label))) {
          ADD_FAILURE() << what << ": " << label << " missing from the text report";
          continue;
        }
        EXPECT_EQ(sign(from_text.at(label)), sign(v)) << what << ": text and JSON differ for " << label;
        EXPECT_EQ(sign(double(html_velocity[3 * i + static_cast<std::size_t>(c)])), sign(v)) << what << ": HTML differs for " << label;
        compared += 2;
        // Planar drawings: the arrow points the same way (screen y is down). Only components
        // that are a visible part of the arrow are compared.
        if (model.dimension == 2 && c < 2 && std::abs(v) > 0.2 * largest && arrows.count(node.name)) {
          const auto [dx, dy] = arrows.at(node.name);
          EXPECT_EQ(sign(c == 0 ? dx : -dy), sign(v)) << what << ": SVG arrow of " << label;
          ++compared;
        }
      }
    }
  }
  return compared;
}

/// Value of a linear form as the reports write it ("-Ub", "Ub - We", "2*Ua + 1/2*Ub") when the
/// primary `one` is 1 and every other primary 0.
double evaluate_form(const std::string& form, const std::string& one) {
  std::string text = " + " + form;
  double total = 0;
  std::size_t at = 0;
  while (at < text.size()) {
    const auto plus = text.find(" + ", at), minus = text.find(" - ", at);
    const auto start = std::min(plus, minus);
    if (start == std::string::npos) break;
    double sign_of_term = start == minus ? -1.0 : 1.0;
    const auto next = std::min(text.find(" + ", start + 3), text.find(" - ", start + 3));
    std::string term = text.substr(start + 3, next == std::string::npos ? std::string::npos : next - start - 3);
    at = next == std::string::npos ? text.size() : next;
    if (!term.empty() && term[0] == '-') sign_of_term = -sign_of_term, term = term.substr(1);
    double coefficient = 1.0;
    if (const auto star = term.find('*'); star != std::string::npos) {
      const std::string number = term.substr(0, star);
      const auto slash = number.find('/');
      coefficient = slash == std::string::npos ? std::stod(number) : std::stod(number.substr(0, slash)) / std::stod(number.substr(slash + 1));
      term = term.substr(star + 1);
    }
    if (term == one) total += sign_of_term * coefficient;
  }
  return total;
}

/// "name = form" lines of the text report's action magnitudes.
std::map<std::string, std::string> text_action_forms(const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("Action magnitudes", 0) == 0) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.rfind("  ", 0) != 0) break;
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;
    std::string name = line.substr(2, eq - 2);
    name.erase(name.find_last_not_of(' ') + 1);
    out[name] = line.substr(eq + 3);
  }
  return out;
}

/// Compares the wrenches of every self-stress of one network; returns the number compared.
int compare_network_outputs(const std::string& path) {
  const auto loaded = kinestat::io::read_network_model(kinestat::io::YamlFile::load(path));
  const auto result = kinestat::network::analyse_network(loaded.model);
  const std::string text = report::network_report_text(loaded.model, result);
  const auto json = report::network_report_json(loaded.model, result);
  const auto scene = report::network_scene(loaded.model, result);
  const auto html = report::scene_json(scene);
  const auto from_text = text_action_forms(text);
  const auto& components = html["screw_components"];
  int compared = 0;
  for (std::size_t k = 0; k < json["primary_action"].size(); ++k) {
    const std::string primary = json["primary_action"][k];
    // The wrench of every coupling from the JSON report: magnitudes times unit actions.
    std::map<std::string, std::array<double, 6>> wrench;
    for (const auto& unit : json["unit_actions"]) {
      const std::string name = unit["name"], coupling = unit["coupling"];
      const std::string form = json["actions"][name];
      if (!(from_text.count(name))) {
        ADD_FAILURE() << path << ": " << name << " missing from the text report";
        continue;
      }
      const double value = evaluate_form(form, primary);
      EXPECT_NEAR(evaluate_form(from_text.at(name), primary), value, 1e-9) << path << ": text and JSON differ for " << name;
      auto& w = wrench[coupling];
      for (std::size_t i = 0; i < unit["unit_screw"].size(); ++i) w[components[i].get<std::size_t>()] += value * double(unit["unit_screw"][i]);
    }
    // The same wrench from the HTML scene: force along the axis through `point` with `pitch`.
    std::map<std::string, std::array<double, 6>> drawn;
    std::map<std::string, double> lever;
    for (const auto& w : html["stresses"][k]["wrenches"]) {
      Eigen::Vector3d d(w["direction"][0], w["direction"][1], w["direction"][2]), p(w["point"][0], w["point"][1], w["point"][2]);
      const double magnitude = w["magnitude"], pitch = w["pitch"];
      Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = magnitude * d;
      if (!w["pure"].get<bool>()) force = magnitude * d, moment = p.cross(force) + pitch * force;
      drawn[w["name"]] = {moment.x(), moment.y(), moment.z(), force.x(), force.y(), force.z()};
      // The scene's numbers are rounded to 6 decimals; the moment rebuilt from the axis point
      // carries that rounding times the lever arm.
      lever[w["name"]] = 1.0 + p.norm();
    }
    const std::string svg = report::mechanism_svg(scene, {0, static_cast<int>(k) + 1});
    for (const auto& [coupling, w] : wrench) {
      double size = 0;
      for (double x : w) size = std::max(size, std::abs(x));
      if (size < 1e-9) {
        EXPECT_FALSE(drawn.count(coupling)) << path << ": coupling " << coupling << " carries no action but a wrench is drawn";
        continue;
      }
      if (!(drawn.count(coupling))) {
        ADD_FAILURE() << path << ": no wrench drawn for coupling " << coupling;
        continue;
      }
      for (int i = 0; i < 6; ++i)
        EXPECT_NEAR(drawn[coupling][static_cast<std::size_t>(i)], w[static_cast<std::size_t>(i)],
                    1e-4 * std::max(size, 1.0) * (i < 3 ? lever[coupling] : 1.0))
            << path << ": self-stress " << k + 1 << ", coupling " << coupling << ", component " << i;
      ++compared;
      // Planar drawings: the arrow of the line of action points along the force.
      if (scene.dimension == 2) {
        const std::regex line(R"re(<line class="wrench" data-name=")re" + coupling +
                              R"re(" x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)")re");
        std::smatch m;
        if (std::regex_search(svg, m, line)) {
          const double dx = std::stod(m[3]) - std::stod(m[1]), dy = std::stod(m[4]) - std::stod(m[2]);
          EXPECT_GT(dx * w[3] - dy * w[4], 0.0) << path << ": SVG arrow of coupling " << coupling << " points against the force";
          ++compared;
        }
      }
    }
  }
  return compared;
}

framework::FrameworkModel read_model(const std::string& name, const std::string& yaml) {
  return kinestat::io::read_framework_model(kinestat::io::YamlFile::parse(name, yaml));
}

TEST(SignAgreement, EveryFrameworkExample) {
  int examples = 0, compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(KINESTAT_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto file = kinestat::io::YamlFile::load(entry.path().string());
    if (kinestat::io::model_kind(file) != "framework") continue;
    compared += compare_outputs(kinestat::io::read_framework_model(file), entry.path().filename().string());
    ++examples;
  }
  EXPECT_GE(examples, 10);
  EXPECT_GT(compared, 100);
}

TEST(SignAgreement, EveryNetworkExample) {
  int networks = 0, compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(KINESTAT_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto file = kinestat::io::YamlFile::load(entry.path().string());
    if (kinestat::io::model_kind(file) != "network") continue;
    compared += compare_network_outputs(entry.path().string());
    ++networks;
  }
  EXPECT_GE(networks, 10);
  EXPECT_GT(compared, 10);
}

TEST(SignAgreement, WarrenTrussWithAnExtraDiagonal) {
  // Bottom chord A-B-C, top chord D-E, a statically determinate Warren truss plus the extra
  // diagonal A-E: one self-stress.
  const auto model = read_model("warren.yaml", R"(kinestat: 1
kind: framework
dimension: planar
nodes: {A: [0, 0], B: [2, 0], C: [4, 0], D: [1, 1.7], E: [3, 1.7]}
supports: {A: pinned, C: [y]}
elements:
  - {name: AB, type: truss, nodes: [A, B]}
  - {name: BC, type: truss, nodes: [B, C]}
  - {name: AD, type: truss, nodes: [A, D]}
  - {name: DB, type: truss, nodes: [D, B]}
  - {name: BE, type: truss, nodes: [B, E]}
  - {name: EC, type: truss, nodes: [E, C]}
  - {name: DE, type: truss, nodes: [D, E]}
  - {name: extra, type: truss, nodes: [A, E]}
)");
  const auto analysis = framework::analyse_framework(model);
  ASSERT_EQ(analysis.self_stresses, 1);
  EXPECT_GT(compare_outputs(model, "warren"), 8);
}

TEST(SignAgreement, RandomPlanarFrameworks) {
  std::mt19937 random(20261123);
  std::uniform_real_distribution<double> coordinate(0.0, 10.0);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int nodes = 4 + trial % 5;
    std::ostringstream yaml;
    yaml << "kinestat: 1\nkind: framework\ndimension: planar\nnodes:\n";
    for (int i = 0; i < nodes; ++i) yaml << "  n" << i << ": [" << coordinate(random) << ", " << coordinate(random) << "]\n";
    yaml << "supports: {n0: pinned, n1: [y]}\nelements:\n";
    // A chain n0-n1-...-n(last) and every node to two earlier ones, plus a few random bars:
    // some models carry self-stresses, some modes, some both.
    std::set<std::pair<int, int>> bars;
    for (int i = 1; i < nodes; ++i) bars.insert({i - 1, i});
    for (int i = 2; i < nodes; ++i) bars.insert({i - 2, i});
    std::uniform_int_distribution<int> pick(0, nodes - 1);
    for (int extra = 0; extra < trial % 4; ++extra) {
      int a = pick(random), b = pick(random);
      if (a != b) bars.insert({std::min(a, b), std::max(a, b)});
    }
    if (trial % 3 == 0 && bars.size() > 3) bars.erase(std::prev(bars.end()));
    for (const auto& [a, b] : bars) yaml << "  - {name: b" << a << "_" << b << ", type: truss, nodes: [n" << a << ", n" << b << "]}\n";
    const auto model = read_model("random.yaml", yaml.str());
    compared += compare_outputs(model, "random framework " + std::to_string(trial));
  }
  EXPECT_GT(compared, 200);
}

}  // namespace
