// SPDX-License-Identifier: BSD-3-Clause
// The counts-only sparse path factors D(c) in a nested dissection of the node graph when that
// graph keeps enough of D(c)'s column couplings (linalg::grouped_nested_dissection_order,
// linalg::sparse_numerical_rank). Expected shares are counted by hand from the lattices' bars;
// expected counts come from the lattices' geometry (tests/support/lattice_generator.hpp) and,
// for the rotated lattices, from the dense SVD path on the same model.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/linalg/nested_dissection.hpp"
#include "support/lattice_generator.hpp"

namespace kinestat::framework {
namespace {

std::vector<Eigen::Index> column_nodes(const FrameworkResult& prepared) {
  std::vector<Eigen::Index> nodes;
  for (const Eigen::Index coordinate : prepared.partition.dependent_coordinates)
    nodes.push_back(static_cast<Eigen::Index>(prepared.indexing.coordinates[static_cast<std::size_t>(coordinate)].node));
  return nodes;
}

// The model turned by a rotation that leaves no bar along a coordinate axis.
FrameworkModel turned_lattice(FrameworkModel model) {
  const Eigen::Matrix3d turn = model.dimension == 2
                                   ? Eigen::Matrix3d(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()))
                                   : Eigen::Matrix3d(Eigen::AngleAxisd(0.5, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
  for (Node& node : model.nodes) node.position = turn * node.position;
  return model;
}

AnalysisOptions sparse_counts() {
  AnalysisOptions options;
  options.vectors = false;
  options.dense_limit = 0;
  return options;
}

TEST(NodeOrderRank, ShareOfCouplingsKeptByTheNodeGraph) {
  // Planar n × n triangulated grid, bottom row pinned: the bars between free nodes are
  // (n − 1)² horizontal and n(n − 2) vertical ones (1 of the 4 coordinate pairs of their nodes
  // coupled) and (n − 2)(n − 1) diagonals (all 4): at n = 12, 681 / 1404 = 0.485.
  {
    const FrameworkModel model = planar_lattice(12, true);
    FrameworkResult prepared;
    const Eigen::SparseMatrix<double> d = prepare_analysis(model, prepared);
    EXPECT_EQ(linalg::grouped_nested_dissection_order(d, column_nodes(prepared), 0.48).size(), static_cast<std::size_t>(d.cols()));
    EXPECT_TRUE(linalg::grouped_nested_dissection_order(d, column_nodes(prepared), 0.49).empty());
    // Turned: every bar couples all 4 pairs.
    const FrameworkModel turned = turned_lattice(model);
    FrameworkResult turned_prepared;
    const Eigen::SparseMatrix<double> dt = prepare_analysis(turned, turned_prepared);
    EXPECT_EQ(linalg::grouped_nested_dissection_order(dt, column_nodes(turned_prepared), 1.0).size(),
              static_cast<std::size_t>(dt.cols()));
  }
  // Cubic n³ lattice, base pinned: free bars 2(n − 1)²n along x and y and n²(n − 2) along z
  // (1 of 9 pairs), (n − 1)³ diagonals (4 of 9): at n = 5, 491 / 2691 = 0.182.
  {
    const FrameworkModel model = spatial_lattice(5);
    FrameworkResult prepared;
    const Eigen::SparseMatrix<double> d = prepare_analysis(model, prepared);
    EXPECT_EQ(linalg::grouped_nested_dissection_order(d, column_nodes(prepared), 0.18).size(), static_cast<std::size_t>(d.cols()));
    EXPECT_TRUE(linalg::grouped_nested_dissection_order(d, column_nodes(prepared), 0.19).empty());
  }
}

TEST(NodeOrderRank, CountsOfLatticesInEitherOrder) {
  // Triangulated grid (node order, share 0.485 ≥ 0.4): rigid, (n − 1)² self-stresses.
  for (const int n : {12, 30}) {
    const FrameworkResult r = analyse_framework(planar_lattice(n, true), sparse_counts());
    ASSERT_EQ(r.method, RankMethod::sparse_qr);
    EXPECT_EQ(r.mechanisms, 0) << n;
    EXPECT_EQ(r.self_stresses, (n - 1) * (n - 1)) << n;
    EXPECT_FALSE(r.decision.close()) << n;
  }
  // Cubic lattice (METIS, share 0.18): 3(n − 1) mechanisms.
  const FrameworkResult cubic = analyse_framework(spatial_lattice(5), sparse_counts());
  EXPECT_EQ(cubic.mechanisms, 12);
  EXPECT_FALSE(cubic.decision.close());
  // Turned lattices (node order, share 1): the same counts as the dense SVD of the same model.
  for (const FrameworkModel& model : {turned_lattice(planar_lattice(12, true)), turned_lattice(spatial_lattice(5))}) {
    AnalysisOptions dense = sparse_counts();
    dense.dense_limit = 100000;
    const FrameworkResult by_svd = analyse_framework(model, dense);
    const FrameworkResult by_qr = analyse_framework(model, sparse_counts());
    ASSERT_EQ(by_svd.method, RankMethod::dense_svd);
    ASSERT_EQ(by_qr.method, RankMethod::sparse_qr);
    EXPECT_EQ(by_qr.rank, by_svd.rank);
    EXPECT_EQ(by_qr.mechanisms, model.dimension == 2 ? 0 : 12);
    EXPECT_FALSE(by_qr.decision.close());
  }
}

}  // namespace
}  // namespace kinestat::framework
