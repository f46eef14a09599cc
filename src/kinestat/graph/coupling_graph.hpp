// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The coupling graph G_C (seed 000, section 2.3.1): bodies are nodes, couplings are directed
// edges `between: [i, j]` from i to j. Circuits take the orientation of their chord, cutsets
// that of their branch.

#include "kinestat/error.hpp"
#include <Eigen/Core>

#include <stdexcept>
#include <vector>

namespace kinestat::graph {

struct Edge {
  int from = 0;
  int to = 0;
};

/// A spanning tree given by its edges (branches); the other edges are chords. Both lists are
/// in increasing edge order, which is the order of circuits (rows of B) and cutsets (rows of Q).
struct SpanningTree {
  std::vector<int> branches;
  std::vector<int> chords;
};

/// How to reach every body from the root along the tree: bodies in visiting order, the tree
/// edge that reaches each body (-1 for the root) and +1 if that edge points away from the root.
struct TreeWalk {
  std::vector<int> order;
  std::vector<int> parent_edge;
  std::vector<int> parent_body;
  std::vector<int> sign;
};

/// The tree requested by the user is not a spanning tree; the message says why.
class TreeError : public Error {
 public:
  explicit TreeError(const std::string& what, int edge = -1) : Error(what), edge_(edge) {}
  /// The edge that closes a circuit among the non-chords, or -1.
  int edge() const { return edge_; }

 private:
  int edge_ = -1;
};

class CouplingGraph {
 public:
  CouplingGraph(int bodies, std::vector<Edge> edges);

  int bodies() const { return bodies_; }
  int edges() const { return static_cast<int>(edges_.size()); }
  const Edge& edge(int e) const { return edges_[static_cast<std::size_t>(e)]; }

  /// Connected components, each a list of bodies in increasing order; components ordered by
  /// their smallest body.
  std::vector<std::vector<int>> components() const;

  /// Breadth-first spanning tree from `root`, edges taken in increasing order: deterministic.
  SpanningTree breadth_first_tree(int root) const;
  /// The spanning tree whose chords are exactly `chords`. Throws TreeError if the remaining
  /// edges contain a circuit or do not reach every body.
  SpanningTree tree_with_chords(const std::vector<int>& chords) const;

  /// Walk of `tree` from `root`.
  TreeWalk walk(const SpanningTree& tree, int root) const;

  /// Fundamental circuit matrix [B]l,e: +1 / -1 where an edge lies in the circuit with / against
  /// the circuit's sense (the sense of its chord), 0 elsewhere (seed eq. 3a).
  Eigen::MatrixXi circuit_matrix(const SpanningTree& tree) const;
  /// Fundamental cutset matrix [Q]k,e: +1 / -1 where an edge crosses the cutset with / against
  /// the sense of its branch (seed eq. 3b). Q = [I | -B_tree^T] up to column order.
  Eigen::MatrixXi cutset_matrix(const SpanningTree& tree) const;

 private:
  int bodies_;
  std::vector<Edge> edges_;
};

}  // namespace kinestat::graph
