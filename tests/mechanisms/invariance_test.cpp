// SPDX-License-Identifier: BSD-3-Clause
// FN, CN and every pair's fij and cij are properties of the mechanism, not of its
// description: they must not change under a rigid motion of all geometry, a change of
// length unit, renaming and reordering of bodies and couplings, another spanning tree, or
// exact versus floating-point arithmetic. Each case also checks the published FN and CN.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kinestat/network/analyse_network.hpp"
#include "model_transforms.hpp"

namespace kinestat::mechanisms_test {
namespace {

using network::Arithmetic;

struct Published {
  std::string file;
  int FN, CN;  // from the source cited in the file (see published_mechanisms_test.cpp)
};

std::ostream& operator<<(std::ostream& os, const Published& p) { return os << p.file; }

const std::vector<Published> kMechanisms = {
    {"davies-2-circuit.yaml", 3, 2},  {"single-circuit-two-spheres.yaml", 1, 1},
    {"four-bar-planar.yaml", 1, 0},   {"four-bar-spatial.yaml", 1, 3},
    {"slider-crank-planar.yaml", 1, 0},      {"bennett.yaml", 1, 3},
    {"bennett-perturbed.yaml", 0, 2}, {"spherical-4r.yaml", 1, 3},
    {"stewart-6ups.yaml", 6, 0},      {"sarrus.yaml", 1, 1},
    {"parallelogram.yaml", 1, 0},     {"parallelogram-redundant.yaml", 1, 1},
    {"tsai-3upu.yaml", 3, 0},         {"screw-jack.yaml", 1, 4},
};

network::NetworkResult analyse_model(const network::Model& model, Arithmetic arithmetic = Arithmetic::automatic) {
  network::AnalysisOptions options;
  options.arithmetic = arithmetic;
  return network::analyse_network(model, options);
}

class Invariance : public ::testing::TestWithParam<Published> {
 protected:
  void SetUp() override {
    model_ = load_example(GetParam().file);
    reference_ = analyse_model(model_);
    ASSERT_EQ(reference_.FN, GetParam().FN);
    ASSERT_EQ(reference_.CN, GetParam().CN);
  }

  // Same FN, CN, F, C, l, k and pair table as the untransformed model.
  void expect_same(const network::Model& model, const network::NetworkResult& r, bool renamed = false) const {
    EXPECT_EQ(r.FN, GetParam().FN);
    EXPECT_EQ(r.CN, GetParam().CN);
    EXPECT_EQ(r.F, reference_.F);
    EXPECT_EQ(r.C, reference_.C);
    EXPECT_EQ(r.l, reference_.l);
    EXPECT_EQ(r.k, reference_.k);
    EXPECT_TRUE(r.identities_hold);
    EXPECT_TRUE(r.motion_methods_agree);
    EXPECT_TRUE(r.action_methods_agree);
    EXPECT_EQ(pair_table(model, r, renamed), pair_table(model_, reference_));
  }

  bool planar() const { return model_.space.is_planar(); }

