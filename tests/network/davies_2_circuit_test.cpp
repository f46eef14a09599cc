// SPDX-License-Identifier: BSD-3-Clause
// Davies' 2-circuit network (seed 000, Fig. 1, Appendix 3): every matrix, rank and table
// printed in the paper. Expected values are typed in from the paper and were checked by hand
// against Tables 3 and 4 (unit screws) and the partitions of B and Q; two printed values that
// contradict the paper's own matrices are noted where they are tested.
#include <gtest/gtest.h>

#include <map>

#include "kinestat/network/analyse_network.hpp"
#include "kinestat/report/linear_form_text.hpp"
#include "seed_fixture.hpp"

namespace kinestat::network {
namespace {

using linalg::RationalMatrix;

RationalMatrix matrix(std::initializer_list<std::initializer_list<int>> rows) {
  RationalMatrix m(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.begin()->size()));
  Eigen::Index r = 0;
  for (const auto& row : rows) {
    Eigen::Index c = 0;
    for (int value : row) m(r, c++) = value;
    ++r;
  }
  return m;
}

Eigen::MatrixXi int_matrix(std::initializer_list<std::initializer_list<int>> rows) {
  return matrix(rows).to_double().cast<int>();
}

class Davies2Circuit : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    loaded_ = new io::LoadedNetwork(testing::load_example("davies-2-circuit.yaml"));
    result_ = new NetworkResult(analyse_network(loaded_->model));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete loaded_;
  }
  static const NetworkResult& r() { return *result_; }

  std::vector<std::string> motion_primary_names() const {
    std::vector<std::string> names;
    for (int i : r().primary_motion) names.push_back(r().motions[static_cast<std::size_t>(i)].name);
    return names;
  }
  std::vector<std::string> action_primary_names() const {
    std::vector<std::string> names;
    for (int i : r().primary_action) names.push_back(r().actions[static_cast<std::size_t>(i)].name);
    return names;
  }

  static io::LoadedNetwork* loaded_;
  static NetworkResult* result_;
};
io::LoadedNetwork* Davies2Circuit::loaded_ = nullptr;
NetworkResult* Davies2Circuit::result_ = nullptr;

TEST_F(Davies2Circuit, CountsRanksAndNettFreedoms) {
  EXPECT_TRUE(r().exact);
  EXPECT_EQ(r().d, 6);
  EXPECT_EQ(r().bodies, 4);
  EXPECT_EQ(r().e, 5);
  EXPECT_EQ(r().l, 2);
  EXPECT_EQ(r().k, 3);
  EXPECT_EQ(r().F, 13);
  EXPECT_EQ(r().C, 17);
  EXPECT_EQ(r().m, 10);  // section 2.5.1
  EXPECT_EQ(r().a, 15);
  EXPECT_EQ(r().FN, 3);
  EXPECT_EQ(r().CN, 2);
  EXPECT_EQ(r().classification, NetworkClass::overconstrained_chain);  // Table 2, FN > 0 and CN > 0
  EXPECT_TRUE(r().identities_hold);
  // Eqs 7, 8, 16 written out.
  EXPECT_EQ(r().FN - r().CN, r().F - r().d * r().l);
  EXPECT_EQ(r().CN - r().FN, r().C - r().d * r().k);
  EXPECT_EQ(r().FN, r().d * r().k - r().a);
  EXPECT_EQ(r().CN, r().d * r().l - r().m);
}

TEST_F(Davies2Circuit, CircuitAndCutsetMatricesEq3) {
  EXPECT_EQ(r().branches, (std::vector<int>{0, 2, 3}));  // a, c, d
  EXPECT_EQ(r().chords, (std::vector<int>{1, 4}));       // b, e
  EXPECT_EQ(r().B, int_matrix({{0, 1, -1, 1, 0}, {1, 0, -1, 0, 1}}));                    // eq. 3a
  EXPECT_EQ(r().Q, int_matrix({{1, 0, 0, 0, -1}, {0, 1, 1, 0, 1}, {0, -1, 0, 1, 0}}));  // eq. 3b
}

