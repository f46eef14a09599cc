// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/column_partition.hpp"

#include <algorithm>
#include <cstddef>

namespace kinestat::distributed {

namespace {

// The column graph without forming AᵀA: a column's neighbours are the columns of its rows.
struct ColumnGraph {
  const Eigen::SparseMatrix<double>& by_column;
  Eigen::SparseMatrix<double, Eigen::RowMajor> by_row;
};

// Breadth-first levels from `start` over the unvisited part of its component, numbered from
// `base`; appends the columns reached to `order` and returns the last level used.
Eigen::Index visit_levels(const ColumnGraph& graph, Eigen::Index start, Eigen::Index base, std::vector<Eigen::Index>& level,
                          std::vector<Eigen::Index>& order) {
  const std::size_t first = order.size();
  level[static_cast<std::size_t>(start)] = base;
  order.push_back(start);
  Eigen::Index last = base;
  for (std::size_t k = first; k < order.size(); ++k) {
    const Eigen::Index column = order[k];
    const Eigen::Index next = level[static_cast<std::size_t>(column)] + 1;
    for (Eigen::SparseMatrix<double>::InnerIterator row(graph.by_column, column); row; ++row)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator to(graph.by_row, row.row()); to; ++to) {
        auto& seen = level[static_cast<std::size_t>(to.col())];
        if (seen >= 0) continue;
        seen = next;
        last = std::max(last, next);
        order.push_back(to.col());
      }
  }
  return last;
}

// Levels of every column: each component from a pseudo-peripheral column (the last one reached
// from its first column), components one after the other.
std::vector<Eigen::Index> column_levels(const ColumnGraph& graph) {
  const Eigen::Index n = graph.by_column.cols();
  std::vector<Eigen::Index> level(static_cast<std::size_t>(n), -1), probe(static_cast<std::size_t>(n), -1);
  std::vector<Eigen::Index> order, probe_order;
  Eigen::Index base = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (level[static_cast<std::size_t>(j)] >= 0) continue;
    probe_order.clear();
    visit_levels(graph, j, 0, probe, probe_order);
    base = visit_levels(graph, probe_order.back(), base, level, order) + 1;
  }
  return level;
}

}  // namespace

ColumnPartition partition_columns(const Eigen::SparseMatrix<double>& a, int parts) {
  ColumnPartition out;
  out.parts = std::max(parts, 1);
  const ColumnGraph graph{a, Eigen::SparseMatrix<double, Eigen::RowMajor>(a)};
  const std::vector<Eigen::Index> level = column_levels(graph);
  const Eigen::Index levels = level.empty() ? 0 : *std::max_element(level.begin(), level.end()) + 1;
  std::vector<Eigen::Index> count(static_cast<std::size_t>(levels), 0);
  for (Eigen::Index l : level) ++count[static_cast<std::size_t>(l)];
  // Separating levels: the first level at which the columns before it reach p/parts of all,
  // at least two levels after the previous separator (a non-empty interior between them) and
  // before the last level (one after it).
  std::vector<Eigen::Index> separators;
  Eigen::Index seen = 0;
  for (Eigen::Index l = 0, p = 1; l + 1 < levels && p < out.parts; ++l) {
    seen += count[static_cast<std::size_t>(l)];
    const bool spaced = separators.empty() ? l >= 1 : l >= separators.back() + 2;
    if (spaced && seen * out.parts >= p * static_cast<Eigen::Index>(level.size())) {
      separators.push_back(l);
      ++p;
    }
  }
  out.column_part.resize(level.size());
  out.column_separator.assign(level.size(), -1);
  for (std::size_t j = 0; j < level.size(); ++j) {
    const auto at = std::lower_bound(separators.begin(), separators.end(), level[j]);
    const bool on_separator = at != separators.end() && *at == level[j];
    out.column_part[j] = on_separator ? ColumnPartition::kInterface : static_cast<int>(at - separators.begin());
    if (on_separator) out.column_separator[j] = static_cast<int>(at - separators.begin());
    if (on_separator) ++out.interface_columns;
  }
  out.row_part.assign(static_cast<std::size_t>(a.rows()), ColumnPartition::kInterface);
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    const int part = out.column_part[static_cast<std::size_t>(j)];
    if (part == ColumnPartition::kInterface) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) out.row_part[static_cast<std::size_t>(it.row())] = part;
  }
  return out;
}

}  // namespace kinestat::distributed
