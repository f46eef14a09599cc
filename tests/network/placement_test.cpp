// SPDX-License-Identifier: BSD-3-Clause
// Placement never changes the answer (issue 12, item 1): every network example, rotated and
// moved by 10, 100 and 1000 times its size with its coordinates at full double precision (as a
// program that places a mechanism in a machine writes them), analysed in floating point, gives
// the FN, CN and pair freedoms of the example itself. The expected answers are the example's
// own (exact where it is given in short decimals): placement is a rigid motion, which changes
// no mobility. Before the rank threshold took the rounding of the input into account, the
// collinear and coplanar special geometry of several examples was lost from 10x on.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "kinestat/network/analyse_network.hpp"
#include "properties/random_network.hpp"
#include "seed_fixture.hpp"

namespace kinestat::network {
namespace {

using screw::Rational;
using screw::Vec3;

Eigen::Vector3d as_double(const Vec3& v) { return {v[0].get_d(), v[1].get_d(), v[2].get_d()}; }
Vec3 as_exact(const Eigen::Vector3d& v) { return {Rational(v.x()), Rational(v.y()), Rational(v.z())}; }

// Size of the model: the largest distance of a coupling point from their centroid (1 if none).
double model_size(const Model& model) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& c : model.couplings) centroid += as_double(c.geometry.point);
  centroid /= static_cast<double>(std::max<std::size_t>(model.couplings.size(), 1));
  double size = 0;
  for (const auto& c : model.couplings) size = std::max(size, (as_double(c.geometry.point) - centroid).norm());
  return size > 0 ? size : 1.0;
}

// The rotation used for planar and for spatial models.
Eigen::Matrix3d placement_rotation(bool planar) {
  return planar ? Eigen::AngleAxisd(0.9, Eigen::Vector3d::UnitZ()).toRotationMatrix()
                : (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitZ()))
                      .toRotationMatrix();
}

// The model rotated by `rotation` and moved by `shift`; every vector rounded to double. Primary
// variables are named by the axes they lie along, so a rotated model drops the user's choice.
Model placed(Model model, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift) {
  model.primary.clear();
  model.values.clear();
  for (auto& c : model.couplings) {
    auto& g = c.geometry;
    g.point = as_exact(rotation * as_double(g.point) + shift);
    for (auto* v : {&g.axis, &g.axis2, &g.normal})
      if (*v) **v = as_exact(rotation * as_double(**v));
  }
  return model;
}

// FN, CN and every pair's fij and cij of `moved` equal those of `base`.
void expect_same_answer(const NetworkResult& moved, const NetworkResult& base) {
  EXPECT_EQ(moved.FN, base.FN);
  EXPECT_EQ(moved.CN, base.CN);
  ASSERT_EQ(moved.pairs.size(), base.pairs.size());
  for (std::size_t k = 0; k < base.pairs.size(); ++k) {
    EXPECT_EQ(moved.pairs[k].fij, base.pairs[k].fij) << "pair " << k;
    EXPECT_EQ(moved.pairs[k].cij, base.pairs[k].cij) << "pair " << k;
  }
}

bool has_custom_screws(const Model& model) {
  for (const auto& c : model.couplings)
    if (!c.geometry.custom_motions.empty() || !c.geometry.custom_actions.empty()) return true;
  return false;
}

TEST(Placement, FarFromTheOriginEveryNetworkExampleKeepsItsAnswer) {
  int checked = 0;
  for (const std::string& name : testing::network_examples()) {
    const io::LoadedNetwork loaded = testing::load_example(name);
    const Model& model = loaded.model;
    if (has_custom_screws(model)) continue;
    SCOPED_TRACE(name);
    const NetworkResult base = analyse_network(model);
    const bool planar = !model.space.is_spatial();
    const Eigen::Matrix3d rotation = placement_rotation(planar);
    const Eigen::Vector3d direction = planar ? Eigen::Vector3d(0.8, -0.6, 0) : Eigen::Vector3d(0.48, -0.6, 0.64);
    AnalysisOptions floating;
    floating.arithmetic = Arithmetic::floating;
    for (double offset : {10.0, 100.0, 1000.0}) {
      SCOPED_TRACE(offset);
      const NetworkResult moved = analyse_network(placed(model, rotation, offset * model_size(model) * direction), floating);
      expect_same_answer(moved, base);
    }
    ++checked;
  }
  EXPECT_GE(checked, 15);  // the network examples without custom screws
}

