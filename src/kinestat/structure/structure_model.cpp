// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/structure/structure_model.hpp"

#include "kinestat/error.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace kinestat::structure {

int StructureModel::input_count() const {
  int total = 0;
  for (const Pair& p : pairs) total += p.inputs;
  return total;
}

int StructureModel::mobility() const {
  int m = dimension * (body_count() - 1);
  for (const Pair& p : pairs) m -= dimension - p.freedoms;
  return m;
}

int pair_code(PairKind kind, int inputs) {
  if (kind == PairKind::lower) return inputs == 0 ? 1 : 3;
  return inputs == 0 ? 2 : (inputs == 1 ? 4 : 5);
}

Pair pair_from_code(int a, int b, int code) {
  Pair p;
  p.a = a;
  p.b = b;
  switch (code) {
    case 1: p.kind = PairKind::lower; p.inputs = 0; break;
    case 2: p.kind = PairKind::higher; p.inputs = 0; break;
    case 3: p.kind = PairKind::lower; p.inputs = 1; break;
    case 4: p.kind = PairKind::higher; p.inputs = 1; break;
    case 5: p.kind = PairKind::higher; p.inputs = 2; break;
    default: throw Error("pair code must be 1..5, got " + std::to_string(code));
  }
  // Table 1 is planar: a lower pair allows one relative freedom, a higher pair two.
  p.freedoms = p.kind == PairKind::lower ? 1 : 2;
  return p;
}

StructureModel model_from_adjacency(const std::vector<std::vector<int>>& adjacency) {
  StructureModel model;
  model.dimension = 3;
  const int n = static_cast<int>(adjacency.size());
  for (int i = 0; i < n; ++i) model.body_names.push_back(std::to_string(i + 1));
  // The upper triangle holds each pair once (Step 4 of the seed).
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (adjacency[i][j] != 0) model.pairs.push_back(pair_from_code(i, j, adjacency[i][j]));
  return model;
}

std::vector<std::vector<int>> adjacency_of(const StructureModel& model) {
  if (model.dimension != 3) return {};
  const int n = model.body_count();
  std::vector<std::vector<int>> m(n, std::vector<int>(n, 0));
  for (const Pair& p : model.pairs) {
    const int planar_freedoms = p.kind == PairKind::lower ? 1 : 2;
    if (p.freedoms != planar_freedoms || m[p.a][p.b] != 0) return {};
    m[p.a][p.b] = m[p.b][p.a] = pair_code(p.kind, p.inputs);
  }
  return m;
}

StructureModel model_from_couplings(std::vector<std::string> body_names, const std::vector<CouplingPair>& couplings,
                                    int dimension) {
  if (dimension != 3 && dimension != 6) throw Error("dimension must be 3 (planar) or 6 (spatial)");
  StructureModel model;
  model.dimension = dimension;
  model.body_names = std::move(body_names);
  const int n = model.body_count();
  for (const CouplingPair& c : couplings) {
    if (c.body_i < 0 || c.body_i >= n || c.body_j < 0 || c.body_j >= n)
      throw Error("coupling refers to a body outside 0.." + std::to_string(n - 1));
    if (c.body_i == c.body_j) throw Error("coupling joins a body to itself");
    Pair p;
    p.a = std::min(c.body_i, c.body_j);
    p.b = std::max(c.body_i, c.body_j);
    p.kind = c.kind;
    p.freedoms = c.freedoms.value_or(c.kind == PairKind::lower ? 1 : 2);
    p.inputs = c.inputs;
    if (p.freedoms < 1 || p.freedoms >= dimension)
      throw Error("a pair must allow 1.." + std::to_string(dimension - 1) + " freedoms");
    if (p.inputs < 0 || p.inputs > p.freedoms)
      throw Error("a pair can carry 0.." + std::to_string(p.freedoms) + " inputs");
    model.pairs.push_back(p);
  }
  return model;
}

std::optional<PairKind> pair_kind_of_coupling_type(std::string_view type) {
  // Lower pairs keep surface contact; higher pairs touch along a line or at a point.
  static constexpr std::string_view lower[] = {"revolute", "prismatic", "helical", "screw", "cylindrical",
                                               "spherical", "planar", "universal", "hinge", "slider"};
  static constexpr std::string_view higher[] = {"cam", "gear", "point_contact", "point_on_plane", "point_on_line",
                                                "line_contact", "line_on_plane", "rolling", "pin_in_slot",
                                                "sphere_on_plane", "cylinder_on_plane", "higher"};
  for (auto name : lower)
    if (type == name) return PairKind::lower;
  for (auto name : higher)
    if (type == name) return PairKind::higher;
  return std::nullopt;
}

std::string body_label(const StructureModel& model, int body) {
  if (body >= 0 && body < model.body_count() && !model.body_names[body].empty()) return model.body_names[body];
  return std::to_string(body + 1);
}

}  // namespace kinestat::structure