TEST_F(Davies2Circuit, MotionAndActionGraphMatricesEq4) {
  EXPECT_EQ(r().BM, int_matrix({{0, 0, 0, 1, 1, 1, -1, -1, -1, 1, 1, 0, 0},  // eq. 4a
                                {1, 1, 1, 0, 0, 0, -1, -1, -1, 0, 0, 1, 1}}));
  EXPECT_EQ(r().QA, int_matrix({{1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, -1, -1, -1},  // eq. 4b
                                {0, 0, 0, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1},
                                {0, 0, 0, -1, -1, -1, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0}}));
}

TEST_F(Davies2Circuit, UnitMatricesOfDirectCouplings) {
  // [M^D]6,13, section 2.4.1 (columns ra sa ta | rb sb tb | tc uc vc | sd vd | se ve).
  EXPECT_EQ(r().MD, matrix({{1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0},
                            {0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0},
                            {0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 1},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}}));
  // [A^D]6,17 (columns Ua Va Wa | Ub Vb Wb | Rc Sc Wc | Rd Td Ud Wd | Re Te Ue We).
  EXPECT_EQ(r().AD, matrix({{0, 0, 0, 0, -1, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
                            {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0},
                            {1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0},
                            {0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}}));
  const std::vector<std::string> motion_names{"ra", "sa", "ta", "rb", "sb", "tb", "tc",
                                              "uc", "vc", "sd", "vd", "se", "ve"};
  const std::vector<std::string> action_names{"Ua", "Va", "Wa", "Ub", "Vb", "Wb", "Rc", "Sc", "Wc",
                                              "Rd", "Td", "Ud", "Wd", "Re", "Te", "Ue", "We"};
  ASSERT_EQ(r().motions.size(), motion_names.size());
  ASSERT_EQ(r().actions.size(), action_names.size());
  for (std::size_t i = 0; i < motion_names.size(); ++i) EXPECT_EQ(r().motions[i].name, motion_names[i]);
  for (std::size_t i = 0; i < action_names.size(); ++i) EXPECT_EQ(r().actions[i].name, action_names[i]);
}

TEST_F(Davies2Circuit, NetworkUnitMatricesEq5) {
  EXPECT_EQ(r().MN, matrix({{0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0},
                            {0, 0, 0, 0, 0, 1, -1, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, -1, 0, 0, -1, 0, 0, 0, 0, 0},
                            {0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 1, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0},
                            {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0},
                            {0, 0, 1, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 1},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}}));
  EXPECT_EQ(r().AN, matrix({{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0},
                            {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0},
                            {0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1},
                            {0, 0, 0, 0, -1, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0},
                            {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0},
                            {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0},
                            {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1},
                            {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                            {0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0}}));
}

TEST_F(Davies2Circuit, RedundantEquations) {
  // Section 2.5.1: "The discarded rows can be the second and the empty twelfth."
  EXPECT_EQ(r().circulation.solution.redundant_rows, (std::vector<Eigen::Index>{1, 11}));
  // The paper says rows 2, 3 and 9 of [A^N]18,17; but row 3 (-Te) and row 9 (+Te) are each
  // other's negatives, so they cannot both go while the rank stays 15. The three dependencies
  // are: row 2 is empty, row 3 = -row 9, row 11 = -row 17. Any valid choice has row 2, one of
  // {3, 9} and one of {11, 17}; kinestat keeps later rows, giving 2, 3, 11.
  EXPECT_EQ(r().cutset_law.solution.redundant_rows, (std::vector<Eigen::Index>{1, 2, 10}));
  // Section 3.4.1: rows 2, 3, 9 of [M^N T]13,12 and rows 1, 3 of [A^N T]17,18 can be eliminated.
  EXPECT_EQ(r().circuit_action.solution.redundant_rows, (std::vector<Eigen::Index>{1, 2, 8}));
  EXPECT_EQ(r().cutset_motion.solution.redundant_rows, (std::vector<Eigen::Index>{0, 2}));
}

