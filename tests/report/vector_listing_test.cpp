// SPDX-License-Identifier: BSD-3-Clause
// A report whose size follows its content (issue 41, item 2): the JSON lists the non-zero
// entries of each stress state and mode by name, every entry on request (VectorListing::full,
// `analyze --json --full-vectors`).
//
// The framework, by hand: a unit square A-B-C-D with both diagonals (pinned at A, B held in y)
// carries the one self-stress of a braced square; node E hangs from B and C by a dyad (no
// stress), and F from E by one vertical bar (F swings about E: one mechanism). Equilibrium at A
// (bars AB along x, AD along y, AC along (1, 1)/sqrt 2, each row of D(c) the unit vector of its
// bar): t_AB + t_AC/sqrt 2 = 0, so every side carries t and each diagonal -sqrt 2 t; normalised
// to unit 2-norm (4 t^2 + 2 (2 t^2) = 1) with the largest entry positive: diagonals +1/2, sides
// -1/(2 sqrt 2). The mode moves F alone, along x (perpendicular to EF): F.x = 1.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/report/framework_report.hpp"

namespace {

namespace report = kinestat::report;
namespace framework = kinestat::framework;

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

struct Analysed {
  framework::FrameworkModel model;
  framework::FrameworkResult analysis;
};

Analysed braced_square() {
  Analysed a;
  a.model = kinestat::io::read_framework_model(kinestat::io::YamlFile::parse("braced-square-dyad.yaml", kBracedSquareWithDyad));
  a.analysis = framework::analyse_framework(a.model);
  return a;
}

/// element -> value of a JSON resultants list (each entry's deformation must be the bar's elongation).
std::map<std::string, double> resultants(const nlohmann::ordered_json& list) {
  std::map<std::string, double> out;
  for (const auto& entry : list) {
    EXPECT_EQ(entry.at("deformation"), "elongation");
    out[entry.at("element").get<std::string>()] = entry.at("value").get<double>();
  }
  return out;
}

/// "node.coordinate" -> rate of a JSON mode's velocities.
std::map<std::string, double> velocities(const nlohmann::ordered_json& by_node) {
  std::map<std::string, double> out;
  for (const auto& [node, coordinates] : by_node.items())
    for (const auto& [coordinate, rate] : coordinates.items()) out[node + "." + coordinate] = rate.get<double>();
  return out;
}

const double kSide = -1.0 / (2.0 * std::sqrt(2.0)), kDiagonal = 0.5;

TEST(VectorListing, TheSelfStressListsExactlyTheBarsItLoadsWithTheirValues) {
  const auto a = braced_square();
  ASSERT_EQ(a.analysis.self_stresses, 1);
  ASSERT_EQ(a.analysis.mechanisms, 1);
  const auto json = report::framework_report_json(a.model, a.analysis);
  EXPECT_EQ(json.at("vector_listing"), "non_zero");
  ASSERT_EQ(json.at("stresses").size(), 1u);
  const auto listed = resultants(json.at("stresses")[0].at("resultants"));
  const std::map<std::string, double> expected{{"AB", kSide}, {"BC", kSide}, {"CD", kSide},
                                               {"DA", kSide}, {"AC", kDiagonal}, {"BD", kDiagonal}};
  ASSERT_EQ(listed.size(), expected.size());
  for (const auto& [bar, value] : expected) {
    ASSERT_EQ(listed.count(bar), 1u) << bar;
    EXPECT_NEAR(listed.at(bar), value, 1e-9) << bar;
  }
}

TEST(VectorListing, TheModeListsTheOneCoordinateThatMoves) {
  const auto a = braced_square();
  const auto json = report::framework_report_json(a.model, a.analysis);
  ASSERT_EQ(json.at("modes").size(), 1u);
  const auto listed = velocities(json.at("modes")[0].at("velocities"));
  ASSERT_EQ(listed.size(), 1u);
  ASSERT_EQ(listed.count("F.x"), 1u);
  EXPECT_NEAR(listed.at("F.x"), 1.0, 1e-9);
}

TEST(VectorListing, TheFullListingGivesEveryRowAndCoordinateWithItsZeros) {
  const auto a = braced_square();
  const auto json = report::framework_report_json(a.model, a.analysis, nullptr, nullptr, report::VectorListing::full);
  EXPECT_EQ(json.at("vector_listing"), "full");
  // Every bar, in the order of D(c)'s rows (the row labels), the unloaded ones as 0.
  const auto& list = json.at("stresses")[0].at("resultants");
  const auto& rows = json.at("row_labels");
  ASSERT_EQ(list.size(), 9u);
  ASSERT_EQ(rows.size(), 9u);
  for (std::size_t i = 0; i < list.size(); ++i)
    EXPECT_EQ(list[i].at("element").get<std::string>() + "." + list[i].at("deformation").get<std::string>(), rows[i].get<std::string>());
  const auto full = resultants(list);
  for (const char* unloaded : {"BE", "CE", "EF"}) EXPECT_EQ(full.at(unloaded), 0.0) << unloaded;
  EXPECT_NEAR(full.at("AC"), kDiagonal, 1e-9);
  EXPECT_NEAR(full.at("AB"), kSide, 1e-9);
  // Every dependent coordinate (the columns of D(c)): 6 nodes x 2 less A's two and B's y.
  const auto rates = velocities(json.at("modes")[0].at("velocities"));
  EXPECT_EQ(rates.size(), 9u);
  EXPECT_EQ(rates.size(), json.at("column_labels").size());
  for (const auto& [coordinate, rate] : rates)
    if (coordinate != "F.x") {
      EXPECT_EQ(rate, 0.0) << coordinate;
    }
  EXPECT_NEAR(rates.at("F.x"), 1.0, 1e-9);
}

TEST(VectorListing, ZeroIsRelativeToTheVectorsLargestEntry) {
  // The same framework 10^6 times larger and 10^-6 times smaller: the same bars listed (lengths
  // are non-dimensional in D(c), so the values are the same too).
  for (const double scale : {1e-6, 1e6}) {
    std::string yaml = kBracedSquareWithDyad;
    const std::string from = "nodes: {A: [0, 0], B: [1, 0], C: [1, 1], D: [0, 1], E: [2, 0.5], F: [2, 1.5]}";
    const auto s = [scale](double v) { return fmt::format("{}", v * scale); };
    const std::string to = "nodes: {A: [0, 0], B: [" + s(1) + ", 0], C: [" + s(1) + ", " + s(1) + "], D: [0, " + s(1) + "], E: [" +
                           s(2) + ", " + s(0.5) + "], F: [" + s(2) + ", " + s(1.5) + "]}";
    yaml.replace(yaml.find(from), from.size(), to);
    const auto model = kinestat::io::read_framework_model(kinestat::io::YamlFile::parse("scaled.yaml", yaml));
    const auto json = report::framework_report_json(model, framework::analyse_framework(model));
    std::set<std::string> bars;
    for (const auto& [bar, value] : resultants(json.at("stresses")[0].at("resultants"))) bars.insert(bar);
    EXPECT_EQ(bars, (std::set<std::string>{"AB", "BC", "CD", "DA", "AC", "BD"})) << scale;
  }
}

}  // namespace
