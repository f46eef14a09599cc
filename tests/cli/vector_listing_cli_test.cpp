// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze --json [--full-vectors]` (issue 41, item 2) as a user runs it: the default
// lists each stress state's and mode's non-zero entries, --full-vectors every entry in the order
// of row_labels and column_labels; a network refuses the option with exit code 2.
//
// The framework, by hand: a unit square A-B-C-D with both diagonals (A pinned, B held in y)
// carries the one self-stress of a braced square; E hangs from B and C by a dyad (no stress) and
// F from E by one bar (F swings about E: one mechanism). Equilibrium at A gives every side t and
// each diagonal -√2 t; at unit 2-norm with the largest entry positive: diagonals +1/2, sides
// -1/(2√2). The mode moves F alone, along x (perpendicular to EF): F.x = 1.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <string>

#include "support/cli_run.hpp"

namespace {

using kinestat::testing::run_cli;

constexpr const char* kBracedSquareWithDyad = R"(kinestat: 1
kind: framework
dimension: planar
nodes: {A: [0, 0], B: [1, 0], C: [1, 1], D: [0, 1], E: [2, 0.5], F: [2, 1.5]}
supports: {A: pinned, B: [y]}
elements:
  - {name: AB, type: truss, nodes: [A, B]}
  - {name: BC, type: truss, nodes: [B, C]}
  - {name: CD, type: truss, nodes: [C, D]}
  - {name: DA, type: truss, nodes: [D, A]}
  - {name: AC, type: truss, nodes: [A, C]}
  - {name: BD, type: truss, nodes: [B, D]}
  - {name: BE, type: truss, nodes: [B, E]}
  - {name: CE, type: truss, nodes: [C, E]}
  - {name: EF, type: truss, nodes: [E, F]}
)";

const double kSide = -1.0 / (2.0 * std::sqrt(2.0)), kDiagonal = 0.5;

nlohmann::json analyse(const std::string& options) {
  const std::string path = kinestat::testing::write_temp_file("braced-square-dyad.yaml", kBracedSquareWithDyad);
  const auto r = run_cli("analyze " + path + " --json " + options);
  EXPECT_NE(r.exit_code, 2) << r.err;
  return nlohmann::json::parse(r.out);
}

std::map<std::string, double> resultants(const nlohmann::json& list) {
  std::map<std::string, double> out;
  for (const auto& entry : list) out[entry.at("element").get<std::string>()] = entry.at("value").get<double>();
  return out;
}

std::map<std::string, double> velocities(const nlohmann::json& by_node) {
  std::map<std::string, double> out;
  for (const auto& [node, coordinates] : by_node.items())
    for (const auto& [coordinate, rate] : coordinates.items()) out[node + "." + coordinate] = rate.get<double>();
  return out;
}

TEST(VectorListingCommand, DefaultListsTheNonZeroEntries) {
  const auto report = analyse("");
  EXPECT_EQ(report.at("vector_listing"), "non_zero");
  ASSERT_EQ(report.at("stresses").size(), 1u);
  const auto listed = resultants(report.at("stresses")[0].at("resultants"));
  const std::map<std::string, double> expected{{"AB", kSide}, {"BC", kSide}, {"CD", kSide},
                                               {"DA", kSide}, {"AC", kDiagonal}, {"BD", kDiagonal}};
  ASSERT_EQ(listed.size(), expected.size());
  for (const auto& [bar, value] : expected) {
    ASSERT_EQ(listed.count(bar), 1u) << bar;
    EXPECT_NEAR(listed.at(bar), value, 1e-9) << bar;
  }
  ASSERT_EQ(report.at("modes").size(), 1u);
  const auto rates = velocities(report.at("modes")[0].at("velocities"));
  ASSERT_EQ(rates.size(), 1u);
  EXPECT_NEAR(rates.at("F.x"), 1.0, 1e-9);
}

TEST(VectorListingCommand, FullVectorsListsEveryEntryInLabelOrder) {
  const auto report = analyse("--full-vectors");
  EXPECT_EQ(report.at("vector_listing"), "full");
  const auto& list = report.at("stresses")[0].at("resultants");
  const auto& rows = report.at("row_labels");
  ASSERT_EQ(list.size(), 9u);  // the nine bars' elongations
  ASSERT_EQ(rows.size(), list.size());
  for (std::size_t i = 0; i < list.size(); ++i)
    EXPECT_EQ(list[i].at("element").get<std::string>() + "." + list[i].at("deformation").get<std::string>(), rows[i].get<std::string>());
  const auto full = resultants(list);
  for (const char* unloaded : {"BE", "CE", "EF"}) EXPECT_EQ(full.at(unloaded), 0.0) << unloaded;
  EXPECT_NEAR(full.at("BD"), kDiagonal, 1e-9);
  EXPECT_NEAR(full.at("DA"), kSide, 1e-9);
  // Every dependent coordinate: 6 nodes × 2 less A's two and B's y.
  const auto rates = velocities(report.at("modes")[0].at("velocities"));
  ASSERT_EQ(rates.size(), 9u);
  EXPECT_EQ(rates.size(), report.at("column_labels").size());
  for (const auto& [coordinate, rate] : rates)
    if (coordinate != "F.x") {
      EXPECT_EQ(rate, 0.0) << coordinate;
    }
  EXPECT_NEAR(rates.at("F.x"), 1.0, 1e-9);
}

TEST(VectorListingCommand, NetworkRefusesFullVectorsWithExitCode2) {
  const auto r = run_cli("analyze " + kinestat::testing::example_path("davies-2-circuit.yaml") + " --json --full-vectors");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("davies-2-circuit.yaml:1:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--full-vectors"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

}  // namespace

namespace {

// The text report lists the non-zero entries of each vector whatever is asked, so --full-vectors
// without --json would be ignored silently: it is refused, one line, exit code 2, nothing on
// standard output.
TEST(VectorListingCommand, FullVectorsWithoutJsonIsRefusedWithExitCode2) {
  const auto r = run_cli("analyze " + kinestat::testing::example_path("braced-square.yaml") + " --full-vectors");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--full-vectors"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--json"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

}  // namespace
