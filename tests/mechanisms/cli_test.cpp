// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze` on every mechanism example: exit code 0, JSON that parses and carries the
// published FN and CN, byte-identical output for the same input.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace {

kinestat::testing::CliRun run(const std::string& arguments) { return kinestat::testing::run_cli(arguments); }

std::string example(const std::string& file) { return "\"" + kinestat::testing::example_path(file) + "\""; }

struct Expected {
  std::string file;
  int F, C, l, k, FN, CN;  // F, C, l, k: hand counts; FN, CN: the published values
  std::string classification;
};

std::ostream& operator<<(std::ostream& os, const Expected& e) { return os << e.file; }

// Hand counts: F = sum of joint freedoms, C = d e - F, l = e - n + 1, k = n - 1.
const std::vector<Expected> kExamples = {
    {"single-circuit-two-spheres.yaml", 6, 6, 1, 1, 1, 1, "overconstrained_chain"},
    {"four-bar-planar.yaml", 4, 8, 1, 3, 1, 0, "kinematically_designed_chain"},
    {"four-bar-spatial.yaml", 4, 20, 1, 3, 1, 3, "overconstrained_chain"},
    {"slider-crank-planar.yaml", 4, 8, 1, 3, 1, 0, "kinematically_designed_chain"},
    {"bennett.yaml", 4, 20, 1, 3, 1, 3, "overconstrained_chain"},
    {"bennett-perturbed.yaml", 4, 20, 1, 3, 0, 2, "overconstrained_structure"},
    {"spherical-4r.yaml", 4, 20, 1, 3, 1, 3, "overconstrained_chain"},
    {"stewart-6ups.yaml", 36, 72, 5, 13, 6, 0, "kinematically_designed_chain"},
    {"sarrus.yaml", 6, 30, 1, 5, 1, 1, "overconstrained_chain"},
    {"parallelogram.yaml", 4, 8, 1, 3, 1, 0, "kinematically_designed_chain"},
    {"parallelogram-redundant.yaml", 6, 12, 2, 4, 1, 1, "overconstrained_chain"},
    {"tsai-3upu.yaml", 15, 39, 2, 7, 3, 0, "kinematically_designed_chain"},
    {"screw-jack.yaml", 3, 15, 1, 2, 1, 4, "overconstrained_chain"},
};

class AnalyzeCommand : public ::testing::TestWithParam<Expected> {};

TEST_P(AnalyzeCommand, TextReportExitsZero) {
  const auto result = run("analyze " + example(GetParam().file));
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_FALSE(result.out.empty());
}

TEST_P(AnalyzeCommand, JsonHasThePublishedValues) {
  const auto& e = GetParam();
  const auto result = run("analyze --json " + example(e.file));
  ASSERT_EQ(result.exit_code, 0);
  const auto j = nlohmann::json::parse(result.out);
  for (const char* key : {"F", "C", "l", "k", "rank_motion", "rank_action", "FN", "CN", "classification", "pairs",
                          "primary_motion", "primary_action", "motions", "actions"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["F"], e.F);
  EXPECT_EQ(j["C"], e.C);
  EXPECT_EQ(j["l"], e.l);
  EXPECT_EQ(j["k"], e.k);
  EXPECT_EQ(j["FN"], e.FN);
  EXPECT_EQ(j["CN"], e.CN);
  EXPECT_EQ(j["rank_motion"], e.F - e.FN);  // FN = F - m
  EXPECT_EQ(j["rank_action"], e.C - e.CN);  // CN = C - a
  EXPECT_EQ(j["classification"], e.classification);
  EXPECT_EQ(j["primary_motion"].size(), static_cast<std::size_t>(e.FN));
  EXPECT_EQ(j["primary_action"].size(), static_cast<std::size_t>(e.CN));
  EXPECT_EQ(j["motions"].size(), static_cast<std::size_t>(e.F));
  EXPECT_EQ(j["actions"].size(), static_cast<std::size_t>(e.C));
  EXPECT_TRUE(j["pairs"].is_array());
  EXPECT_FALSE(j["pairs"].empty());
}

TEST_P(AnalyzeCommand, JsonIsByteIdenticalTwice) {
  const auto first = run("analyze --json " + example(GetParam().file));
  const auto second = run("analyze --json " + example(GetParam().file));
  ASSERT_EQ(first.exit_code, 0);
  EXPECT_EQ(first.out, second.out);
}

TEST_P(AnalyzeCommand, FloatingPointGivesTheSameFNAndCN) {
  const auto result = run("analyze --json --float " + example(GetParam().file));
  ASSERT_EQ(result.exit_code, 0);
  const auto j = nlohmann::json::parse(result.out);
  EXPECT_EQ(j["arithmetic"], "floating");
  EXPECT_EQ(j["FN"], GetParam().FN);
  EXPECT_EQ(j["CN"], GetParam().CN);
}

INSTANTIATE_TEST_SUITE_P(Examples, AnalyzeCommand, ::testing::ValuesIn(kExamples), [](const ::testing::TestParamInfo<Expected>& param_info) {
  std::string name = param_info.param.file.substr(0, param_info.param.file.find('.'));
  for (char& ch : name)
    if (ch == '-') ch = '_';
  return name;
});

TEST(AnalyzeCommand, PairTableOfTheTwoSpheres) {
  // Seed 000, section 2.1: fij = 1 for the two bodies; section 2.2: each coupling transmits
  // one action (cij = 1).
  const auto result = run("analyze --json " + example("single-circuit-two-spheres.yaml"));
  ASSERT_EQ(result.exit_code, 0);
  const auto j = nlohmann::json::parse(result.out);
  ASSERT_EQ(j["pairs"].size(), 2u);
  for (const auto& pair : j["pairs"]) {
    EXPECT_EQ(pair["f"], 3);
    EXPECT_EQ(pair["fij"], 1);
    EXPECT_EQ(pair["c"], 3);
    EXPECT_EQ(pair["cij"], 1);
  }
}

}  // namespace
