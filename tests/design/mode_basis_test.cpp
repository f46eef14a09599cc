// SPDX-License-Identifier: BSD-3-Clause
// Issue 35, item 4: clean mode spaces. A model free in space has six rigid motions (three
// translations, three rotations: by hand), named first and kept apart; the internal modes are
// orthonormal and orthogonal to them, and only they carry `order` and `cause`. Checked on
// Bricard's octahedron (6 rigid motions + 1 finite flex, Bricard 1897) and the simplex tensegrity
// (6 rigid motions + 1 infinitesimal mode, stiffened by its prestress): the rigid motions are
// built here by hand from the node positions, independently of the analysis.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <string>
#include <vector>

#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/io/model_file.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;

struct Analysed {
  framework::FrameworkModel model;
  framework::FrameworkResult result;
};

Analysed analysed(const std::string& file) {
  const io::ModelFile loaded = io::read_model_file(example_path(file));
  EXPECT_TRUE(loaded.framework.has_value());
  Analysed a{*loaded.framework, {}};
  a.result = framework::analyse_framework_as_reported(a.model, {});
  return a;
}

// The six rigid motions of a free spatial truss by hand, on the columns of D(c) (node x, y, z):
// translations e_k, and rotations e_k x (p - c) about axes through the centroid c.
Eigen::MatrixXd rigid_by_hand(const Analysed& a) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& node : a.model.nodes) c += node.position;
  c /= static_cast<double>(a.model.nodes.size());
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(a.result.n, 6);
  for (Eigen::Index j = 0; j < a.result.n; ++j) {
    const auto& ref = a.result.indexing.coordinates[static_cast<std::size_t>(a.result.partition.dependent_coordinates[static_cast<std::size_t>(j)])];
    const Eigen::Vector3d arm = a.model.nodes[ref.node].position - c;
    g(j, ref.slot) = 1.0;
    for (int axis = 0; axis < 3; ++axis) g(j, 3 + axis) = Eigen::Vector3d::Unit(axis).cross(arm)(ref.slot);
  }
  return g;
}

void expect_clean_basis(const std::string& file, framework::MotionOrder internal_order) {
  SCOPED_TRACE(file);
  const Analysed a = analysed(file);
  const auto& modes = a.result.modes;
  ASSERT_EQ(modes.size(), 7u);  // 6 rigid + 1 internal
  for (std::size_t k = 0; k < 6; ++k) EXPECT_FALSE(modes[k].rigid_motion.empty()) << k;
  EXPECT_TRUE(modes[6].rigid_motion.empty());
  EXPECT_EQ(modes[0].rigid_motion, "translation along x");
  // The first six span exactly the hand-built rigid motions; the seventh is orthogonal to them.
  const Eigen::MatrixXd g = rigid_by_hand(a);
  Eigen::MatrixXd basis(a.result.n, 7);
  for (Eigen::Index k = 0; k < 7; ++k) basis.col(k) = modes[static_cast<std::size_t>(k)].velocities.normalized();
  const Eigen::MatrixXd gq = Eigen::HouseholderQR<Eigen::MatrixXd>(g).householderQ() * Eigen::MatrixXd::Identity(a.result.n, 6);
  for (Eigen::Index k = 0; k < 6; ++k) EXPECT_LT((basis.col(k) - gq * (gq.transpose() * basis.col(k))).norm(), 1e-9) << k;
  EXPECT_LT((gq.transpose() * basis.col(6)).norm(), 1e-9);
  // Numerically full rank: the normalised basis's smallest singular value at least 0.1.
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(basis).singularValues();
  EXPECT_GE(sigma(6), 0.1);
  ASSERT_EQ(a.result.orders.size(), 7u);
  EXPECT_EQ(a.result.orders[6].order, internal_order);

  // JSON: the rigid motions named, without order or cause; the internal mode with both.
  const auto run = run_cli("analyze " + example_path(file) + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["modes"].size(), 7u);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_TRUE(j["modes"][k].contains("rigid_motion"));
    EXPECT_FALSE(j["modes"][k].contains("order"));
    EXPECT_FALSE(j["modes"][k].contains("cause"));
  }
  EXPECT_EQ(j["modes"][6]["order"], framework::motion_order_name(internal_order));
  EXPECT_EQ(j["modes"][6]["cause"], "geometry");
  EXPECT_EQ(j["verdict"]["states"][0]["description"], "no supports: 6 rigid motions");
}

TEST(ModeBasis, BricardOctahedronHasSixRigidMotionsAndOneFiniteFlex) {
  expect_clean_basis("bricard-octahedron.yaml", framework::MotionOrder::finite);
}

TEST(ModeBasis, SimplexTensegrityHasNoSupportsAndOneInfinitesimalMode) {
  expect_clean_basis("simplex-tensegrity.yaml", framework::MotionOrder::infinitesimal);
}

}  // namespace
}  // namespace kinestat
