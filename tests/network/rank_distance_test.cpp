// SPDX-License-Identifier: BSD-3-Clause
// Issue 12, item 2: every rank decision has a status (exact, certain, close) and a distance to
// another rank. Exact analyses of designs a little away from a mobile one (Bennett's linkage, the
// parallelogram with a redundant crank) say FN = 0 exactly, and how near the mobile design is
// (the distance, from a floating-point SVD alongside), in text, JSON and HTML.
//
// The perturbed models move one coupling point by δ × the model's size, written as a short
// decimal so that automatic arithmetic is exact:
// - Bennett (examples/bennett.yaml, size 580 = its largest coordinate): J1's point (0, 0, 0)
//   moves to (580 δ, 0, 0). J1's axis is z, so its line moves off the Bennett geometry (the link
//   length a changes while the twists stay): a general 4R loop, rank M^N = 4, FN = 0, CN = 2.
// - Parallelogram with a redundant crank (size 8): A (0, 0) moves to (8 δ, 0). Crank 1 is no
//   longer parallel to the other two, so the coupler cannot translate: FN = 0, CN = 0
//   (FN − CN = F − 3 l = 0).
// Expected distance (smallest kept / largest singular value of the conditioned M^N): the special
// design has σ_min = 0. Moving one point by p changes one twist's moment by at most p (|Δr × ω|,
// ω a unit vector), which is p / L in the conditioned frame (L: largest coordinate distance from
// the centroid: 306 for Bennett, 4 for the parallelogram, so p / L ≈ 1.9 δ and 2 δ). By Weyl's
// theorem σ_min ≤ p / L, and σ_max ≥ 1 (each column holds a unit ω), so distance ≤ 2 δ. From
// below, first-order perturbation of a simple zero singular value gives σ_min ≈ |u₀ᵀ E v₀| ∝ δ,
// with a geometric factor that is not tiny for a generic direction of the move: the bracket
// [δ / 100, 100 δ] holds with margin, and distance(1e-6) / distance(1e-9) ≈ 1000 (linear in δ).
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "kinestat/tolerances.hpp"
#include "support/cli_run.hpp"

