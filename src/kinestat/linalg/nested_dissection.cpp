// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/nested_dissection.hpp"

#include <cholmod.h>

#include <algorithm>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>

namespace kinestat::linalg {

namespace {

// Rows of a with more groups than this join them as a star (each to the row's first group)
// instead of a clique, so that the graph stays linear in the non-zeros of a. Any order is a valid
// column order; a star only lets the dissection see less of that row's coupling.
constexpr std::size_t kNestedDissectionCliqueLimit = 16;

}  // namespace

std::vector<Eigen::Index> nested_dissection_order(Eigen::Index vertices,
                                                  const std::vector<std::pair<Eigen::Index, Eigen::Index>>& edges) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(std::max<Eigen::Index>(vertices, 0)));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  if (vertices < 3 || edges.empty()) return order;
  // The upper triangle of the adjacency pattern in compressed columns (row < column), sorted,
  // without repeats: CHOLMOD hands METIS the symmetric graph of this pattern.
  std::vector<std::pair<SuiteSparse_long, SuiteSparse_long>> upper;  // (column, row)
  upper.reserve(edges.size());
  for (const auto& [a, b] : edges) {
    if (a == b || a < 0 || b < 0 || a >= vertices || b >= vertices) continue;
    upper.emplace_back(static_cast<SuiteSparse_long>(std::max(a, b)), static_cast<SuiteSparse_long>(std::min(a, b)));
  }
  std::sort(upper.begin(), upper.end());
  upper.erase(std::unique(upper.begin(), upper.end()), upper.end());
  if (upper.empty()) return order;
  std::vector<SuiteSparse_long> column_start(static_cast<std::size_t>(vertices) + 1, 0), rows(upper.size());
  for (std::size_t k = 0; k < upper.size(); ++k) {
    ++column_start[static_cast<std::size_t>(upper[k].first) + 1];
    rows[k] = upper[k].second;
  }
  std::partial_sum(column_start.begin(), column_start.end(), column_start.begin());

  cholmod_sparse pattern{};
  pattern.nrow = static_cast<std::size_t>(vertices);
  pattern.ncol = static_cast<std::size_t>(vertices);
  pattern.nzmax = upper.size();
  pattern.p = column_start.data();
  pattern.i = rows.data();
  pattern.stype = 1;  // symmetric, upper triangle stored
  pattern.itype = CHOLMOD_LONG;
  pattern.xtype = CHOLMOD_PATTERN;
  pattern.dtype = CHOLMOD_DOUBLE;
  pattern.sorted = 1;
  pattern.packed = 1;

  cholmod_common common{};
  cholmod_l_start(&common);
  common.print = 0;
  std::vector<SuiteSparse_long> permutation(static_cast<std::size_t>(vertices));
  const int ok = cholmod_l_metis(&pattern, nullptr, 0, 1, permutation.data(), &common);
  const int status = common.status;
  cholmod_l_finish(&common);
  if (status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  if (ok == 0 || status < CHOLMOD_OK)
    throw std::runtime_error("nested dissection ordering failed (CHOLMOD status " + std::to_string(status) + ")");
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<Eigen::Index>(permutation[k]);
  return order;
}