TEST_F(Davies2Circuit, MagnitudesInPrimaryVariables) {
  EXPECT_EQ(motion_primary_names(), (std::vector<std::string>{"sa", "ta", "vc"}));
  EXPECT_EQ(action_primary_names(), (std::vector<std::string>{"Ub", "We"}));
  // Section 2.6.1 ("2sa" in the extracted text is -sa, "2Ub" is -Ub; Wc = Ub - We).
  const std::vector<std::string> motions{"0", "sa", "ta", "0", "0", "ta", "ta", "0", "vc", "0", "vc", "-sa", "vc"};
  const std::vector<std::string> actions{"-Ub", "0", "We", "Ub", "0", "-Ub", "0", "-Ub", "Ub - We",
                                         "0",   "0", "Ub", "-Ub", "0", "0", "-Ub", "We"};
  for (std::size_t i = 0; i < motions.size(); ++i)
    EXPECT_EQ(report::linear_form_text(r().motion_magnitudes, static_cast<Eigen::Index>(i), motion_primary_names()), motions[i])
        << r().motions[i].name;
  for (std::size_t i = 0; i < actions.size(); ++i)
    EXPECT_EQ(report::linear_form_text(r().action_magnitudes, static_cast<Eigen::Index>(i), action_primary_names()), actions[i])
        << r().actions[i].name;
}

// Column `coupling` of a contracted matrix as six expressions.
std::vector<std::string> column(const LinearForms& forms, int coupling, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (int c = 0; c < 6; ++c) out.push_back(report::linear_form_text(forms, coupling * 6 + c, names));
  return out;
}

TEST_F(Davies2Circuit, ContractedMatricesEq15) {
  using V = std::vector<std::string>;
  const auto mp = motion_primary_names();
  const auto ap = action_primary_names();
  // (15a): columns A..E of [M]6,5.
  EXPECT_EQ(column(r().circulation.contracted, 0, mp), (V{"0", "sa", "ta", "0", "0", "0"}));
  EXPECT_EQ(column(r().circulation.contracted, 1, mp), (V{"0", "0", "ta", "0", "0", "0"}));
  EXPECT_EQ(column(r().circulation.contracted, 2, mp), (V{"0", "0", "ta", "0", "vc", "0"}));
  EXPECT_EQ(column(r().circulation.contracted, 3, mp), (V{"0", "0", "0", "0", "vc", "0"}));
  EXPECT_EQ(column(r().circulation.contracted, 4, mp), (V{"0", "-sa", "0", "0", "vc", "0"}));
  // (15b): columns A..E of [A]6,5.
  EXPECT_EQ(column(r().cutset_law.contracted, 0, ap), (V{"0", "0", "0", "-Ub", "0", "We"}));
  EXPECT_EQ(column(r().cutset_law.contracted, 1, ap), (V{"0", "Ub", "0", "Ub", "0", "-Ub"}));
  EXPECT_EQ(column(r().cutset_law.contracted, 2, ap), (V{"0", "-Ub", "0", "0", "0", "Ub - We"}));
  EXPECT_EQ(column(r().cutset_law.contracted, 3, ap), (V{"0", "Ub", "0", "Ub", "0", "-Ub"}));
  EXPECT_EQ(column(r().cutset_law.contracted, 4, ap), (V{"0", "0", "0", "-Ub", "0", "We"}));
}

