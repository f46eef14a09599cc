// SPDX-License-Identifier: BSD-3-Clause
// SVG drawings are deterministic and match the stored, eye-reviewed files under
// tests/report/golden/. To regenerate after an intended change (then look at every changed
// picture before committing it):
//   KINESTAT_UPDATE_GOLDEN=1 ./build/release/tests/kinestat_report_tests --gtest_filter='Golden*'

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"

namespace {

using kinestat::testing::example_path;
using kinestat::testing::run_cli;

struct GoldenCase {
  const char* golden;   // file name under tests/report/golden
  const char* example;  // file name under examples
  const char* options;  // extra options of `kinestat draw`
};

const GoldenCase kCases[] = {
    {"davies-2-circuit-graph.svg", "davies-2-circuit.yaml", "--what graph"},
    {"davies-2-circuit-mechanism-mode3.svg", "davies-2-circuit.yaml", "--what mechanism --mode 3"},
    {"truss-12-mechanism.svg", "truss-12.yaml", "--what mechanism"},
    {"four-bar-linkage-mechanism.svg", "four-bar-linkage.yaml", ""},
    {"wire-flexure-guide-mechanism.svg", "wire-flexure-guide.yaml", "--what mechanism"},
    {"saura-eq2-graph.svg", "saura-eq2.yaml", "--what graph"},
    {"saura-eq2-structure.svg", "saura-eq2.yaml", "--what structure"},
    {"stephenson-six-bar-graph.svg", "stephenson-six-bar.yaml", ""},
};

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class GoldenSvg : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenSvg, MatchesStoredDrawing) {
  const GoldenCase& c = GetParam();
  const auto run = run_cli("draw " + example_path(c.example) + " " + c.options);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::filesystem::path golden = std::filesystem::path(KINESTAT_SOURCE_DIR) / "tests/report/golden" / c.golden;
  const char* update = std::getenv("KINESTAT_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    std::ofstream(golden, std::ios::binary) << run.out;
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; run with KINESTAT_UPDATE_GOLDEN=1";
  EXPECT_TRUE(read(golden) == run.out) << c.golden << " differs from the drawing of " << c.example
                                       << "; if the change is intended, regenerate with KINESTAT_UPDATE_GOLDEN=1 and look at it";
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenSvg, ::testing::ValuesIn(kCases), [](const auto& case_info) {
  std::string name = case_info.param.golden;
  name = name.substr(0, name.size() - 4);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
});

TEST(DrawCli, SameModelGivesIdenticalBytes) {
  const auto a = run_cli("draw " + example_path("truss-12.yaml"));
  const auto b = run_cli("draw " + example_path("truss-12.yaml"));
  ASSERT_EQ(a.exit_code, 0);
  EXPECT_EQ(a.out, b.out);
}

// Under AddressSanitizer a quarter of the examples (support/sanitizer_sample.hpp).
TEST(DrawCli, EveryExampleDrawsWithItsDefault) {
  std::vector<std::string> examples;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples"))
    if (entry.path().extension() == ".yaml") examples.push_back(entry.path().string());
  for (const std::string& path : kinestat::testing::sampled_under_sanitizer(examples)) {
    const auto run = run_cli("draw " + path);
    EXPECT_EQ(run.exit_code, 0) << path << ": " << run.err;
    EXPECT_NE(run.out.find("<svg"), std::string::npos) << path;
    EXPECT_NE(run.out.find("</svg>"), std::string::npos) << path;
  }
}

TEST(DrawCli, UnwritableOutputIsExitTwoWithMessage) {
  const auto run = run_cli("draw " + example_path("truss-12.yaml") + " -o /nonexistent-folder/x.svg");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/nonexistent-folder/x.svg: error: cannot write output file"), std::string::npos) << run.err;
}

TEST(DrawCli, WritesTheFileGiven) {
  const auto path = kinestat::testing::scratch_folder() / "draw.svg";
  const auto run = run_cli("draw " + example_path("davies-2-circuit.yaml") + " -o " + path.string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(read(path).find("coupling graph"), std::string::npos);
  std::filesystem::remove(path);
}

TEST(DrawCli, DrawingsThatDoNotApplyAreRefused) {
  auto run = run_cli("draw " + example_path("truss-12.yaml") + " --what graph");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("has no coupling graph"), std::string::npos) << run.err;
  run = run_cli("draw " + example_path("saura-eq2.yaml") + " --what mechanism");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no geometry"), std::string::npos) << run.err;
  run = run_cli("draw " + example_path("truss-12.yaml") + " --what structure");
  EXPECT_EQ(run.exit_code, 2);
  run = run_cli("draw " + example_path("truss-12.yaml") + " --mode 5");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("1 kinematic mode"), std::string::npos) << run.err;
  run = run_cli("draw " + example_path("truss-12.yaml") + " --what pictures");
  EXPECT_EQ(run.exit_code, 2);
}

TEST(DrawCli, BadModelIsExitTwoWithPosition) {
  const auto path = kinestat::testing::write_temp_file("bad_draw.yaml", "kinestat: 1\nkind: framework\nnodes: [1, 2\n");
  const auto run = run_cli("draw " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path + ":"), std::string::npos) << run.err;
}

}  // namespace
