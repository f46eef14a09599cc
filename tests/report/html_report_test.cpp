// SPDX-License-Identifier: BSD-3-Clause
// `kinestat report`: one self-contained HTML file, errors with exit code 2, and large models
// that still give a bounded file (elements merged into one line set above kLargeSceneElements).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "kinestat/report/html_writer.hpp"
#include "kinestat/report/scene.hpp"
#include "support/cli_run.hpp"

namespace {

using kinestat::testing::example_path;
using kinestat::testing::run_cli;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string temp(const std::string& name) {
  return (kinestat::testing::scratch_folder() / name).string();
}

TEST(HtmlReport, SelfContainedFileForTheTruss) {
  if (!kinestat::report::html_report_built_in()) {
    const auto run = run_cli("report " + example_path("truss-12.yaml") + " -o " + temp("x.html"));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("HTML output is not built in"), std::string::npos) << run.err;
    GTEST_SKIP() << "built without npm: HTML output is not built in";
  }
  const std::string path = temp("truss.html");
  const auto run = run_cli("report " + example_path("truss-12.yaml") + " -o " + path);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string html = read_text(path);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("window.KINESTAT_SCENE = {"), std::string::npos);
  EXPECT_NE(html.find("\"self-stress 1\""), std::string::npos);
  EXPECT_NE(html.find("three.js"), std::string::npos);  // the library's licence header: inlined
  // Offline: nothing is fetched from anywhere.
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  // Deterministic.
  const auto again = run_cli("report " + example_path("truss-12.yaml"));
  EXPECT_EQ(again.out, html);
  std::filesystem::remove(path);
}

TEST(HtmlReport, UnwritableOutputIsExitTwo) {
  if (!kinestat::report::html_report_built_in()) GTEST_SKIP() << "HTML output is not built in";
  const auto run = run_cli("report " + example_path("davies-2-circuit.yaml") + " -o /nonexistent-folder/r.html");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/nonexistent-folder/r.html: error: cannot write output file"), std::string::npos) << run.err;
}

TEST(HtmlReport, MissingModelIsExitTwo) {
  const auto run = run_cli("report /nonexistent-model.yaml -o " + temp("y.html"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/nonexistent-model.yaml"), std::string::npos) << run.err;
}

TEST(HtmlReport, ScriptTextCannotCloseTheScriptElement) {
  kinestat::report::Scene scene;
  scene.kind = kinestat::io::ModelKind::framework;
  scene.name = "evil </script><script>alert(1)</script>";
  const std::string json = kinestat::report::scene_json(scene).dump();
  EXPECT_NE(json.find("</script>"), std::string::npos);  // the raw JSON has it ...
  if (!kinestat::report::html_report_built_in()) GTEST_SKIP();
  const std::string html = kinestat::report::html_report(scene);
  EXPECT_EQ(html.find("alert(1)</script>"), std::string::npos);  // ... the page does not
}

// A planar strip of about 200 000 bars: the report and the drawing are produced and bounded.
TEST(LargeModel, TwoHundredThousandElementsGiveBoundedFiles) {
  const int columns = 66700;
  std::string model = "kinestat: 1\nkind: framework\nname: large strip\ndimension: planar\nnodes:\n";
  for (int i = 0; i < columns; ++i)
    model += "  a" + std::to_string(i) + ": [" + std::to_string(i) + ", 0]\n  b" + std::to_string(i) + ": [" + std::to_string(i) + ", 1]\n";
  model += "supports: {a0: fixed, b0: fixed}\nelements:\n";
  for (int i = 0; i + 1 < columns; ++i) {
    const std::string a = "a" + std::to_string(i), b = "b" + std::to_string(i);
    const std::string a1 = "a" + std::to_string(i + 1), b1 = "b" + std::to_string(i + 1);
    model += "  - {type: truss, nodes: [" + a + ", " + a1 + "]}\n  - {type: truss, nodes: [" + b + ", " + b1 +
             "]}\n  - {type: truss, nodes: [" + a1 + ", " + b + "]}\n";
  }
  const std::string path = kinestat::testing::write_temp_file("large_strip.yaml", model);
  const std::string svg = temp("large.svg");
  auto run = run_cli("draw " + path + " -o " + svg);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LT(std::filesystem::file_size(svg), 8u * 1024 * 1024);
  EXPECT_NE(read_text(svg).find("elements: drawn as one path"), std::string::npos);
  std::filesystem::remove(svg);
  if (kinestat::report::html_report_built_in()) {
    const std::string html = temp("large.html");
    run = run_cli("report " + path + " -o " + html);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_LT(std::filesystem::file_size(html), 12u * 1024 * 1024);
    EXPECT_NE(read_text(html).find("\"large\":true"), std::string::npos);
    std::filesystem::remove(html);
  }
  std::filesystem::remove(path);
}

}  // namespace