TEST_F(Davies2Circuit, VirtualPowerMethodsEq13And14) {
  EXPECT_TRUE(r().motion_methods_agree);
  EXPECT_TRUE(r().action_methods_agree);
  // (13a): with sa, ta, vc (2nd, 3rd, 11th components of [Mk]18) as primaries.
  const auto mk = linalg::with_free_variables(r().cutset_motion.solution, {1, 2, 10});
  const LinearForms mk_forms{mk.coefficients, mk.exact_coefficients};
  const std::vector<std::string> mk_names{"sa", "ta", "vc"};
  const std::vector<std::string> expected_mk{"0", "sa", "ta", "0", "0",  "0", "0", "0", "ta",
                                             "0", "vc", "0",  "0", "0", "0", "0", "vc", "0"};
  for (std::size_t i = 0; i < expected_mk.size(); ++i)
    EXPECT_EQ(report::linear_form_text(mk_forms, static_cast<Eigen::Index>(i), mk_names), expected_mk[i]) << i;
  // (13b): with Ub, We (4th and 12th components of [Al]12) as primaries.
  const auto al = linalg::with_free_variables(r().circuit_action.solution, {3, 11});
  const LinearForms al_forms{al.coefficients, al.exact_coefficients};
  const std::vector<std::string> al_names{"Ub", "We"};
  const std::vector<std::string> expected_al{"0", "Ub", "0", "Ub", "0", "-Ub", "0", "0", "0", "-Ub", "0", "We"};
  for (std::size_t i = 0; i < expected_al.size(); ++i)
    EXPECT_EQ(report::linear_form_text(al_forms, static_cast<Eigen::Index>(i), al_names), expected_al[i]) << i;
  // (14b): [A]6,5 = [Al]6,2 [B]2,5 reproduces (15b) with the same primaries.
  for (int e = 0; e < 5; ++e)
    for (int c = 0; c < 6; ++c) {
      linalg::RationalMatrix sum(1, 2);
      for (int circuit = 0; circuit < 2; ++circuit)
        for (int p = 0; p < 2; ++p) sum(0, p) += r().B(circuit, e) * (*al.exact_coefficients)(circuit * 6 + c, p);
      for (int p = 0; p < 2; ++p) EXPECT_EQ(sum(0, p), (*r().cutset_law.contracted.exact)(e * 6 + c, p)) << e << "," << c;
    }
}

TEST_F(Davies2Circuit, PairsOfBodiesTable1) {
  struct Row {
    std::string i, j, coupling;
    int f, fij;
    std::vector<std::string> motion_primaries;
    int c, cij;
    std::vector<std::string> action_primaries;
  };
  // Table 1. The printed row (3, 4) gives primaries "sa, vc", but column A of the paper's own
  // (15a) is (0, sa, ta; 0, 0, 0): a spheric coupling cannot allow the translation vc, so the
  // row is sa, ta.
  const std::vector<Row> table{
      {"1", "2", "D", 2, 1, {"vc"}, 4, 1, {"Ub"}},
      {"1", "3", "E", 2, 2, {"sa", "vc"}, 4, 2, {"Ub", "We"}},
      {"1", "4", "C", 3, 2, {"ta", "vc"}, 3, 2, {"Ub", "We"}},
      {"2", "3", "", 6, 1, {"sa"}, 0, 0, {}},
      {"2", "4", "B", 3, 1, {"ta"}, 3, 1, {"Ub"}},
      {"3", "4", "A", 3, 2, {"sa", "ta"}, 3, 2, {"Ub", "We"}},
  };
  const auto& bodies = loaded_->model.bodies;
  ASSERT_EQ(r().pairs.size(), table.size());
  const auto mp = motion_primary_names();
  const auto ap = action_primary_names();
  for (std::size_t n = 0; n < table.size(); ++n) {
    const PairSystem& p = r().pairs[n];
    const Row& row = table[n];
    SCOPED_TRACE(row.i + "," + row.j);
    EXPECT_EQ(bodies[static_cast<std::size_t>(p.body_i)], row.i);
    EXPECT_EQ(bodies[static_cast<std::size_t>(p.body_j)], row.j);
    EXPECT_EQ(p.coupling ? loaded_->model.couplings[static_cast<std::size_t>(*p.coupling)].name : "", row.coupling);
    EXPECT_EQ(p.f, row.f);
    EXPECT_EQ(p.fij, row.fij);
    EXPECT_EQ(p.c, row.c);
    EXPECT_EQ(p.cij, row.cij);
    std::vector<std::string> motion, action;
    for (int i : p.motion_primaries) motion.push_back(mp[static_cast<std::size_t>(i)]);
    for (int i : p.action_primaries) action.push_back(ap[static_cast<std::size_t>(i)]);
    EXPECT_EQ(motion, row.motion_primaries);
    EXPECT_EQ(action, row.action_primaries);
  }
  // Section 2.7: [M23]6 = (0, -sa, 0; 0, 0, 0), angular velocity about the y-axis.
  EXPECT_EQ(column(r().pairs[3].motion_system, 0, mp), (std::vector<std::string>{"0", "-sa", "0", "0", "0", "0"}));
}