namespace {

using kinestat::testing::run_cli;
using kinestat::testing::write_temp_file;
using Json = nlohmann::json;

// `digits` (e.g. "58") times 10^-(exponent): a short decimal "0.000…58".
std::string short_decimal(const std::string& digits, int exponent) {
  return "0." + std::string(static_cast<std::size_t>(exponent - static_cast<int>(digits.size())), '0') + digits;
}

// Bennett with J1 moved by 10^-k of the model size: 580 · 10^-k = 58 · 10^-(k-1).
std::string bennett(int k) {
  return fmt::format(
      "kinestat: 1\nkind: network\nname: Bennett moved by 1e-{}\ndimension: spatial\nground: ground\ncouplings:\n"
      "  - {{name: J1, type: revolute, between: [ground, link1], point: [{}, 0, 0], axis: [0, 0, 1]}}\n"
      "  - {{name: J2, type: revolute, between: [link1, link2], point: [-261, 348, 0], axis: [12, 9, 20]}}\n"
      "  - {{name: J3, type: revolute, between: [link2, link3], point: [-265, -180, 240], axis: [-12, 11, 24]}}\n"
      "  - {{name: J4, type: revolute, between: [link3, ground], point: [-580, 0, 0], axis: [0, 4, 3]}}\n",
      k, short_decimal("58", k - 1));
}

// The parallelogram with a redundant crank with A moved by 8 · 10^-k.
std::string parallelogram(int k) {
  return fmt::format(
      "kinestat: 1\nkind: network\nname: parallelogram moved by 1e-{}\ndimension: planar\nground: ground\ncouplings:\n"
      "  - {{name: A, type: revolute, between: [ground, crank1], point: [{}, 0]}}\n"
      "  - {{name: B, type: revolute, between: [crank1, coupler], point: [2, 4]}}\n"
      "  - {{name: C, type: revolute, between: [coupler, crank2], point: [8, 4]}}\n"
      "  - {{name: D, type: revolute, between: [crank2, ground], point: [6, 0]}}\n"
      "  - {{name: E, type: revolute, between: [ground, crank3], point: [3, 0]}}\n"
      "  - {{name: H, type: revolute, between: [crank3, coupler], point: [5, 4]}}\n",
      k, short_decimal("8", k));
}

struct Case {
  std::string name;
  std::string text;
  double delta;
  int CN;
};

Json analyse_json(const Case& c) {
  const std::string path = write_temp_file(c.name + ".yaml", c.text);
  const auto run = run_cli("analyze --json " + path);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return Json::parse(run.out);
}

std::vector<Case> cases(int k) {
  return {{fmt::format("bennett-{}", k), bennett(k), std::pow(10.0, -k), 2},
          {fmt::format("parallelogram-{}", k), parallelogram(k), std::pow(10.0, -k), 0}};
}

TEST(RankDistance, ShortDecimalsAreWhatTheTestMeans) {
  EXPECT_EQ(short_decimal("58", 2), "0.58");        // 580 · 1e-3
  EXPECT_EQ(short_decimal("58", 11), "0.00000000058");  // 580 · 1e-12
  EXPECT_EQ(short_decimal("8", 3), "0.008");        // 8 · 1e-3
}

TEST(RankDistance, PerturbedSpecialDesignsAreExactlyRigidAndSayHowNearTheMechanismIs) {
  double bennett_6 = 0, bennett_9 = 0, parallelogram_6 = 0, parallelogram_9 = 0;
  for (int k : {3, 6, 9, 12}) {
    for (const Case& c : cases(k)) {
      SCOPED_TRACE(c.name);
      const Json j = analyse_json(c);
      EXPECT_EQ(j["arithmetic"], "exact");
      EXPECT_EQ(j["FN"], 0);
      EXPECT_EQ(j["CN"], c.CN);
      const Json& motion = j["rank_evidence"]["motion"];
      EXPECT_EQ(motion["status"], "exact");
      EXPECT_FALSE(motion.contains("close"));  // exact decisions have no closeness flag: no tolerance
      ASSERT_TRUE(motion["distance"].is_number());
      const double distance = motion["distance"];
      EXPECT_GE(distance, c.delta / 100);
      EXPECT_LE(distance, 100 * c.delta);
      if (k == 6) (c.CN == 2 ? bennett_6 : parallelogram_6) = distance;
      if (k == 9) (c.CN == 2 ? bennett_9 : parallelogram_9) = distance;
      const Json& verdict = j["verdict"];
      EXPECT_TRUE(verdict["exactly_constrained"] == (c.CN == 0));
      if (k == 3) {
        // 1e-3 is not close: no note in the verdict.
        EXPECT_FALSE(verdict.contains("near_rank_change"));
        EXPECT_EQ(verdict["summary"].get<std::string>().find("from a mechanism"), std::string::npos);
      } else if (k >= 9) {
        ASSERT_TRUE(verdict.contains("near_rank_change"));
        EXPECT_DOUBLE_EQ(verdict["near_rank_change"].get<double>(), distance);
        EXPECT_NE(verdict["summary"].get<std::string>().find("from a mechanism"), std::string::npos);
      }
    }
  }
  // Linear in δ: a thousand times nearer at 1e-9 than at 1e-6.
  EXPECT_NEAR(bennett_6 / bennett_9, 1000, 100);
  EXPECT_NEAR(parallelogram_6 / parallelogram_9, 1000, 100);
}

TEST(RankDistance, TextAndHtmlShowTheStatusAndTheDistance) {
  const Case c = cases(9).front();
  const std::string path = write_temp_file(c.name + "-text.yaml", c.text);
  const auto text = run_cli("analyze " + path);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("    rank 4 of 4: exact; "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" from rank 3 (smallest kept / largest singular value of a floating-point copy)"), std::string::npos);
  EXPECT_NE(text.out.find("Verdict: Not exactly constrained"), std::string::npos);
  EXPECT_NE(text.out.find(", but "), std::string::npos);
  EXPECT_NE(text.out.find(" from a mechanism."), std::string::npos);

  const auto html = run_cli("report " + path);
  if (html.exit_code != 0) GTEST_SKIP() << "no HTML report in this build: " << html.err;
  EXPECT_NE(html.out.find("near_rank_change"), std::string::npos);
  EXPECT_NE(html.out.find("rank 4 of 4: exact; "), std::string::npos);
}

}  // namespace
