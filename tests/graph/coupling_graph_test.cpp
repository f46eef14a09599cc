// SPDX-License-Identifier: BSD-3-Clause
// The coupling graph of seed 000 (section 2.3.1) on a ring of four bodies, every matrix derived
// by hand: bodies 0-3, couplings a: 0→1, b: 1→2, c: 2→3, d: 3→0.
#include <gtest/gtest.h>

#include <vector>

#include "kinestat/graph/coupling_graph.hpp"

namespace kinestat::graph {
namespace {

CouplingGraph four_bar_ring() { return CouplingGraph(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}); }

TEST(CouplingGraph, BreadthFirstTreeTakesEdgesInOrder) {
  // From body 0: a reaches 1 and d reaches 3, then b reaches 2; c closes the one circuit.
  const SpanningTree tree = four_bar_ring().breadth_first_tree(0);
  EXPECT_EQ(tree.branches, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(tree.chords, (std::vector<int>{2}));
}

TEST(CouplingGraph, CircuitMatrixFollowsTheChord) {
  // The circuit of chord c runs 2→3 (c), 3→0 (d), 0→1 (a), 1→2 (b): every coupling with it.
  const CouplingGraph g = four_bar_ring();
  const Eigen::MatrixXi b = g.circuit_matrix(g.breadth_first_tree(0));
  Eigen::MatrixXi expected(1, 4);
  expected << 1, 1, 1, 1;
  EXPECT_EQ(b, expected);
}

TEST(CouplingGraph, CutsetMatrixFollowsTheBranches) {
  // Cutting branch a separates {0, 3} from {1, 2}: a crosses with it, c (2→3) against it.
  // Cutting b separates {2}: b with it, c against. Cutting d separates {3}: d with it (3→0),
  // c (into 3) against. Every cutset meets the circuit twice, once each way: B Qᵀ = 0.
  const CouplingGraph g = four_bar_ring();
  const SpanningTree tree = g.breadth_first_tree(0);
  const Eigen::MatrixXi q = g.cutset_matrix(tree);
  Eigen::MatrixXi expected(3, 4);
  expected << 1, 0, -1, 0,  //
      0, 1, -1, 0,          //
      0, 0, -1, 1;
  EXPECT_EQ(q, expected);
  EXPECT_TRUE((g.circuit_matrix(tree) * q.transpose()).isZero());
}

TEST(CouplingGraph, ChosenChordsAndTheirErrors) {
  const CouplingGraph g = four_bar_ring();
  const SpanningTree tree = g.tree_with_chords({0});
  EXPECT_EQ(tree.branches, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(tree.chords, (std::vector<int>{0}));
  // No chord: the four couplings close a circuit; two chords: body 1 or 2 is cut off.
  EXPECT_THROW(g.tree_with_chords({}), TreeError);
  EXPECT_THROW(g.tree_with_chords({0, 1}), TreeError);
}

TEST(CouplingGraph, ComponentsInOrderOfTheirSmallestBody) {
  const CouplingGraph g(5, {{3, 1}, {4, 2}});
  EXPECT_EQ(g.components(), (std::vector<std::vector<int>>{{0}, {1, 3}, {2, 4}}));
}

TEST(CouplingGraph, WalkFromTheGround) {
  // Body 1 is reached by a (pointing away from body 0), 2 by b (away), 3 by d (3→0: towards).
  const CouplingGraph g = four_bar_ring();
  const TreeWalk walk = g.walk(g.breadth_first_tree(0), 0);
  ASSERT_EQ(walk.order.size(), 4U);
  EXPECT_EQ(walk.order.front(), 0);
  EXPECT_EQ(walk.parent_edge, (std::vector<int>{-1, 0, 1, 3}));
  EXPECT_EQ(walk.parent_body[1], 0);
  EXPECT_EQ(walk.parent_body[2], 1);
  EXPECT_EQ(walk.parent_body[3], 0);
  EXPECT_EQ(walk.sign[1], 1);
  EXPECT_EQ(walk.sign[2], 1);
  EXPECT_EQ(walk.sign[3], -1);
}

}  // namespace
}  // namespace kinestat::graph
