// SPDX-License-Identifier: BSD-3-Clause
// Seed 002, section 3.3: the system of twelve rigid trusses (Fig. 2, Table 2, after
// Pellegrino & Calladine 1986).

#include <gtest/gtest.h>

#include <cmath>

#include "framework_test_support.hpp"

namespace kinestat::framework {
namespace {

using testing::column_of;
using testing::load_example;

TEST(Truss12, JacobianIsTheSeedsMatrix) {
  const FrameworkModel model = load_example("truss-12.yaml");
  const FrameworkIndexing indexing = index_framework(model);
  const FrameworkPartition partition = partition_framework(model, indexing);
  const Eigen::MatrixXd d = Eigen::MatrixXd(dependent_jacobian(model, indexing, partition, deformation_derivative(model, indexing),
                                                               characteristic_length(model)));
  // The 12 x 12 matrix printed in the seed (rows: elements 1-12; columns: x, y, z of E, F, G, H),
  // in units of sqrt(2)/2. Only translations and elongations occur, so the non-dimensional
  // D(c) equals the dimensional one.
  const int seed[12][12] = {
      {+1, 0, +1, 0, 0, 0, 0, 0, 0, 0, 0, 0},   {-1, 0, +1, 0, 0, 0, 0, 0, 0, 0, 0, 0},
      {0, 0, 0, 0, +1, +1, 0, 0, 0, 0, 0, 0},   {0, 0, 0, 0, -1, +1, 0, 0, 0, 0, 0, 0},
      {0, 0, 0, 0, 0, 0, -1, 0, +1, 0, 0, 0},   {0, 0, 0, 0, 0, 0, +1, 0, +1, 0, 0, 0},
      {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, +1},   {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, +1, +1},
      {-1, -1, 0, +1, +1, 0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, +1, -1, 0, -1, +1, 0, 0, 0, 0},
      {0, 0, 0, 0, 0, 0, +1, +1, 0, -1, -1, 0}, {+1, -1, 0, 0, 0, 0, 0, 0, 0, -1, +1, 0}};
  ASSERT_EQ(d.rows(), 12);
  ASSERT_EQ(d.cols(), 12);
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) EXPECT_NEAR(d(i, j), seed[i][j] * std::sqrt(0.5), 1e-15) << i << "," << j;
}

TEST(Truss12, OneMechanismAndOneSelfStressAsInTable2) {
  const FrameworkModel model = load_example("truss-12.yaml");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.m, 12);
  EXPECT_EQ(a.n, 12);
  EXPECT_EQ(a.rank, 11);
  EXPECT_EQ(a.count.grubler_dof(), 0);  // eq (15): "suggesting that the system is a structure"
  EXPECT_TRUE(a.count.square());
  ASSERT_EQ(a.singular_values.size(), 12);
  EXPECT_LT(a.singular_values(11), 1e-14);
  EXPECT_GT(a.decision.gap(), 1e10);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 1);
  EXPECT_FALSE(a.statically_determinate());
  EXPECT_FALSE(a.kinematically_determinate());
  EXPECT_EQ(report::framework_classification(a), "statically indeterminate, kinematically indeterminate");

  // Table 2 (up to sign): E (0, -0.5, 0), F (-0.5, 0, 0), G (0, 0.5, 0), H (0.5, 0, 0).
  ASSERT_EQ(a.modes.size(), 1u);
  const Eigen::VectorXd& v = a.modes[0].velocities;
  const double sign = v(column_of(model, a, "E.y")) < 0 ? 1.0 : -1.0;
  const std::pair<const char*, double> table2[] = {{"E.x", 0},   {"E.y", -0.5}, {"E.z", 0}, {"F.x", -0.5}, {"F.y", 0}, {"F.z", 0},
                                                   {"G.x", 0},   {"G.y", 0.5},  {"G.z", 0}, {"H.x", 0.5},  {"H.y", 0}, {"H.z", 0}};
  for (const auto& [label, value] : table2) EXPECT_NEAR(sign * v(column_of(model, a, label)), value, 1e-12) << label;
  EXPECT_EQ(a.modes[0].moving.size(), 4u);

  // All twelve normal forces ±√3/6, six of each sign.
  ASSERT_EQ(a.stresses.size(), 1u);
  int positive = 0, negative = 0;
  for (Eigen::Index i = 0; i < 12; ++i) {
    const double s = a.stresses[0].resultants(i);
    EXPECT_NEAR(std::abs(s), std::sqrt(3.0) / 6, 1e-12);
    (s > 0 ? positive : negative)++;
  }
  EXPECT_EQ(positive, 6);
  EXPECT_EQ(negative, 6);
  EXPECT_EQ(a.stresses[0].candidates.size(), 12u);  // any truss may be released
}

TEST(Truss12, ProposalGivesAnExactlyConstrainedDesign) {
  const FrameworkModel model = load_example("truss-12.yaml");
  const FrameworkResult a = analyse_framework(model);
  ASSERT_EQ(a.releases.size(), 1u);
  ASSERT_EQ(a.constrain.size(), 1u);
  const FrameworkResult repaired = analyse_framework(apply_proposal(model, a));
  EXPECT_TRUE(repaired.exactly_constrained());
  EXPECT_EQ(repaired.m, 11);
  EXPECT_EQ(repaired.n, 11);
  EXPECT_EQ(repaired.rank, 11);
  EXPECT_GT(repaired.relative_smallest_singular_value(), 1e-3);
}

TEST(Truss12, ReleasingAnyOneTrussRemovesTheSelfStressButNotTheMechanism) {
  // The seed: "The over-constrained condition can be avoided by allowing the elongation in one
  // of the trusses." Every truss carries the self-stress, so any one will do.
  const FrameworkModel model = load_example("truss-12.yaml");
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    FrameworkModel released = model;
    released.elements[e].roles[0] = DeformationRole::released;
    const FrameworkResult a = analyse_framework(released);
    EXPECT_EQ(a.self_stresses, 0) << e;
    EXPECT_EQ(a.mechanisms, 1) << e;
  }
}

}  // namespace
}  // namespace kinestat::framework
