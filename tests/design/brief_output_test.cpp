// SPDX-License-Identifier: BSD-3-Clause
// Issue 35, item 7: `--brief` prints the verdict block alone — in text, the lines from "Verdict:"
// to the blank line that ends the block; in JSON, just the `verdict` object — and the same
// verdict as the full report.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;

TEST(BriefOutput, TextIsTheVerdictBlockOfTheFullReport) {
  for (const std::string command : {"analyze", "structure"}) {
    SCOPED_TRACE(command);
    const auto full = run_cli(command + " " + example_path("bennett.yaml"));
    const auto brief = run_cli(command + " --brief " + example_path("bennett.yaml"));
    ASSERT_EQ(brief.exit_code, 0) << brief.err;
    EXPECT_EQ(brief.out.rfind("Verdict: ", 0), 0u);
    EXPECT_EQ(brief.out.find("\n\n"), std::string::npos);  // one block, no detail after it
    EXPECT_EQ(full.out.rfind(brief.out, 0), 0u);             // the full report starts with it
  }
}

TEST(BriefOutput, JsonIsTheVerdictObjectAlone) {
  const auto full = run_cli("analyze --json " + example_path("four-bar-planar.yaml"));
  const auto brief = run_cli("analyze --json --brief " + example_path("four-bar-planar.yaml"));
  ASSERT_EQ(brief.exit_code, 0) << brief.err;
  auto verdict = nlohmann::json::parse(brief.out);
  const auto report = nlohmann::json::parse(full.out);
  // Every JSON output names its versions (issue 39): the full report's.
  EXPECT_EQ(verdict["kinestat_version"], report["kinestat_version"]);
  EXPECT_EQ(verdict["report_version"], report["report_version"]);
  verdict.erase("kinestat_version");
  verdict.erase("report_version");
  EXPECT_EQ(verdict, report["verdict"]);
  EXPECT_TRUE(verdict.contains("summary"));
  EXPECT_FALSE(verdict.contains("verdict"));
}

// The verdict block of every shipped example fits in 25 lines (issue 35, item 7). Under
// AddressSanitizer a fixed quarter of each folder (support/sanitizer_sample.hpp).
TEST(BriefOutput, EveryExamplesVerdictBlockFitsIn25Lines) {
  for (const std::string folder : {"", "robots/"}) {
    for (const std::string& path : testing::sampled_files(example_path(folder))) {
      auto run = run_cli("analyze --brief " + path);
      if (run.exit_code != 0) run = run_cli("structure --brief " + path);  // kind: structure
      if (run.exit_code != 0) continue;                                   // not a model (e.g. a README)
      SCOPED_TRACE(path);
      EXPECT_EQ(run.out.rfind("Verdict: ", 0), 0u);
      EXPECT_LE(std::count(run.out.begin(), run.out.end(), '\n'), 25);
    }
  }
}

}  // namespace
}  // namespace kinestat
