// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/structure_reader.hpp"

#include "kinestat/io/model_vocabulary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

namespace kinestat::io {

namespace {

using structure::PairKind;
using structure::StructureModel;

// One matrix element and where it was written.
struct Cell {
  long long value = 0;
  SourceLocation where;
};
using CellMatrix = std::vector<std::vector<Cell>>;

// Bodies that no chain of pairs joins to the frame (body 0), in order; `joined[i]` lists the
// bodies that share a pair with body i.
std::vector<std::size_t> unreachable_from_frame(const std::vector<std::vector<std::size_t>>& joined) {
  std::vector<bool> reached(joined.size(), false);
  std::vector<std::size_t> stack{0};
  reached[0] = true;
  while (!stack.empty()) {
    const std::size_t body = stack.back();
    stack.pop_back();
    for (std::size_t other : joined[body]) {
      if (!reached[other]) {
        reached[other] = true;
        stack.push_back(other);
      }
    }
  }
  std::vector<std::size_t> missing;
  for (std::size_t i = 0; i < joined.size(); ++i)
    if (!reached[i]) missing.push_back(i);
  return missing;
}

// "bodies 3, 4 and 5 are" / "body 3 is", with `name` giving each body's label.
template <typename Name>
std::string not_connected_message(const std::vector<std::size_t>& bodies, Name name) {
  std::string list;
  const std::size_t shown = std::min<std::size_t>(bodies.size(), 10);
  for (std::size_t k = 0; k < shown; ++k) list += (k ? ", " : "") + name(bodies[k]);
  if (bodies.size() > shown) list += fmt::format(" and {} more", bodies.size() - shown);
  return fmt::format("{} {} not connected to the frame by any chain of pairs: a mechanism must hang from the frame "
                     "(join {} to the rest, or remove {})",
                     bodies.size() == 1 ? "body" : "bodies", list + (bodies.size() == 1 ? " is" : " are"),
                     bodies.size() == 1 ? "it" : "them", bodies.size() == 1 ? "it" : "them");
}

// Checks the rules of Table 1 and of a mechanism's topology, naming row and column
// (1-based, as the paper numbers bodies). `whole` locates the matrix itself.
void validate_adjacency(const CellMatrix& m, const SourceLocation& whole) {
  const std::size_t n = m.size();
  if (n < 2) throw InputError(whole, "adjacency must have at least 2 rows: the frame and one body");
  for (std::size_t i = 0; i < n; ++i) {
    if (m[i].size() != n) {
      const SourceLocation& at = m[i].empty() ? whole : m[i].front().where;
      throw InputError(at, fmt::format("adjacency must be square: row {} has {} entries, expected {}", i + 1,
                                       m[i].size(), n));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const Cell& c = m[i][j];
      if (c.value < 0 || c.value > 5) {
        throw InputError(c.where, fmt::format("adjacency code at row {}, column {} is {}; expected 0 to 5 "
                                              "(0 no pair, 1 lower, 2 higher, 3 lower with one input, "
                                              "4 higher with one input, 5 higher with two inputs)",
                                              i + 1, j + 1, c.value));
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (m[i][i].value != 0) {
      throw InputError(m[i][i].where, fmt::format("adjacency diagonal must be 0: row {}, column {} is {} "
                                                  "(a body cannot form a pair with itself)",
                                                  i + 1, i + 1, m[i][i].value));
    }
    for (std::size_t j = i + 1; j < n; ++j) {
      if (m[i][j].value != m[j][i].value) {
        throw InputError(m[j][i].where,
                         fmt::format("adjacency is not symmetric: row {}, column {} is {} but row {}, column {} is {}",
                                     i + 1, j + 1, m[i][j].value, j + 1, i + 1, m[j][i].value));
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    bool any = false;
    for (std::size_t j = 0; j < n; ++j) any = any || m[i][j].value != 0;
    if (any) continue;
    const SourceLocation& at = m[i].front().where;
    if (i == 0) throw InputError(at, "the frame (row 1) forms no pair: nothing is attached to it");
    throw InputError(at, fmt::format("body {} is isolated: row {} forms no pair", i + 1, i + 1));
  }
  std::vector<std::vector<std::size_t>> joined(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (m[i][j].value != 0) joined[i].push_back(j);
  if (const auto missing = unreachable_from_frame(joined); !missing.empty()) {
    throw InputError(m[missing.front()].front().where,
                     not_connected_message(missing, [](std::size_t b) { return std::to_string(b + 1); }));
  }
}

StructureModel model_from_cells(const CellMatrix& m) {
  std::vector<std::vector<int>> codes(m.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    for (const Cell& c : m[i]) codes[i].push_back(static_cast<int>(c.value));
  return structure::model_from_adjacency(codes);
}

CellMatrix read_yaml_matrix(const YamlFile& file, const TreeNode& node) {
  file.expect_sequence(node, "'adjacency'");
  CellMatrix m;
  for (const auto& row : node.items()) {
    file.expect_sequence(row, fmt::format("row {} of 'adjacency'", m.size() + 1));
    std::vector<Cell> cells;
    for (const auto& item : row.items()) {
      const std::string what = fmt::format("adjacency row {}, column {}", m.size() + 1, cells.size() + 1);
      cells.push_back({file.integer(item, what), file.where(item)});
    }
    m.push_back(std::move(cells));
  }
  return m;
}

std::vector<std::string> read_body_names(const YamlFile& file, const TreeNode& node) {
  file.expect_sequence(node, "'bodies'");
  std::vector<std::string> names;
  std::map<std::string, int> seen;
  for (const auto& item : node.items()) {
    const std::string name = file.string(item, "a body name");
    if (!seen.emplace(name, static_cast<int>(names.size())).second) {
      file.fail(item, fmt::format("duplicate body name '{}'", name));
    }
    names.push_back(name);
  }
  if (names.size() < 2) file.fail(node, "'bodies' must name the frame (first) and at least one more body");
  return names;
}

StructureModel read_pairs(const YamlFile& file, const TreeNode& bodies_node, const TreeNode& pairs_node,
                          int dimension) {
  StructureModel model;
  model.dimension = dimension;
  model.body_names = read_body_names(file, bodies_node);
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < model.body_names.size(); ++i) index[model.body_names[i]] = static_cast<int>(i);
  file.expect_sequence(pairs_node, "'pairs'");
  std::vector<int> degree(model.body_names.size(), 0);
  for (const auto& item : pairs_node.items()) {
    file.check_keys(item, "a pair", {"between", "pair", "inputs", "freedoms", "name"});
    const TreeNode between = file.required(item, "between", "a pair");
    file.expect_sequence(between, "'between'");
    if (between.size() != 2) file.fail(between, "'between' must name exactly two bodies");
    int ends[2];
    for (int s = 0; s < 2; ++s) {
      const std::string name = file.string(between[s], "a body of 'between'");
      const auto found = index.find(name);
      if (found == index.end()) file.fail(between[s], fmt::format("unknown body '{}' (not in 'bodies')", name));
      ends[s] = found->second;
    }
    if (ends[0] == ends[1]) file.fail(between, "a pair must join two different bodies");
    const TreeNode kind_node = file.required(item, "pair", "a pair");
    const std::string kind = file.string(kind_node, "'pair'");
    if (kind != "lower" && kind != "higher") file.fail(kind_node, fmt::format("unknown pair '{}'; expected lower or higher", kind));
    structure::Pair p;
    p.a = std::min(ends[0], ends[1]);
    p.b = std::max(ends[0], ends[1]);
    p.kind = kind == "lower" ? PairKind::lower : PairKind::higher;
    const TreeNode freedoms = file.optional(item, "freedoms");
    if (freedoms.defined()) {
      const long long f = file.integer(freedoms, "'freedoms'");
      if (f < 1 || f >= dimension) file.fail(freedoms, fmt::format("'freedoms' must be 1 to {}, found {}", dimension - 1, f));
      p.freedoms = static_cast<int>(f);
    } else if (dimension == 6 && p.kind == PairKind::higher) {
      file.fail(item, "a spatial higher pair needs 'freedoms' (2 to 5)");
    } else {
      p.freedoms = p.kind == PairKind::lower ? 1 : 2;  // the planar grades of Table 1
    }
    const TreeNode inputs = file.optional(item, "inputs");
    if (inputs.defined()) {
      const long long n = file.integer(inputs, "'inputs'");
      if (n < 0 || n > p.freedoms) file.fail(inputs, fmt::format("'inputs' must be 0 to {} (the pair's freedoms), found {}", p.freedoms, n));
      p.inputs = static_cast<int>(n);
    }
    const TreeNode name = file.optional(item, "name");
    if (name.defined()) (void)file.string(name, "'name'");
    ++degree[p.a];
    ++degree[p.b];
    model.pairs.push_back(p);
  }
  for (std::size_t i = 0; i < degree.size(); ++i) {
    if (degree[i] != 0) continue;
    if (i == 0) file.fail(bodies_node[0], fmt::format("the frame '{}' forms no pair: nothing is attached to it", model.body_names[0]));
    file.fail(bodies_node[i], fmt::format("body '{}' (body {}) is isolated: it forms no pair", model.body_names[i], i + 1));
  }
  std::vector<std::vector<std::size_t>> joined(model.body_names.size());
  for (const structure::Pair& p : model.pairs) {
    joined[static_cast<std::size_t>(p.a)].push_back(static_cast<std::size_t>(p.b));
    joined[static_cast<std::size_t>(p.b)].push_back(static_cast<std::size_t>(p.a));
  }
  if (const auto missing = unreachable_from_frame(joined); !missing.empty()) {
    file.fail(bodies_node[missing.front()],
              not_connected_message(missing, [&](std::size_t b) { return fmt::format("'{}'", model.body_names[b]); }));
  }
  return model;
}

}  // namespace

StructureModel read_structure_model(const YamlFile& file) {
  const TreeNode& root = file.root();
  file.check_keys(root, "a structure model",
                  {"kinestat", kSchemaKey, "kind", "name", "description", "dimension", "space", "units", "bodies", "adjacency", "pairs"});
  if (model_kind(file) != "structure") file.fail(root, "expected 'kind: structure'");
  TreeNode space = file.optional(root, "dimension");
  int dimension = 0;
  if (const TreeNode old = file.optional(root, "space"); old.defined()) {
    // `space: planar|spatial` is how structure files of format version 1 first wrote
    // `dimension:`; read as written, with a notice naming the new spelling.
    const std::string word(old.is_scalar() ? old.scalar() : "");
    if (word != "planar" && word != "spatial") file.fail(old, "'space' (now written 'dimension') must be 'planar' or 'spatial'");
    if (space.defined()) file.fail(old, "'space' is the older spelling of 'dimension': give 'dimension' alone");
    file.notice(old, fmt::format("'space: {}' is the older spelling of 'dimension: {}' (read as such); write 'dimension: {}'", word,
                                 word, word));
    dimension = word == "planar" ? 3 : 6;
    space = old;
  } else {
    dimension = read_planar(file, root, "structure", true) ? 3 : 6;
  }
  const std::string units = read_units(file, root);
  const TreeNode adjacency = file.optional(root, "adjacency");
  const TreeNode pairs = file.optional(root, "pairs");
  const TreeNode bodies = file.optional(root, "bodies");
  StructureModel model;
  if (adjacency.defined() == pairs.defined()) {
    file.fail(root, "a structure model needs exactly one of 'adjacency' (a matrix) or 'pairs' (with 'bodies')");
  }
  if (adjacency.defined()) {
    if (dimension != 3) file.fail(space, "an adjacency matrix of Table-1 codes is planar; describe a spatial mechanism with 'bodies' and 'pairs'");
    const CellMatrix cells = read_yaml_matrix(file, adjacency);
    validate_adjacency(cells, file.where(adjacency));
    model = model_from_cells(cells);
    if (bodies.defined()) {
      std::vector<std::string> names = read_body_names(file, bodies);
      if (names.size() != cells.size()) {
        file.fail(bodies, fmt::format("'bodies' names {} bodies but 'adjacency' has {} rows", names.size(), cells.size()));
      }
      model.body_names = std::move(names);
    }
  } else {
    if (!bodies.defined()) file.fail(pairs, "'pairs' needs 'bodies' (the frame first) to name the bodies");
    model = read_pairs(file, bodies, pairs, dimension);
  }
  const TreeNode name = file.optional(root, "name");
  if (name.defined()) model.name = file.string(name, "'name'");
  model.units = units;
  return model;
}

StructureModel read_adjacency_text(const std::string& text, const std::string& source) {
  CellMatrix m;
  int line = 1;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view row(text.data() + pos, end - pos);
    if (const auto hash = row.find('#'); hash != std::string_view::npos) row = row.substr(0, hash);
    std::vector<Cell> cells;
    std::size_t i = 0;
    while (i < row.size()) {
      if (std::isspace(static_cast<unsigned char>(row[i])) || row[i] == ',') {
        ++i;
        continue;
      }
      const std::size_t start = i;
      while (i < row.size() && !std::isspace(static_cast<unsigned char>(row[i])) && row[i] != ',') ++i;
      const std::string token(row.substr(start, i - start));
      const SourceLocation where{source, line, static_cast<int>(start) + 1};
      std::size_t digits = token[0] == '-' || token[0] == '+' ? 1 : 0;
      bool integer = digits < token.size() && token.size() <= 9;
      for (std::size_t k = digits; k < token.size(); ++k) integer = integer && std::isdigit(static_cast<unsigned char>(token[k]));
      if (!integer) {
        throw InputError(where, fmt::format("adjacency row {}, column {} must be an integer code 0 to 5, found '{}'",
                                            m.size() + 1, cells.size() + 1, token));
      }
      cells.push_back({std::stoll(token), where});
    }
    if (!cells.empty()) m.push_back(std::move(cells));
    if (end == text.size()) break;
    pos = end + 1;
    ++line;
  }
  if (m.empty()) throw InputError({source, 1, 1}, "no adjacency matrix: expected rows of codes 0 to 5");
  validate_adjacency(m, {source, 1, 1});
  return model_from_cells(m);
}

}  // namespace kinestat::io
