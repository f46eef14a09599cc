// SPDX-License-Identifier: BSD-3-Clause
// The sparse path's modes, stress states and release proposal (null vectors of the sparse R
// factors) against the dense SVD path on every framework example, and against hand-derived
// bases on generated lattices.

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <string>

#include "framework/framework_test_support.hpp"
#include "support/lattice_generator.hpp"

namespace kinestat::framework {
namespace {

Eigen::MatrixXd mode_matrix(const FrameworkResult& a) {
  Eigen::MatrixXd m(a.n, static_cast<Eigen::Index>(a.modes.size()));
  for (std::size_t k = 0; k < a.modes.size(); ++k) m.col(static_cast<Eigen::Index>(k)) = a.modes[k].velocities;
  return m;
}

Eigen::MatrixXd stress_matrix(const FrameworkResult& a) {
  Eigen::MatrixXd m(a.m, static_cast<Eigen::Index>(a.stresses.size()));
  for (std::size_t k = 0; k < a.stresses.size(); ++k) m.col(static_cast<Eigen::Index>(k)) = a.stresses[k].resultants;
  return m;
}

// Numerical rank with a loose relative tolerance: the bases compared are well conditioned.
Eigen::Index loose_rank(const Eigen::MatrixXd& m) {
  if (m.cols() == 0 || m.rows() == 0) return 0;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
  const Eigen::VectorXd s = svd.singularValues();
  Eigen::Index r = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > 1e-7 * s(0)) ++r;
  return r;
}

// Columns of a and b span the same space (both of full column rank).
void expect_same_span(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const std::string& what) {
  ASSERT_EQ(a.cols(), b.cols()) << what;
  ASSERT_EQ(loose_rank(a), a.cols()) << what;
  ASSERT_EQ(loose_rank(b), b.cols()) << what;
  Eigen::MatrixXd both(a.rows(), a.cols() + b.cols());
  both << a, b;
  EXPECT_EQ(loose_rank(both), a.cols()) << what;
}

AnalysisOptions sparse_with_vectors(Eigen::Index k) {
  AnalysisOptions options;
  options.dense_limit = 0;
  options.sparse_vectors = k;
  return options;
}

TEST(SparseVectors, SameSpacesAndAnExactProposalOnEveryExample) {
  for (const char* name : {"braced-square.yaml", "cube-frame.yaml", "folded-sheet-double-clamped.yaml", "folded-sheet-flexure.yaml",
                           "folded-sheet-guide-5-symmetric.yaml", "folded-sheet-guide-5.yaml", "folded-sheet-guide-6.yaml",
                           "four-bar-linkage.yaml", "octahedron.yaml", "pellegrino-calladine-two-bar.yaml",
                           "simplex-tensegrity.yaml", "truss-12.yaml", "wire-flexure-guide.yaml"}) {
    const FrameworkModel model = testing::load_example(name);
    const FrameworkResult dense = analyse_framework(model);
    const FrameworkResult sparse = analyse_framework(model, sparse_with_vectors(1000));
    EXPECT_EQ(sparse.method, RankMethod::sparse_qr) << name;
    EXPECT_TRUE(sparse.vectors) << name;
    ASSERT_EQ(sparse.rank, dense.rank) << name;
    ASSERT_EQ(static_cast<Eigen::Index>(sparse.modes.size()), dense.mechanisms) << name;
    ASSERT_EQ(static_cast<Eigen::Index>(sparse.stresses.size()), dense.self_stresses) << name;
    EXPECT_LT(sparse.null_space_residual, 1e-10) << name;
    // σ_min of the kept block R11 is estimated: at most the smallest kept |R_ii|, and at most
    // σ_rank of D(c) (R11 is a block of R, whose singular values are D(c)'s; the dense path's
    // smallest kept value), up to the estimate's convergence from above.
    if (sparse.rank > 0) {
      EXPECT_TRUE(sparse.decision.factor_estimated) << name;
      EXPECT_LE(sparse.decision.factor_smallest, sparse.decision.smallest_kept * (1.0 + 1e-12)) << name;
      EXPECT_LE(sparse.decision.factor_smallest, dense.decision.smallest_kept * 1.05) << name;
      EXPECT_GT(sparse.decision.factor_smallest, 0.0) << name;
    }
    expect_same_span(mode_matrix(sparse), mode_matrix(dense), std::string(name) + " modes");
    expect_same_span(stress_matrix(sparse), stress_matrix(dense), std::string(name) + " stresses");
    // The proposal may differ from the dense one (another pivoting), but applied it must give
    // an exactly constrained design, by the dense analysis.
    EXPECT_EQ(static_cast<Eigen::Index>(sparse.releases.size()), dense.self_stresses) << name;
    EXPECT_EQ(static_cast<Eigen::Index>(sparse.constrain.size()), dense.mechanisms) << name;
    EXPECT_TRUE(analyse_framework(apply_proposal(model, sparse)).exactly_constrained()) << name;
  }
}

TEST(SparseVectors, SquareLatticeModesAreTheShearsOfItsRows) {
  // n × n square grid, bottom row pinned: the only motions are the horizontal shears of the
  // rows of vertical bars (all nodes of rows j and above move in x alike, j = 1 … n − 1), and
  // the only self-stresses are the n − 1 bars between pinned nodes (zero rows of D(c)).
  const int n = 9;
  const FrameworkModel model = planar_lattice(n, false);
  const FrameworkResult a = analyse_framework(model, sparse_with_vectors(100));
  ASSERT_EQ(a.mechanisms, n - 1);
  ASSERT_EQ(a.self_stresses, n - 1);
  Eigen::MatrixXd shears = Eigen::MatrixXd::Zero(a.n, n - 1);
  for (int j = 1; j < n; ++j)
    for (int row = j; row < n; ++row)
      for (int col = 0; col < n; ++col)
        shears(testing::column_of(model, a, "n" + std::to_string(row * n + col) + ".x"), j - 1) = 1.0;
  expect_same_span(mode_matrix(a), shears, "shears");
  Eigen::MatrixXd pinned = Eigen::MatrixXd::Zero(a.m, n - 1);
  Eigen::Index found = 0;
  for (Eigen::Index i = 0; i < a.m; ++i) {
    const Element& bar = model.elements[a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(i)])].element];
    if (bar.nodes[0] < static_cast<std::size_t>(n) && bar.nodes[1] < static_cast<std::size_t>(n)) pinned(i, found++) = 1.0;
  }
  ASSERT_EQ(found, n - 1);
  expect_same_span(stress_matrix(a), pinned, "pinned bars");
}

