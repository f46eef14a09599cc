// SPDX-License-Identifier: BSD-3-Clause
#include "support/lattice_generator.hpp"

#include <cmath>
#include <string>

namespace kinestat::framework {

namespace {

void add_bar(FrameworkModel& model, std::size_t p, std::size_t q) {
  Element bar;
  bar.name = std::to_string(model.elements.size() + 1);
  bar.type = ElementType::truss;
  bar.nodes = {p, q};
  bar.roles = {DeformationRole::fixed};
  model.elements.push_back(std::move(bar));
}

Node lattice_node(std::size_t index, double x, double y, double z, bool pinned) {
  Node node;
  node.name = "n" + std::to_string(index);
  node.position = {x, y, z};
  if (pinned) node.roles.fill(CoordinateRole::fixed);
  return node;
}

}  // namespace

FrameworkModel planar_lattice(int n, bool diagonals) {
  FrameworkModel model;
  model.dimension = 2;
  auto id = [n](int i, int j) { return static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i); };
  const auto side = static_cast<std::size_t>(n);
  model.nodes.reserve(side * side);
  model.elements.reserve(side * side * (diagonals ? 3 : 2));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) model.nodes.push_back(lattice_node(id(i, j), i, j, 0.0, j == 0));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n) add_bar(model, id(i, j), id(i + 1, j));
      if (j + 1 < n) add_bar(model, id(i, j), id(i, j + 1));
      if (diagonals && i + 1 < n && j + 1 < n) add_bar(model, id(i, j), id(i + 1, j + 1));
    }
  return model;
}

FrameworkModel spatial_lattice(int n) {
  FrameworkModel model;
  const auto side = static_cast<std::size_t>(n);
  auto id = [side](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * side + static_cast<std::size_t>(j)) * side + static_cast<std::size_t>(i);
  };
  model.nodes.reserve(side * side * side);
  model.elements.reserve(4 * side * side * side);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) model.nodes.push_back(lattice_node(id(i, j, k), i, j, k, k == 0));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (i + 1 < n) add_bar(model, id(i, j, k), id(i + 1, j, k));
        if (j + 1 < n) add_bar(model, id(i, j, k), id(i, j + 1, k));
        if (k + 1 < n) add_bar(model, id(i, j, k), id(i, j, k + 1));
        if (i + 1 < n && j + 1 < n) add_bar(model, id(i, j, k), id(i + 1, j + 1, k));
      }
  return model;
}

int lattice_side(double bars, double per_cell, int dimension) {
  return static_cast<int>(std::lround(std::pow(bars / per_cell, 1.0 / dimension))) + 1;
}

}  // namespace kinestat::framework
