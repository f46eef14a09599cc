// SPDX-License-Identifier: BSD-3-Clause
#include "support/valid_models.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/structure_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/svg_writer.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat::testing {

namespace {

// A grid coordinate: small integers make coincident, collinear and coplanar points common.
int coordinate(Choices& c) { return c.pick(-2, 2); }

std::string point(Choices& c, bool planar) {
  return planar ? fmt::format("[{}, {}]", coordinate(c), coordinate(c))
                : fmt::format("[{}, {}, {}]", coordinate(c), coordinate(c), coordinate(c));
}

// A non-zero direction on the grid.
std::string direction(Choices& c, bool planar) {
  int x = 0, y = 0, z = 0;
  while (x == 0 && y == 0 && z == 0) {
    x = c.pick(-1, 1);
    y = c.pick(-1, 1);
    z = planar ? 0 : c.pick(-1, 1);
    if (x == 0 && y == 0 && z == 0) x = 1;  // bytes used up: still a direction
  }
  return planar ? fmt::format("[{}, {}]", x, y) : fmt::format("[{}, {}, {}]", x, y, z);
}

std::string node_name(int i) { return "N" + std::to_string(i); }
std::string body_name(int i) { return "b" + std::to_string(i); }

}  // namespace

std::string random_framework_yaml(Choices& c) {
  const bool planar = c.pick(0, 1) == 1;
  const int nodes = c.pick(1, 7);
  // Degenerate shapes get their own weight: every node supported, no element.
  const int shape = c.pick(0, 5);
  const bool all_supported = shape == 0, no_elements = shape == 1;
  std::string text = fmt::format("kinestat: 1\nkind: framework\nname: random\ndimension: {}\nnodes:\n", planar ? "planar" : "spatial");
  for (int i = 0; i < nodes; ++i) text += fmt::format("  {}: {}\n", node_name(i), point(c, planar));

  struct Element {
    std::string type;
    std::vector<int> nodes;
  };
  std::vector<Element> elements;
  const int count = no_elements ? 0 : c.pick(0, 10);
  for (int e = 0; e < count && nodes >= 2; ++e) {
    const int type = c.pick(0, 5);  // trusses most often
    Element element{type <= 3 ? "truss" : (type == 4 ? "beam" : "rigid_body"), {}};
    const int size = element.type == "rigid_body" ? c.pick(2, std::min(nodes, 3)) : 2;
    std::vector<int> free(static_cast<std::size_t>(nodes));
    for (int i = 0; i < nodes; ++i) free[static_cast<std::size_t>(i)] = i;
    for (int k = 0; k < size; ++k) {
      const int at = c.pick(0, static_cast<int>(free.size()) - 1);
      element.nodes.push_back(free[static_cast<std::size_t>(at)]);
      free.erase(free.begin() + at);
    }
    elements.push_back(element);
  }
  // Nodes of beams and rigid bodies have rotational coordinates; supports may name them.
  std::vector<bool> rotational(static_cast<std::size_t>(nodes), false);
  for (const Element& element : elements)
    if (element.type != "truss")
      for (int n : element.nodes) rotational[static_cast<std::size_t>(n)] = true;

  std::string supports;
  for (int i = 0; i < nodes; ++i) {
    const int kind = all_supported ? 1 : c.pick(0, 6);
    if (kind == 1) supports += fmt::format("  {}: fixed\n", node_name(i));
    if (kind == 2 && rotational[static_cast<std::size_t>(i)]) supports += fmt::format("  {}: pinned\n", node_name(i));
    if (kind == 3) supports += fmt::format("  {}: [x]\n", node_name(i));
    if (kind == 4) supports += fmt::format("  {}: [{}]\n", node_name(i), planar ? "y" : "x, z");
  }
  if (!supports.empty()) text += "supports:\n" + supports;
  if (!all_supported && c.pick(0, 5) == 0) {
    // An independent coordinate on a node without supports (x^m).
    const int i = c.pick(0, nodes - 1);
    if (supports.find(node_name(i) + ":") == std::string::npos) text += fmt::format("independent:\n  {}: [y]\n", node_name(i));
  }
  text += elements.empty() ? "elements: []\n" : "elements:\n";
  for (const Element& element : elements) {
    std::string names;
    for (int n : element.nodes) names += (names.empty() ? "" : ", ") + node_name(n);
    std::string released;
    if (element.type == "beam") {
      const int r = c.pick(0, 2);
      if (r == 1) released = planar ? ", released: [bending]" : ", released: [torsion, bending]";
      if (r == 2) released = planar ? ", released: [bending_q]" : ", released: [torsion, bending_xy]";
    } else if (element.type == "truss" && c.pick(0, 7) == 0) {
      released = ", released: [elongation]";
    }
    text += fmt::format("  - {{type: {}, nodes: [{}]{}}}\n", element.type, names, released);
  }
  return text;
}