// The same for the random networks of the property tests (short decimals, analysed exactly):
// rotated and moved by 1000 times their size, at full double precision, in floating point.
// A random network can be close to another answer by chance; those are left out (and counted,
// so that the test cannot pass by leaving out everything).
TEST(Placement, FarFromTheOriginRandomNetworksKeepTheirAnswer) {
  int checked = 0, close = 0;
  for (int seed = 0; seed < 80; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(7000 + seed));
    const bool planar = seed % 2 == 1;
    const Model model = testing::random_network(rng, 2 + seed % 5, 1 + seed % 3, planar);
    SCOPED_TRACE("seed " + std::to_string(seed) + (planar ? " planar" : " spatial"));
    AnalysisOptions exact, floating;
    exact.arithmetic = Arithmetic::exact;
    floating.arithmetic = Arithmetic::floating;
    const NetworkResult base = analyse_network(model, exact);
    const NetworkResult here = analyse_network(model, floating);
    if (here.circulation.solution.rank.close() || here.cutset_law.solution.rank.close()) {
      ++close;
      continue;
    }
    const Eigen::Vector3d direction = planar ? Eigen::Vector3d(0.8, -0.6, 0) : Eigen::Vector3d(0.48, -0.6, 0.64);
    const NetworkResult moved = analyse_network(placed(model, placement_rotation(planar), 1000.0 * model_size(model) * direction), floating);
    expect_same_answer(moved, base);
    ++checked;
  }
  EXPECT_GE(checked, 60) << close << " were close in floating point where they are";
}


// Body motions are reported in the user's frame, whichever frame decides (exact: the user's;
// floating point: centred on the couplings and scaled). Kinematics alone fixes them: across a
// revolute at P, the relative twist (ω; v) of its two bodies (planar: ω about z, v the velocity
// of the point at the user's origin) moves P not at all, v + ω ẑ × P = 0; the ground does not
// move; and the four-bar (FN = 1) moves. Checked for the planar four-bar at its place and moved
// 1000 units away (full-precision coordinates, floating point), grounded on the ground link and
// on the coupler (a body with a larger index than some others).
TEST(Placement, BodyMotionsAreTheUsersAndFixEveryRevolute) {
  for (const char* ground : {"ground", "coupler"})
    for (const double offset : {0.0, 1000.0 + 1.0 / 3.0})
      for (const Arithmetic arithmetic : {Arithmetic::exact, Arithmetic::floating}) {
        if (offset != 0.0 && arithmetic == Arithmetic::exact) continue;
        const auto point = [&](int x, int y) {
          return offset == 0.0 ? fmt::format("[{}, {}]", x, y) : fmt::format("[{:.17g}, {:.17g}]", x + offset, y - offset);
        };
        const io::LoadedNetwork loaded = testing::parse_network(fmt::format(
            "kinestat: 1\nkind: network\nname: four-bar\ndimension: planar\nground: {}\ncouplings:\n"
            "  - {{name: A, type: revolute, between: [ground, crank], point: {}}}\n"
            "  - {{name: B, type: revolute, between: [crank, coupler], point: {}}}\n"
            "  - {{name: C, type: revolute, between: [coupler, rocker], point: {}}}\n"
            "  - {{name: D, type: revolute, between: [rocker, ground], point: {}}}\n",
            ground, point(0, 0), point(1, 2), point(4, 3), point(5, 0)));
        const Model& model = loaded.model;
        SCOPED_TRACE(fmt::format("ground {}, offset {}, {}", ground, offset, arithmetic == Arithmetic::exact ? "exact" : "floating"));
        AnalysisOptions options;
        options.arithmetic = arithmetic;
        const NetworkResult r = analyse_network(model, options);
        ASSERT_EQ(r.FN, 1);
        ASSERT_EQ(r.body_motions.size(), model.bodies.size());
        const auto g = static_cast<std::size_t>(r.ground);
        EXPECT_EQ(model.bodies[g], ground);
        EXPECT_EQ(r.body_motions[g].values.norm(), 0.0);
        double largest = 0.0;
        for (const auto& motion : r.body_motions) {
          ASSERT_EQ(motion.values.rows(), 3);
          ASSERT_EQ(motion.values.cols(), 1);
          largest = std::max(largest, std::abs(motion.values(0, 0)));
        }
        EXPECT_GT(largest, 0.0);
        for (const auto& c : model.couplings) {
          const Eigen::Vector3d twist = r.body_motions[static_cast<std::size_t>(c.to)].values.col(0) -
                                        r.body_motions[static_cast<std::size_t>(c.from)].values.col(0);
          const double px = c.geometry.point[0].get_d(), py = c.geometry.point[1].get_d();
          const double vx = twist(1) - twist(0) * py, vy = twist(2) + twist(0) * px;
          const double scale = largest * (1.0 + std::abs(px) + std::abs(py));
          EXPECT_NEAR(vx, 0.0, 1e-12 * scale) << c.name;
          EXPECT_NEAR(vy, 0.0, 1e-12 * scale) << c.name;
        }
      }
}

}  // namespace
}  // namespace kinestat::network