TEST_F(Davies2Circuit, FloatingPointGivesTheSameAnswer) {
  AnalysisOptions options;
  options.arithmetic = Arithmetic::floating;
  const NetworkResult f = analyse_network(loaded_->model, options);
  EXPECT_FALSE(f.exact);
  EXPECT_EQ(f.m, 10);
  EXPECT_EQ(f.a, 15);
  EXPECT_EQ(f.FN, 3);
  EXPECT_EQ(f.CN, 2);
  EXPECT_FALSE(f.circulation.solution.rank.close());
  EXPECT_GT(f.circulation.solution.rank.gap(), 1e12);
  EXPECT_TRUE(f.motion_methods_agree);
  EXPECT_TRUE(f.action_methods_agree);
  EXPECT_TRUE(f.motion_magnitudes.values.isApprox(r().motion_magnitudes.values, 1e-12));
  EXPECT_TRUE(f.action_magnitudes.values.isApprox(r().action_magnitudes.values, 1e-12));
  EXPECT_TRUE(f.circulation.contracted.values.isApprox(r().circulation.contracted.values, 1e-12));
  ASSERT_EQ(f.pairs.size(), r().pairs.size());
  for (std::size_t i = 0; i < f.pairs.size(); ++i) {
    EXPECT_EQ(f.pairs[i].fij, r().pairs[i].fij);
    EXPECT_EQ(f.pairs[i].cij, r().pairs[i].cij);
  }
}

TEST_F(Davies2Circuit, NumericValuesOfPrimaries) {
  // Section 4.6: given an input speed and a measured action, every magnitude follows.
  AnalysisOptions options;
  options.values = {{"sa", 2}, {"ta", linalg::Rational(1, 2)}, {"vc", -1}, {"Ub", 3}, {"We", 1}};
  const NetworkResult v = analyse_network(loaded_->model, options);
  ASSERT_TRUE(v.motion_values && v.action_values);
  EXPECT_DOUBLE_EQ((*v.motion_values)(11), -2.0);  // se = -sa
  EXPECT_DOUBLE_EQ((*v.motion_values)(12), -1.0);  // ve = vc
  EXPECT_DOUBLE_EQ((*v.action_values)(8), 2.0);    // Wc = Ub - We
  EXPECT_DOUBLE_EQ((*v.action_values)(0), -3.0);   // Ua = -Ub
}

TEST_F(Davies2Circuit, OtherPrimaryVariables) {
  // Section 2.6.2: sa may be replaced by -se, ta by tb, vc by ve; Ub by Sb... and We by Wa.
  AnalysisOptions options;
  options.primary = std::vector<std::string>{"se", "tb", "ve", "Sb", "Wa"};
  EXPECT_THROW(analyse_network(loaded_->model, options), ModelError);  // Sb is not a magnitude: B is spheric
  options.primary = std::vector<std::string>{"se", "tb", "ve", "Ud", "Wa"};
  const NetworkResult alt = analyse_network(loaded_->model, options);
  const std::vector<std::string> names{"tb", "se", "ve"};  // free variables in increasing order
  EXPECT_EQ(report::linear_form_text(alt.motion_magnitudes, 1, names), "-se");  // sa
  EXPECT_EQ(report::linear_form_text(alt.action_magnitudes, 8, std::vector<std::string>{"Wa", "Ud"}), "-Wa + Ud");  // Wc
  options.primary = std::vector<std::string>{"sa", "tb", "tc"};  // tb = tc: not independent
  try {
    analyse_network(loaded_->model, options);
    FAIL() << "dependent primaries accepted";
  } catch (const ModelError& error) {
    EXPECT_EQ(error.field(), "primary");
    EXPECT_EQ(error.index(), 2);
  }
}

}  // namespace
}  // namespace kinestat::network