std::vector<Eigen::Index> grouped_nested_dissection_order(const Eigen::SparseMatrix<double>& a,
                                                          const std::vector<Eigen::Index>& group_of_column, double min_share) {
  const Eigen::Index rows = a.rows(), cols = a.cols();
  if (static_cast<Eigen::Index>(group_of_column.size()) != cols)
    throw std::invalid_argument("grouped_nested_dissection_order: one group is needed for every column");
  Eigen::Index groups = 0;
  for (const Eigen::Index g : group_of_column) {
    if (g < 0) throw std::invalid_argument("grouped_nested_dissection_order: a column has no group");
    groups = std::max(groups, g + 1);
  }
  // The graph's vertices are the groups that have columns, in increasing group number; the
  // columns of each vertex in increasing index (counting sorts).
  std::vector<Eigen::Index> vertex_of_group(static_cast<std::size_t>(groups), 0);
  for (const Eigen::Index g : group_of_column) vertex_of_group[static_cast<std::size_t>(g)] = 1;
  Eigen::Index vertices = 0;
  for (Eigen::Index& v : vertex_of_group) v = v != 0 ? vertices++ : -1;
  std::vector<Eigen::Index> vertex_start(static_cast<std::size_t>(vertices) + 1, 0);
  for (const Eigen::Index g : group_of_column) ++vertex_start[static_cast<std::size_t>(vertex_of_group[static_cast<std::size_t>(g)]) + 1];
  std::partial_sum(vertex_start.begin(), vertex_start.end(), vertex_start.begin());
  std::vector<Eigen::Index> by_vertex(static_cast<std::size_t>(cols)), fill(vertex_start.begin(), vertex_start.end() - 1);
  for (Eigen::Index j = 0; j < cols; ++j) {
    const Eigen::Index v = vertex_of_group[static_cast<std::size_t>(group_of_column[static_cast<std::size_t>(j)])];
    by_vertex[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = j;
  }
  const auto size_of = [&](Eigen::Index v) {
    return static_cast<double>(vertex_start[static_cast<std::size_t>(v) + 1] - vertex_start[static_cast<std::size_t>(v)]);
  };
  // The vertices met by each row, once per non-zero: a counting sort by row (a is column-major).
  std::vector<Eigen::Index> row_start(static_cast<std::size_t>(rows) + 1, 0);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) ++row_start[static_cast<std::size_t>(it.row()) + 1];
  std::partial_sum(row_start.begin(), row_start.end(), row_start.begin());
  std::vector<Eigen::Index> row_vertices(static_cast<std::size_t>(row_start.back())), next(row_start.begin(), row_start.end() - 1);
  for (Eigen::Index j = 0; j < cols; ++j) {
    const Eigen::Index v = vertex_of_group[static_cast<std::size_t>(group_of_column[static_cast<std::size_t>(j)])];
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it)
      row_vertices[static_cast<std::size_t>(next[static_cast<std::size_t>(it.row())]++)] = v;
  }
  // Edges between the vertices of each row; meanwhile the pairs of columns of different groups
  // that the row couples (its non-zeros) and those the group graph joins (all their columns).
  std::vector<std::pair<Eigen::Index, Eigen::Index>> edges;
  edges.reserve(row_vertices.size());
  double coupled = 0.0, joined = 0.0;
  for (Eigen::Index i = 0; i < rows; ++i) {
    const auto first = row_vertices.begin() + row_start[static_cast<std::size_t>(i)];
    const auto last = row_vertices.begin() + row_start[static_cast<std::size_t>(i) + 1];
    std::sort(first, last);
    const auto entries = static_cast<double>(last - first);
    double same_group = 0.0;  // pairs of the row's non-zeros within one group, each counted twice
    for (auto p = first; p != last;) {
      const auto q = std::upper_bound(p, last, *p);
      same_group += static_cast<double>(q - p) * static_cast<double>(q - p);
      p = q;
    }
    coupled += (entries * entries - same_group) / 2.0;
    const auto end = std::unique(first, last);
    const bool clique = static_cast<std::size_t>(end - first) <= kNestedDissectionCliqueLimit;
    for (auto p = first; p != end; ++p)
      for (auto q = p + 1; q != end && (clique || p == first); ++q) {
        edges.emplace_back(*p, *q);
        joined += size_of(*p) * size_of(*q);
      }
  }
  if (joined > 0.0 && coupled < min_share * joined) return {};
  std::vector<Eigen::Index>().swap(row_vertices);
  const std::vector<Eigen::Index> vertex_order = nested_dissection_order(vertices, edges);
  std::vector<Eigen::Index> order;
  order.reserve(static_cast<std::size_t>(cols));
  for (const Eigen::Index v : vertex_order)
    order.insert(order.end(), by_vertex.begin() + vertex_start[static_cast<std::size_t>(v)],
                 by_vertex.begin() + vertex_start[static_cast<std::size_t>(v) + 1]);
  return order;
}

}  // namespace kinestat::linalg
