#include "kinestat/linalg/nested_dissection.hpp"

#include <cholmod.h>

#include <algorithm>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>

namespace kinestat::linalg {

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

}  // namespace kinestat::linalg