  network::Model model_;
  network::NetworkResult reference_;
};

TEST_P(Invariance, RigidMotionWithRationalRotation) {
  // Quaternion (1, 2, 3, 4): an exact rational rotation (entries over 30) about a skew axis;
  // planar models turn about z by the 3-4-5 angle.
  const Matrix3 rotation = planar() ? z_rotation(Rational(3, 5), Rational(4, 5)) : quaternion_rotation(1, 2, 3, 4);
  const screw::Vec3 translation = planar() ? screw::Vec3{7, -2, 0} : screw::Vec3{7, -2, Rational(5, 2)};
  const auto moved = rigidly_moved(model_, rotation, translation);
  const auto r = analyse_model(moved);
  EXPECT_TRUE(r.exact);
  expect_same(moved, r);
}

TEST_P(Invariance, AnotherRigidMotion) {
  const Matrix3 rotation = planar() ? z_rotation(Rational(-5, 13), Rational(12, 13)) : quaternion_rotation(3, -1, 5, 2);
  const auto moved = rigidly_moved(model_, rotation, {Rational(-1, 8), 100, 0});
  expect_same(moved, analyse_model(moved));
}

TEST_P(Invariance, LengthsTimes1000) {
  const auto big = scaled(model_, 1000);
  expect_same(big, analyse_model(big));
  expect_same(big, analyse_model(big, Arithmetic::floating));
}

TEST_P(Invariance, LengthsOver1000) {
  const auto small = scaled(model_, Rational(1, 1000));
  expect_same(small, analyse_model(small));
  expect_same(small, analyse_model(small, Arithmetic::floating));
}

TEST_P(Invariance, RenamedAndReordered) {
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const auto renamed = renamed_and_reordered(model_, seed);
    expect_same(renamed, analyse_model(renamed), true);
  }
}

TEST_P(Invariance, OtherSpanningTrees) {
  for (unsigned seed : {0u, 1u, 2u, 3u, 4u, 5u}) {
    SCOPED_TRACE(seed);
    const auto other = with_random_tree(model_, seed);
    expect_same(other, analyse_model(other));
  }
}

TEST_P(Invariance, AnyBodyAsGround) {
  // fij is a property of a pair of bodies, whichever body is held still.
  for (std::size_t ground = 0; ground < model_.bodies.size(); ++ground) {
    SCOPED_TRACE(model_.bodies[ground]);
    auto other = model_;
    other.ground = static_cast<int>(ground);
    expect_same(other, analyse_model(other));
  }
}

TEST_P(Invariance, CoupledPairsOnlyIsASubsetOfAllPairs) {
  for (const Arithmetic arithmetic : {Arithmetic::exact, Arithmetic::floating}) {
    network::AnalysisOptions options;
    options.arithmetic = arithmetic;
    options.all_pairs = false;
    const auto r = network::analyse_network(model_, options);
    EXPECT_EQ(r.FN, GetParam().FN);
    EXPECT_EQ(r.CN, GetParam().CN);
    const auto all = pair_table(model_, reference_);
    const auto coupled = pair_table(model_, r);
    std::size_t expected_rows = 0;
    for (const auto& [key, value] : all)
      if (!std::get<2>(key).empty()) ++expected_rows;
    EXPECT_EQ(coupled.size(), expected_rows);
    for (const auto& [key, value] : coupled) {
      ASSERT_FALSE(std::get<2>(key).empty());
      ASSERT_TRUE(all.count(key));
      EXPECT_EQ(value, all.at(key));
    }
  }
}

TEST_P(Invariance, ExactAndFloatingPointAgree) {
  const auto exact = analyse_model(model_, Arithmetic::exact);
  const auto floating = analyse_model(model_, Arithmetic::floating);
  EXPECT_TRUE(exact.exact);
  EXPECT_FALSE(floating.exact);
  expect_same(model_, exact);
  expect_same(model_, floating);
  // Ranks decided in floating point are not close calls for these textbook geometries.
  EXPECT_FALSE(floating.circulation.solution.rank.close());
  EXPECT_FALSE(floating.cutset_law.solution.rank.close());
}

TEST_P(Invariance, PairPrimariesAgreeInFloatingPoint) {
  // Which primary variables appear in a pair's motion system (seed 000, Table 1, "primary
  // variables" columns) is exact information; rounding noise must not add primaries. Checked
  // on the file's geometry and after rigid motions far from the origin.
  const Matrix3 rotation = planar() ? z_rotation(Rational(3, 5), Rational(4, 5)) : quaternion_rotation(1, 2, 3, 4);
  const std::vector<network::Model> models = {model_, rigidly_moved(model_, rotation, {7, -2, 0}),
                                              rigidly_moved(model_, rotation, {12345, -678, planar() ? 0 : 91})};
  for (std::size_t i = 0; i < models.size(); ++i) {
    SCOPED_TRACE(i);
    auto model = models[i];
    const auto exact = analyse_model(model, Arithmetic::exact);
    // The same primaries for both, so that the names can be compared.
    network::AnalysisOptions options;
    options.arithmetic = Arithmetic::floating;
    std::vector<std::string> primary;
    for (int p : exact.primary_motion) primary.push_back(exact.motions[static_cast<std::size_t>(p)].name);
    for (int p : exact.primary_action) primary.push_back(exact.actions[static_cast<std::size_t>(p)].name);
    options.primary = primary;
    const auto floating = network::analyse_network(model, options);
    EXPECT_EQ(pair_primaries(model, floating), pair_primaries(model, exact));
  }
}

TEST_P(Invariance, RedundantRowsAgreeInFloatingPoint) {
  // The redundant equations (rows of the user's M^N and A^N that depend on later rows, seed
  // 000, section 2.5.1) do not depend on the arithmetic, also far from the origin.
  const Matrix3 rotation = planar() ? z_rotation(Rational(3, 5), Rational(4, 5)) : quaternion_rotation(1, 2, 3, 4);
  const std::vector<network::Model> models = {model_, scaled(model_, 1000),
                                              rigidly_moved(model_, rotation, {12345, -678, planar() ? 0 : 91})};
  for (std::size_t i = 0; i < models.size(); ++i) {
    SCOPED_TRACE(i);
    const auto exact = analyse_model(models[i], Arithmetic::exact);
    const auto floating = analyse_model(models[i], Arithmetic::floating);
    EXPECT_EQ(floating.circulation.solution.redundant_rows, exact.circulation.solution.redundant_rows);
    EXPECT_EQ(floating.cutset_law.solution.redundant_rows, exact.cutset_law.solution.redundant_rows);
    // Dropping them leaves as many rows as the rank: CN rows of M^N, FN rows of A^N.
    EXPECT_EQ(static_cast<int>(floating.circulation.solution.redundant_rows.size()), GetParam().CN);
    EXPECT_EQ(static_cast<int>(floating.cutset_law.solution.redundant_rows.size()), GetParam().FN);
  }
}

TEST_P(Invariance, RigidMotionThenFloatingPoint) {
  const Matrix3 rotation = planar() ? z_rotation(Rational(3, 5), Rational(4, 5)) : quaternion_rotation(1, 2, 3, 4);
  const auto moved = rigidly_moved(model_, rotation, {7, -2, 0});
  expect_same(moved, analyse_model(moved, Arithmetic::floating));
}

TEST_P(Invariance, ThirtyDegreesInFullDoublePrecision) {
  // cos 30° and sin 30° written with 16 significant digits, as a file would hold them; every
  // coordinate of the rotated model is rounded to a double. Automatic arithmetic must see the
  // long literals, choose floating point and find the published FN and CN.
  const Rational c(0.8660254037844386), s(0.5);
  Matrix3 rotation;
  if (planar()) {
    rotation = z_rotation(c, s);
  } else {
    // 30° about x, then 30° about z.
    const Matrix3 about_x{{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
    const Matrix3 about_z = z_rotation(c, s);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        rotation[i][j] = 0;
        for (std::size_t m = 0; m < 3; ++m) rotation[i][j] += about_z[i][m] * about_x[m][j];
      }
  }
  const auto rotated = rounded_to_double(rigidly_moved(model_, rotation, {Rational(1, 10), 0, 0}));
  const auto r = analyse_model(rotated);
  EXPECT_FALSE(r.exact);
  expect_same(rotated, r);
  // Exact arithmetic analyses the rounded geometry, which may be a different mechanism; if it
  // is, the library must say that floating point disagrees, with the published answer.
  const auto e = analyse_model(rotated, Arithmetic::exact);
  if (e.FN != GetParam().FN || e.CN != GetParam().CN) {
    ASSERT_TRUE(e.floating_point_disagreement.has_value());
    EXPECT_EQ(e.floating_point_disagreement->first, GetParam().FN);
    EXPECT_EQ(e.floating_point_disagreement->second, GetParam().CN);
  } else {
    EXPECT_FALSE(e.floating_point_disagreement.has_value());
  }
}

INSTANTIATE_TEST_SUITE_P(Mechanisms, Invariance, ::testing::ValuesIn(kMechanisms), [](const ::testing::TestParamInfo<Published>& param_info) {
  std::string name = param_info.param.file.substr(0, param_info.param.file.find('.'));
  for (char& ch : name)
    if (ch == '-') ch = '_';
  return name;
});

}  // namespace
}  // namespace kinestat::mechanisms_test