std::string random_network_yaml(Choices& c) {
  const bool planar = c.pick(0, 1) == 1;
  const int bodies = c.pick(1, 6);
  const std::vector<std::string> spatial_types = {"revolute",  "prismatic", "cylindrical", "spherical", "universal",
                                                  "planar",    "helical",   "point_on_plane", "rigid", "free"};
  const std::vector<std::string> planar_types = {"revolute", "prismatic", "point_on_line", "rigid", "free"};
  const std::vector<std::string>& types = planar ? planar_types : spatial_types;
  // Sometimes every coupling is of one type.
  const int only = c.pick(0, 3) == 0 ? c.pick(0, static_cast<int>(types.size()) - 1) : -1;
  std::string text = fmt::format("kinestat: 1\nkind: network\nname: random\ndimension: {}\nground: {}\nbodies: [", planar ? "planar" : "spatial",
                                 body_name(0));
  for (int b = 0; b < bodies; ++b) text += (b > 0 ? ", " : "") + body_name(b);
  text += "]\n";
  const int couplings = bodies < 2 ? 0 : c.pick(0, 9);
  text += couplings == 0 ? "couplings: []\n" : "couplings:\n";
  for (int i = 0; i < couplings; ++i) {
    const int from = c.pick(0, bodies - 1);
    int to = c.pick(0, bodies - 2);
    if (to >= from) ++to;
    const std::string& type = types[static_cast<std::size_t>(only >= 0 ? only : c.pick(0, static_cast<int>(types.size()) - 1))];
    std::string geometry;
    if (type == "revolute") geometry = ", point: " + point(c, planar) + (planar ? "" : ", axis: " + direction(c, planar));
    if (type == "prismatic") geometry = ", axis: " + direction(c, planar);
    if (type == "cylindrical") geometry = ", point: " + point(c, planar) + ", axis: " + direction(c, planar);
    if (type == "spherical") geometry = ", point: " + point(c, planar);
    if (type == "helical") geometry = fmt::format(", point: {}, axis: {}, pitch: {}", point(c, planar), direction(c, planar), c.pick(-2, 2));
    if (type == "universal") {
      // Two axes on the grid, not parallel: the second is the first turned by a grid step.
      const std::string axis = direction(c, false);
      std::string axis2 = direction(c, false);
      if (axis2 == axis) axis2 = axis == "[0, 0, 1]" ? "[1, 0, 0]" : "[0, 0, 1]";
      geometry = ", point: " + point(c, false) + ", axis: " + axis + ", axis2: " + axis2;
    }
    if (type == "planar" || type == "point_on_plane" || type == "point_on_line")
      geometry = ", point: " + point(c, planar) + ", normal: " + direction(c, planar);
    text += fmt::format("  - {{name: c{}, type: {}, between: [{}, {}]{}}}\n", i, type, body_name(from), body_name(to), geometry);
  }
  return text;
}

std::string random_structure_yaml(Choices& c) {
  const int bodies = c.pick(1, 8);
  std::string text = "kinestat: 1\nkind: structure\nname: random\nbodies: [";
  for (int b = 0; b < bodies; ++b) text += (b > 0 ? ", " : "") + body_name(b);
  text += "]\n";
  // A tree joining every body (the reader refuses a body in no pair), then extra pairs.
  const int pairs = bodies < 2 ? 0 : bodies - 1 + c.pick(0, 6);
  text += pairs == 0 ? "pairs: []\n" : "pairs:\n";
  for (int i = 0; i < pairs; ++i) {
    int from = c.pick(0, bodies - 1), to = 0;
    if (i < bodies - 1) {
      from = i + 1;
      to = c.pick(0, i);
    } else {
      to = c.pick(0, bodies - 2);
      if (to >= from) ++to;
    }
    const bool lower = c.pick(0, 3) > 0;
    const int inputs = c.pick(0, 5) == 0 ? 1 : 0;
    text += fmt::format("  - {{between: [{}, {}], pair: {}{}}}\n", body_name(from), body_name(to), lower ? "lower" : "higher",
                        inputs > 0 ? ", inputs: 1" : "");
  }
  return text;
}

std::string random_model_yaml(Choices& c) {
  switch (c.pick(0, 2)) {
    case 0: return random_framework_yaml(c);
    case 1: return random_network_yaml(c);
    default: return random_structure_yaml(c);
  }
}