TEST(SparseVectors, TriangulatedLatticeStressesAreInEquilibrium) {
  // Rigid, (n − 1)² self-stresses; ask for the first 7 only. Each must be a set of bar forces
  // in equilibrium at every free node: Σ t_e u_e = 0, u_e the unit vector along bar e pointing
  // away from the node (checked from the geometry, not from D(c)).
  const int n = 12;
  const FrameworkModel model = planar_lattice(n, true);
  const FrameworkResult a = analyse_framework(model, sparse_with_vectors(7));
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.self_stresses, (n - 1) * (n - 1));
  ASSERT_EQ(a.stresses.size(), 7u);
  EXPECT_TRUE(a.modes.empty());
  for (const StressState& state : a.stresses) {
    std::vector<Eigen::Vector3d> force(model.nodes.size(), Eigen::Vector3d::Zero());
    for (Eigen::Index i = 0; i < a.m; ++i) {
      const Element& bar = model.elements[a.indexing.deformations[static_cast<std::size_t>(a.rows[static_cast<std::size_t>(i)])].element];
      const Eigen::Vector3d u =
          (model.nodes[bar.nodes[1]].position - model.nodes[bar.nodes[0]].position).normalized();
      force[bar.nodes[0]] += state.resultants(i) * u;
      force[bar.nodes[1]] -= state.resultants(i) * u;
    }
    EXPECT_NEAR(state.resultants.norm(), 1.0, 1e-12);
    for (std::size_t k = static_cast<std::size_t>(n); k < model.nodes.size(); ++k) EXPECT_LT(force[k].norm(), 1e-10);
  }
}

TEST(SparseVectors, SpatialLatticeCountsAndModes) {
  // n³ cubic lattice, base pinned, triangulated horizontal faces: 3(n − 1) mechanisms (each
  // layer moves as a plate over the vertical bars below it); every mode is a null vector.
  const int n = 5;
  const FrameworkModel model = spatial_lattice(n);
  const FrameworkResult a = analyse_framework(model, sparse_with_vectors(1000));
  EXPECT_EQ(a.mechanisms, 3 * (n - 1));
  EXPECT_EQ(static_cast<Eigen::Index>(a.modes.size()), 3 * (n - 1));
  EXPECT_LT(a.null_space_residual, 1e-10);
  EXPECT_TRUE(analyse_framework(apply_proposal(model, a)).exactly_constrained());
}

}  // namespace
}  // namespace kinestat::framework
