// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/graph/coupling_graph.hpp"

#include <algorithm>
#include <deque>
#include <numeric>
#include <string>

namespace kinestat::graph {

namespace {

// Union-find over bodies, for components and for checking that a tree has no circuit.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<std::size_t>(n)) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[static_cast<std::size_t>(x)] != x) {
      parent_[static_cast<std::size_t>(x)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(x)])];
      x = parent_[static_cast<std::size_t>(x)];
    }
    return x;
  }
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    return true;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace

CouplingGraph::CouplingGraph(int bodies, std::vector<Edge> edges) : bodies_(bodies), edges_(std::move(edges)) {}

std::vector<std::vector<int>> CouplingGraph::components() const {
  DisjointSets sets(bodies_);
  for (const Edge& e : edges_) sets.unite(e.from, e.to);
  std::vector<std::vector<int>> result;
  std::vector<int> index_of_root(static_cast<std::size_t>(bodies_), -1);
  for (int b = 0; b < bodies_; ++b) {
    const int root = sets.find(b);
    int& index = index_of_root[static_cast<std::size_t>(root)];
    if (index < 0) {
      index = static_cast<int>(result.size());
      result.emplace_back();
    }
    result[static_cast<std::size_t>(index)].push_back(b);
  }
  return result;
}

SpanningTree CouplingGraph::breadth_first_tree(int root) const {
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(bodies_));
  for (int e = 0; e < edges(); ++e) {
    incident[static_cast<std::size_t>(edge(e).from)].push_back(e);
    incident[static_cast<std::size_t>(edge(e).to)].push_back(e);
  }
  std::vector<bool> reached(static_cast<std::size_t>(bodies_), false), in_tree(edges_.size(), false);
  std::deque<int> queue{root};
  reached[static_cast<std::size_t>(root)] = true;
  while (!queue.empty()) {
    const int body = queue.front();
    queue.pop_front();
    for (int e : incident[static_cast<std::size_t>(body)]) {
      const int other = edge(e).from == body ? edge(e).to : edge(e).from;
      if (reached[static_cast<std::size_t>(other)]) continue;
      reached[static_cast<std::size_t>(other)] = true;
      in_tree[static_cast<std::size_t>(e)] = true;
      queue.push_back(other);
    }
  }
  SpanningTree tree;
  for (int e = 0; e < edges(); ++e) (in_tree[static_cast<std::size_t>(e)] ? tree.branches : tree.chords).push_back(e);
  return tree;
}

SpanningTree CouplingGraph::tree_with_chords(const std::vector<int>& chords) const {
  std::vector<bool> is_chord(edges_.size(), false);
  for (int c : chords) is_chord[static_cast<std::size_t>(c)] = true;
  DisjointSets sets(bodies_);
  SpanningTree tree;
  for (int e = 0; e < edges(); ++e) {
    if (is_chord[static_cast<std::size_t>(e)]) {
      tree.chords.push_back(e);
    } else {
      if (!sets.unite(edge(e).from, edge(e).to))
        throw TreeError("the couplings that are not chords contain a circuit", e);
      tree.branches.push_back(e);
    }
  }
  if (static_cast<int>(tree.branches.size()) != bodies_ - 1)
    throw TreeError("the couplings that are not chords do not connect every body");
  return tree;
}

TreeWalk CouplingGraph::walk(const SpanningTree& tree, int root) const {
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(bodies_));
  for (int e : tree.branches) {
    incident[static_cast<std::size_t>(edge(e).from)].push_back(e);
    incident[static_cast<std::size_t>(edge(e).to)].push_back(e);
  }
  TreeWalk w;
  w.parent_edge.assign(static_cast<std::size_t>(bodies_), -1);
  w.parent_body.assign(static_cast<std::size_t>(bodies_), -1);
  w.sign.assign(static_cast<std::size_t>(bodies_), 0);
  std::vector<bool> reached(static_cast<std::size_t>(bodies_), false);
  std::deque<int> queue{root};
  reached[static_cast<std::size_t>(root)] = true;
  while (!queue.empty()) {
    const int body = queue.front();
    queue.pop_front();
    w.order.push_back(body);
    for (int e : incident[static_cast<std::size_t>(body)]) {
      const int other = edge(e).from == body ? edge(e).to : edge(e).from;
      if (reached[static_cast<std::size_t>(other)]) continue;
      reached[static_cast<std::size_t>(other)] = true;
      w.parent_edge[static_cast<std::size_t>(other)] = e;
      w.parent_body[static_cast<std::size_t>(other)] = body;
      w.sign[static_cast<std::size_t>(other)] = edge(e).from == body ? 1 : -1;
      queue.push_back(other);
    }
  }
  return w;
}

Eigen::MatrixXi CouplingGraph::circuit_matrix(const SpanningTree& tree) const {
  const TreeWalk w = walk(tree, 0);
  std::vector<int> depth(static_cast<std::size_t>(bodies_), 0);
  for (int body : w.order)
    if (w.parent_body[static_cast<std::size_t>(body)] >= 0)
      depth[static_cast<std::size_t>(body)] = depth[static_cast<std::size_t>(w.parent_body[static_cast<std::size_t>(body)])] + 1;

  Eigen::MatrixXi b = Eigen::MatrixXi::Zero(static_cast<Eigen::Index>(tree.chords.size()), edges());
  for (std::size_t row = 0; row < tree.chords.size(); ++row) {
    const int chord = tree.chords[row];
    b(static_cast<Eigen::Index>(row), chord) = 1;
    // The circuit runs from the chord's head back to its tail through the tree. Edges climbed
    // from the head side are traversed child -> parent; those from the tail side parent -> child.
    int head = edge(chord).to, tail = edge(chord).from;
    while (head != tail) {
      if (depth[static_cast<std::size_t>(head)] >= depth[static_cast<std::size_t>(tail)]) {
        const int e = w.parent_edge[static_cast<std::size_t>(head)];
        b(static_cast<Eigen::Index>(row), e) = edge(e).from == head ? 1 : -1;
        head = w.parent_body[static_cast<std::size_t>(head)];
      } else {
        const int e = w.parent_edge[static_cast<std::size_t>(tail)];
        b(static_cast<Eigen::Index>(row), e) = edge(e).to == tail ? 1 : -1;
        tail = w.parent_body[static_cast<std::size_t>(tail)];
      }
    }
  }
  return b;
}

Eigen::MatrixXi CouplingGraph::cutset_matrix(const SpanningTree& tree) const {
  const Eigen::MatrixXi b = circuit_matrix(tree);
  Eigen::MatrixXi q = Eigen::MatrixXi::Zero(static_cast<Eigen::Index>(tree.branches.size()), edges());
  for (std::size_t row = 0; row < tree.branches.size(); ++row) {
    const int branch = tree.branches[row];
    q(static_cast<Eigen::Index>(row), branch) = 1;
    for (std::size_t c = 0; c < tree.chords.size(); ++c)
      q(static_cast<Eigen::Index>(row), tree.chords[c]) = -b(static_cast<Eigen::Index>(c), branch);
  }
  return q;
}

}  // namespace kinestat::graph