namespace {

std::string check_framework(const framework::FrameworkModel& model) {
  const framework::FrameworkResult a = framework::analyse_framework(model);
  const auto verdict = design::framework_verdict(model, a);
  (void)report::framework_report_text(model, a, &verdict);
  (void)report::framework_report_json(model, a, &verdict).dump();
  (void)report::mechanism_svg(report::framework_scene(model, a));
  if (a.rank < 0 || a.rank > std::min(a.m, a.n)) return fmt::format("rank {} outside 0..min({}, {})", a.rank, a.m, a.n);
  if (a.mechanisms - a.self_stresses != a.n - a.m)
    return fmt::format("Maxwell's rule: mechanisms {} - self-stresses {} != columns {} - rows {}", a.mechanisms, a.self_stresses, a.n, a.m);
  if (a.decision.close()) return "";
  framework::AnalysisOptions sparse;
  sparse.dense_limit = 0;
  const framework::FrameworkResult s = framework::analyse_framework(model, sparse);
  if (!s.decision.close() && s.rank != a.rank) return fmt::format("dense rank {} != sparse rank {}", a.rank, s.rank);
  if (a.vectors) {
    // The proposal makes D(c) square and non-singular: nothing left to move or to stress.
    const framework::FrameworkResult fixed = framework::analyse_framework(framework::apply_proposal(model, a));
    if (!fixed.decision.close() && (fixed.mechanisms != 0 || fixed.self_stresses != 0))
      return fmt::format("the proposal re-analysed has {} mechanisms and {} self-stresses, not 0 and 0", fixed.mechanisms, fixed.self_stresses);
  }
  return "";
}

std::string check_network(const io::LoadedNetwork& loaded, const std::string& path) {
  const network::Model& model = loaded.model;
  network::NetworkResult r;
  try {
    r = network::analyse_network(model);
  } catch (const network::ModelError& error) {
    (void)io::locate(error, loaded, path);  // a refusal only the analysis can see, located
    return "";
  }
  const auto verdict = design::network_verdict(model, r);
  report::NetworkReportOptions options{true, &verdict};
  (void)report::network_report_text(model, r, options);
  (void)report::network_report_json(model, r, options).dump();
  const auto scene = report::network_scene(model, r);
  (void)report::graph_svg(scene);
  (void)report::mechanism_svg(scene);
  const int d = r.d;
  if (r.FN - r.CN != r.F - d * r.l) return fmt::format("FN {} - CN {} != F {} - d l = {}", r.FN, r.CN, r.F, d * r.l);
  if (r.CN - r.FN != r.C - d * r.k) return fmt::format("CN {} - FN {} != C {} - d k = {}", r.CN, r.FN, r.C, d * r.k);
  if (r.FN != r.F - r.m || r.CN != r.C - r.a) return fmt::format("FN {} != F {} - m {} or CN {} != C {} - a {}", r.FN, r.F, r.m, r.CN, r.C, r.a);
  if (r.exact) {
    network::AnalysisOptions floating;
    floating.arithmetic = network::Arithmetic::floating;
    const network::NetworkResult f = network::analyse_network(model, floating);
    const bool close = f.circulation.solution.rank.close() || f.cutset_law.solution.rank.close();
    if (!close && (f.FN != r.FN || f.CN != r.CN))
      return fmt::format("exact FN {} CN {} != floating-point FN {} CN {}", r.FN, r.CN, f.FN, f.CN);
  }
  if (!model.couplings.empty()) {
    const network::SparseNetworkResult s = network::analyse_network_sparse(model);
    if (!s.rank.close() && (s.FN != r.FN || s.CN != r.CN))
      return fmt::format("dense FN {} CN {} != sparse FN {} CN {}", r.FN, r.CN, s.FN, s.CN);
  }
  return "";
}

std::string check_structure(const structure::StructureModel& model) {
  const auto decomposition = structure::analyse_structure(model);
  const auto verdict = design::structure_verdict(model, decomposition);
  const report::StructureReport report{model, decomposition, nullptr, structure::SearchMethod::matching, &verdict, model.units};
  (void)report::structure_report_text(report);
  (void)report::structure_report_json(report);
  (void)report::structure_svg(model, decomposition);
  return "";
}

}  // namespace

ModelCheck check_model_text(const std::string& text) {
  const std::string path = "random.yaml";
  ModelCheck check;
  try {
    const io::YamlFile file = io::YamlFile::parse(path, text);
    const std::string kind = io::model_kind(file);
    if (kind == "framework") {
      const framework::FrameworkModel model = io::read_framework_model(file);
      check.read = true;
      check.failed = check_framework(model);
    } else if (kind == "network") {
      const io::LoadedNetwork loaded = io::read_network_model(file);
      check.read = true;
      check.failed = check_network(loaded, path);
    } else if (kind == "structure") {
      const structure::StructureModel model = io::read_structure_model(file);
      check.read = true;
      check.failed = check_structure(model);
    } else {
      check.failed = "unknown kind " + kind;
    }
  } catch (const io::InputError&) {
    // The reader's refusal (e.g. a zero-length bar): a located message, not a crash.
  }
  return check;
}

}  // namespace kinestat::testing
