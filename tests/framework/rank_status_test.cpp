// SPDX-License-Identifier: BSD-3-Clause
// Issue 12, item 2, floating-point path: a well-conditioned framework's rank is certain, the twelve
// trusses of seed 002 moved by 1e-12 are full rank but close, and the report shows the distance
// (it printed "smallest/largest singular value: 0" before: values below 2^12 ε were cut to zero).
//
// Expected values from an independent script (numpy.linalg.svd of the bar-direction matrices built
// by hand from the node coordinates, not from kinestat):
// - braced square (examples/braced-square.yaml, D(c) 6 × 5): σ = 1.6998, 1.4142, 1.1642, 1, 0.50533;
//   σ_min / σ_max = 0.29729.
// - twelve trusses with E moved along x by δ × 1.5 (1.5: the characteristic length, the largest
//   distance of a node from the centroid (0, 0, 0.5), that of A–D): σ_min / σ_max = 0.17678 δ for
//   δ = 1e-3 … 1e-12 (linear: the first-order change of the zero singular value is δpᵀ Ω u, Ω the
//   stress matrix, u the mode, which is non-zero for a move of E along x; moves along y or z keep
//   the design special, σ_min stays at rounding).
// Status by the rule of docs/architecture.md: B = (12·12 ε + 2·12 ρ) σ_max with ρ = ε (coordinates
// of size 1 against a length of 1.5), B / σ_max = 168 ε = 3.7e-14; 100 B / σ_max = 3.7e-12 above
// 1.77e-13: close. Braced square: ρ = ε × 1 / 0.7071 (largest coordinate over the characteristic
// length), B / σ_max = (30 + 2·6·1.414) ε = 1.04e-14, far below 0.297: certain.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <string>

#include "framework_test_support.hpp"
#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::framework {
namespace {

using testing::load_example;
using testing::parse_model;

// examples/truss-12.yaml with E at (x, -1, 1).
FrameworkModel truss_with_e_at(const std::string& x) {
  return parse_model(fmt::format(
      "kinestat: 1\nkind: framework\ndimension: spatial\n"
      "nodes: {{A: [-1, -1, 0], B: [1, -1, 0], C: [1, 1, 0], D: [-1, 1, 0], E: [{}, -1, 1], F: [1, 0, 1], G: [0, 1, 1], H: [-1, 0, 1]}}\n"
      "supports: {{A: fixed, B: fixed, C: fixed, D: fixed}}\n"
      "elements: [{{type: truss, nodes: [A, E]}}, {{type: truss, nodes: [B, E]}}, {{type: truss, nodes: [B, F]}},\n"
      "  {{type: truss, nodes: [C, F]}}, {{type: truss, nodes: [C, G]}}, {{type: truss, nodes: [D, G]}},\n"
      "  {{type: truss, nodes: [D, H]}}, {{type: truss, nodes: [A, H]}}, {{type: truss, nodes: [E, F]}},\n"
      "  {{type: truss, nodes: [F, G]}}, {{type: truss, nodes: [G, H]}}, {{type: truss, nodes: [H, E]}}]\n",
      x));
}

TEST(FrameworkRankStatus, WellConditionedTrussIsCertain) {
  const FrameworkModel model = load_example("braced-square.yaml");
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.rank, 5);
  EXPECT_EQ(a.decision.status(), linalg::RankStatus::certain);
  ASSERT_TRUE(a.decision.distance().has_value());
  EXPECT_NEAR(*a.decision.distance(), 0.29729, 1e-4);
  const auto j = report::framework_report_json(model, a);
  EXPECT_EQ(j["rank_decision"]["status"], "certain");
  EXPECT_NEAR(j["rank_decision"]["distance"].get<double>(), 0.297, 1e-3);
  EXPECT_EQ(j["rank_decision"]["close"], false);
  const design::Verdict v = design::framework_verdict(model, a, {});
  EXPECT_FALSE(v.near_rank_change.has_value());
}

TEST(FrameworkRankStatus, TwelveTrussesMovedBy1eMinus12AreFullRankButClose) {
  const FrameworkModel model = truss_with_e_at("0.0000000000015");  // 1e-12 × 1.5
  const FrameworkResult a = analyse_framework(model);
  EXPECT_EQ(a.rank, 12);  // the default threshold (2.7e-15 of σ_max) keeps 1.77e-13
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.decision.status(), linalg::RankStatus::close);
  ASSERT_TRUE(a.decision.distance().has_value());
  EXPECT_NEAR(*a.decision.distance(), 0.17678e-12, 0.1 * 0.17678e-12);
  EXPECT_NEAR(a.relative_smallest_singular_value(), 0.17678e-12, 0.1 * 0.17678e-12);

  const design::Verdict v = design::framework_verdict(model, a, {});
  ASSERT_TRUE(v.near_rank_change.has_value());
  EXPECT_NE(v.summary.find("Exactly constrained"), std::string::npos) << v.summary;
  EXPECT_NE(v.summary.find(", but 1.77e-13 from a mechanism."), std::string::npos) << v.summary;

  const std::string text = report::framework_report_text(model, a, &v);
  EXPECT_EQ(text.find("smallest/largest singular value: 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("smallest/largest singular value: 1.77e-13\n"), std::string::npos) << text;
  EXPECT_NE(text.find("rank 12 of 12: CLOSE; 1.77e-13 from rank 11"), std::string::npos) << text;
  const auto j = report::framework_report_json(model, a, &v);
  EXPECT_EQ(j["rank_decision"]["status"], "close");
  EXPECT_EQ(j["rank_decision"]["close"], true);
  EXPECT_NEAR(j["rank_decision"]["distance"].get<double>(), 1.77e-13, 0.01e-13);
  EXPECT_NEAR(j["verdict"]["near_rank_change"].get<double>(), 1.77e-13, 0.01e-13);
}

TEST(FrameworkRankStatus, DistanceIsLinearInTheMoveAndNotNearAt1eMinus3) {
  for (const auto& [x, delta] : {std::pair<std::string, double>{"0.0015", 1e-3}, {"0.0000015", 1e-6}, {"0.0000000015", 1e-9}}) {
    SCOPED_TRACE(x);
    const FrameworkModel model = truss_with_e_at(x);
    const FrameworkResult a = analyse_framework(model);
    EXPECT_EQ(a.rank, 12);
    EXPECT_EQ(a.decision.status(), linalg::RankStatus::certain);  // far above the bound 3.7e-12
    EXPECT_NEAR(*a.decision.distance(), 0.17678 * delta, 0.01 * 0.17678 * delta);
    const design::Verdict v = design::framework_verdict(model, a, {});
    EXPECT_EQ(v.near_rank_change.has_value(), 0.17678 * delta < kNearRankChange);
  }
}

}  // namespace
}  // namespace kinestat::framework
