// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/structure_yaml_writer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

namespace kinestat::io {

using structure::Pair;
using structure::PairKind;
using structure::StructureModel;

namespace {

// A YAML double-quoted scalar: JSON's string escapes are valid YAML.
std::string quoted(const std::string& text) { return nlohmann::json(text).dump(); }

bool same_pair(const Pair& x, const Pair& y) {
  return x.a == y.a && x.b == y.b && x.kind == y.kind && x.freedoms == y.freedoms && x.inputs == y.inputs;
}

// The adjacency matrix that reads back as exactly `model`'s pairs in its order, or empty when
// the model must be written pair by pair (spatial, repeated pairs, other freedoms or order).
std::vector<std::vector<int>> exact_adjacency(const StructureModel& model) {
  std::vector<std::vector<int>> matrix = structure::adjacency_of(model);
  if (matrix.empty()) return matrix;
  const StructureModel again = structure::model_from_adjacency(matrix);
  bool same = again.pairs.size() == model.pairs.size();
  for (std::size_t k = 0; same && k < model.pairs.size(); ++k) same = same_pair(again.pairs[k], model.pairs[k]);
  if (!same) matrix.clear();
  return matrix;
}

// Body names are the numbers 1, 2, ... the adjacency form gives unnamed bodies.
bool default_names(const StructureModel& model) {
  for (int i = 0; i < model.body_count(); ++i)
    if (model.body_names[static_cast<std::size_t>(i)] != std::to_string(i + 1)) return false;
  return true;
}

std::string body_list(const StructureModel& model) {
  std::string out = "[";
  for (int i = 0; i < model.body_count(); ++i) out += (i ? ", " : "") + quoted(structure::body_label(model, i));
  return out + "]";
}

}  // namespace

std::string structure_yaml(const StructureModel& model, const std::vector<std::string>& comments) {
  std::string out;
  for (const auto& c : comments) out += "# " + c + "\n";
  out += "kinestat: 1\nkind: structure\n";
  if (!model.name.empty()) out += "name: " + quoted(model.name) + "\n";
  out += model.dimension == 3 ? "dimension: planar\n" : "dimension: spatial\n";
  if (!model.units.empty()) out += "units: " + quoted(model.units) + "\n";
  if (const auto matrix = exact_adjacency(model); !matrix.empty()) {
    if (!default_names(model)) out += "bodies: " + body_list(model) + "\n";
    out += "adjacency:\n";
    for (const auto& row : matrix) out += fmt::format("  - [{}]\n", fmt::join(row, ", "));
    return out;
  }
  out += "bodies: " + body_list(model) + "\n";
  out += "pairs:\n";
  for (const Pair& p : model.pairs)
    out += fmt::format("  - {{between: [{}, {}], pair: {}, freedoms: {}, inputs: {}}}\n", quoted(structure::body_label(model, p.a)),
                       quoted(structure::body_label(model, p.b)), p.kind == PairKind::lower ? "lower" : "higher", p.freedoms,
                       p.inputs);
  return out;
}

}  // namespace kinestat::io
