#pragma once
// A fill-reducing nested-dissection ordering of an undirected graph (METIS, through CHOLMOD):
// for sparse factorisations whose unknowns come in blocks attached to the vertices of a small
// graph (the bodies of a coupling network), ordering the graph costs a fraction of ordering
// the expanded matrix.

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace kinestat::linalg {

/// Nested-dissection order of the `vertices` vertices of an undirected graph given by its
/// `edges` (pairs of vertex indices in [0, vertices); loops and repeated edges are ignored):
/// order[k] is the vertex placed k-th, separators after the parts they separate, postordered
/// by the elimination tree. METIS_NodeND with CHOLMOD's default options (deterministic: the
/// same graph gives the same order on every run). Throws std::bad_alloc when out of memory.
std::vector<Eigen::Index> nested_dissection_order(Eigen::Index vertices,
                                                  const std::vector<std::pair<Eigen::Index, Eigen::Index>>& edges);

}  // namespace kinestat::linalg
