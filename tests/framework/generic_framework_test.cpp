// SPDX-License-Identifier: BSD-3-Clause
// The generic answer of frameworks (issue 12, item 3) and Laman's count by the pebble game.
// Expected numbers come from Maxwell's rule, Laman's theorem and the geometry of each example,
// derived in the comments.
#include <gtest/gtest.h>

#include <algorithm>

#include "framework_test_support.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/framework/mode_order.hpp"
#include "kinestat/framework/pebble_game.hpp"
#include "support/lattice_generator.hpp"

namespace kinestat::framework {
namespace {

using linalg::Cause;
using testing::load_example;

long count(const std::vector<Cause>& causes, Cause cause) { return std::count(causes.begin(), causes.end(), cause); }

GenericFramework generic_of(const FrameworkModel& model, const FrameworkResult& a) {
  const auto g = generic_framework(model, a);
  EXPECT_TRUE(g.has_value());
  return g.value_or(GenericFramework{});
}

// Seed 002's twelve trusses: 4 free nodes (12 coordinates), 12 bars, Maxwell 12 - 12 = 0. Every
// subset of k free nodes has at most 3k bars to the rest, and the given mechanism/self-stress
// pair needs the symmetric "square over square" geometry (Pellegrino & Calladine 1986): a
// generic realisation is isostatic. So the one mode and the one self-stress are geometric.
TEST(GenericFramework, TwelveBarTrussModeAndStressAreGeometric) {
  const FrameworkModel model = load_example("truss-12.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 1);
  ASSERT_EQ(a.self_stresses, 1);
  const GenericFramework g = generic_of(model, a);
  EXPECT_TRUE(g.exact);
  EXPECT_EQ(g.mechanisms, 0);
  EXPECT_EQ(g.self_stresses, 0);
  EXPECT_EQ(g.mode_causes, std::vector<Cause>{Cause::geometry});
  EXPECT_EQ(g.stress_causes, std::vector<Cause>{Cause::geometry});
  EXPECT_FALSE(g.laman.has_value());  // spatial: no Laman count
}

// The simplex tensegrity: its graph is the octahedron's (two triangles and six side bars), a
// triangulated sphere, generically rigid (Gluck 1975) and isostatic: 12 = 3 * 6 - 6. So a
// random realisation has the 6 rigid-body motions and no self-stress; at the 150-degree twist
// one extra mode and one self-stress exist (the prestress): both geometric.
TEST(GenericFramework, TensegrityPrismOneModeAndOneStressFromGeometry) {
  const FrameworkModel model = load_example("simplex-tensegrity.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 7);
  ASSERT_EQ(a.self_stresses, 1);
  const GenericFramework g = generic_of(model, a);
  EXPECT_EQ(g.mechanisms, 6);
  EXPECT_EQ(g.self_stresses, 0);
  EXPECT_EQ(count(g.mode_causes, Cause::topology), 6);
  EXPECT_EQ(count(g.mode_causes, Cause::geometry), 1);
  EXPECT_EQ(g.stress_causes, std::vector<Cause>{Cause::geometry});
  // The six persisting modes are the rigid-body motions; the re-chosen basis puts them first,
  // each within rounding of the persisting subspace, and every one is a rigid motion: its
  // velocities are v = w x p + t at every node (checked by solving for w and t).
  EXPECT_LT(g.split_residual, 1e-3);
  ASSERT_TRUE(g.mode_basis.has_value());
  const FrameworkResult rebased = with_generic_basis(model, a, g);
  ASSERT_EQ(rebased.modes.size(), 7U);
  for (std::size_t k = 0; k < 7; ++k) {
    // Least-squares fit of a rigid motion (w, t) to the 6 nodes' velocities (in D̂ units).
    Eigen::MatrixXd fit(18, 6);
    Eigen::VectorXd v(18);
    for (std::size_t node = 0; node < 6; ++node) {
      const Eigen::Vector3d p = model.nodes[node].position / a.length;
      for (int i = 0; i < 3; ++i) {
        const auto row = static_cast<Eigen::Index>(3 * node) + i;
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e(i) = 1;
        fit.row(row) << p.cross(e).transpose(), e.transpose();  // (w x p)_i = w . (p x e_i)
        v(row) = rebased.modes[k].velocities(row);
      }
    }
    const Eigen::VectorXd x = fit.colPivHouseholderQr().solve(v);
    const double misfit = (fit * x - v).norm();
    if (g.mode_causes[k] == Cause::topology) EXPECT_LT(misfit, 1e-4) << "mode " << k + 1;
    else EXPECT_GT(misfit, 0.1) << "mode " << k + 1;
  }
  // The second-order orders follow the re-chosen modes: the geometric mode is the tensegrity's
  // infinitesimal mechanism, blocked by its prestress (the simplex is prestress stable: Connelly
  // and Whiteley 1996). (The topological modes are rigid motions only to the 1e-4 above, which
  // the second-order test does not take for exact rigid motions; not asserted.)
  ASSERT_EQ(rebased.orders.size(), 7U);
  for (std::size_t k = 0; k < 7; ++k) {
    if (g.mode_causes[k] == Cause::geometry) {
      EXPECT_EQ(rebased.orders[k].order, MotionOrder::infinitesimal) << "mode " << k + 1;
    }
  }
}

// The collinear two-bar (Pellegrino & Calladine): C between pinned A and B on one line. Laman:
// 2 bars on 2 free coordinates, independent in general position: rigid, no self-stress; the
// mode (C moving across) and the self-stress both need the collinearity. The pebble game
// puts C with the ground in one rigid component.
TEST(GenericFramework, CollinearTwoBarIsSpecialAndLamanAgrees) {
  const FrameworkModel model = load_example("pellegrino-calladine-two-bar.yaml");
  const FrameworkResult a = analyse_framework(model);
  const GenericFramework g = generic_of(model, a);
  EXPECT_EQ(g.mechanisms, 0);
  EXPECT_EQ(g.self_stresses, 0);
  ASSERT_TRUE(g.laman.has_value());
  EXPECT_EQ(g.laman->rank, 2);
  EXPECT_EQ(g.laman->rank, g.rank);
  ASSERT_EQ(g.laman->rigid_components.size(), 1U);
  EXPECT_TRUE(g.laman->rigid_components[0].ground);
  EXPECT_EQ(g.laman->rigid_components[0].nodes.size(), 3U);
}

// A triangulated n x n lattice with the bottom row pinned (tests/support): 2n(n-1) free
// coordinates; bars: (n-1)^2 horizontal and n(n-1) vertical and (n-1)^2 diagonal ones touching
// free nodes, plus n - 1 between pinned nodes: (n-1)(3n-1) rows. Rigid, so by Maxwell's rule
// (n-1)(3n-1) - 2n(n-1) = (n-1)^2 self-stresses. Its rank is full at the
// given (regular) geometry, and no realisation has a larger one, so the generic answer is the
// same and every self-stress is topological; Laman's count says the same and finds one rigid
// component: all nodes with the ground.
TEST(GenericFramework, LamanRigidLatticeIsGeneric) {
  const int n = 4;
  const FrameworkModel model = planar_lattice(n, true);
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, 0);
  ASSERT_EQ(a.self_stresses, (n - 1) * (n - 1));
  const GenericFramework g = generic_of(model, a);
  EXPECT_EQ(g.mechanisms, 0);
  EXPECT_EQ(g.self_stresses, (n - 1) * (n - 1));
  EXPECT_EQ(count(g.stress_causes, Cause::topology), (n - 1) * (n - 1));
  ASSERT_TRUE(g.laman.has_value());
  EXPECT_EQ(g.laman->rank, 2 * n * (n - 1));
  EXPECT_EQ(g.laman->self_stresses, (n - 1) * (n - 1));
  ASSERT_EQ(g.laman->rigid_components.size(), 1U);
  EXPECT_TRUE(g.laman->rigid_components[0].ground);
  EXPECT_EQ(g.laman->rigid_components[0].nodes.size(), static_cast<std::size_t>(n * n));
}

// The square grid without diagonals, bottom row pinned: built row by row, each new row is a
// path of n nodes (n - 1 bars) hung on n vertical bars: 2n - 1 bars on 2n coordinates, no part
// overbraced, so generically independent: n - 1 mechanisms (one per row), and the n - 1 bars
// between pinned nodes are self-stresses for any geometry. All of them topological.
TEST(GenericFramework, SquareGridMechanismsAreTopological) {
  const int n = 5;
  const FrameworkModel model = planar_lattice(n, false);
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.mechanisms, n - 1);
  const GenericFramework g = generic_of(model, a);
  EXPECT_EQ(g.mechanisms, n - 1);
  EXPECT_EQ(g.self_stresses, n - 1);
  EXPECT_EQ(count(g.mode_causes, Cause::topology), n - 1);
  EXPECT_EQ(count(g.stress_causes, Cause::topology), n - 1);
  ASSERT_TRUE(g.laman.has_value());
  EXPECT_EQ(g.laman->mechanisms, n - 1);
  EXPECT_EQ(g.laman->rank, g.rank);
}

// Pebble game on small graphs whose Laman counts are known by hand.
TEST(PebbleGame, TriangleIsRigid) {
  const PebbleGame game = pebble_game(3, {{0, 1}, {1, 2}, {2, 0}});
  EXPECT_EQ(game.independent, 3U);
  EXPECT_TRUE(game.redundant.empty());
  EXPECT_EQ(game.rigid_components, (std::vector<std::vector<std::size_t>>{{0, 1, 2}}));
}

TEST(PebbleGame, CompleteGraphOnFourHasOneRedundantBar) {
  // K4 in the plane: 6 bars, 2 * 4 - 3 = 5 independent; the last bar inserted is redundant.
  const PebbleGame game = pebble_game(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}});
  EXPECT_EQ(game.independent, 5U);
  EXPECT_EQ(game.redundant, std::vector<std::size_t>{5});
  EXPECT_EQ(game.rigid_components.size(), 1U);
}

TEST(PebbleGame, QuadrilateralHasFourComponents) {
  // A four-bar loop: 4 bars, all independent, one degree of freedom; each bar is its own
  // rigid component.
  const PebbleGame game = pebble_game(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  EXPECT_EQ(game.independent, 4U);
  EXPECT_EQ(game.rigid_components.size(), 4U);
}

TEST(PebbleGame, TwoTrianglesSharingAVertexAreTwoComponents) {
  const PebbleGame game = pebble_game(5, {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 4}, {4, 2}});
  EXPECT_EQ(game.independent, 6U);
  EXPECT_EQ(game.rigid_components, (std::vector<std::vector<std::size_t>>{{0, 1, 2}, {2, 3, 4}}));
}

}  // namespace
}  // namespace kinestat::framework
