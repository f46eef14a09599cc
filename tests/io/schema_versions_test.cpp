// SPDX-License-Identifier: BSD-3-Clause
// Issue 39, item 4: versions in every JSON report, `$schema` accepted in models, and files of
// format version 1 read as that version says: every earlier spelling (tests/io/data/format-1-*)
// still works, with a notice naming the new spelling, and gives the report of the new spelling.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;
using testing::write_temp_file;

std::string spelling_data_path(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/tests/io/data/" + name; }

std::string spelling_file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string spelling_replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

struct OldSpelling {
  std::string file, command, old_line, new_line;
};

// "line:column" of the value of `key_and_value` (a line "key: value") in `text`.
std::string spelling_value_position(const std::string& text, const std::string& key_and_value) {
  const auto at = text.find("\n" + key_and_value + "\n");
  const auto line = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at + 1), '\n') + 1;
  return std::to_string(line) + ":" + std::to_string(key_and_value.find(": ") + 3);
}

// Each file of an earlier spelling: exit 0, one notice at the old spelling that names the new
// one, and the very report of the same file written in the new spelling.
TEST(FormatVersionOne, EveryEarlierSpellingIsReadWithANoticeAsTheNewOne) {
  const std::vector<OldSpelling> files{
      {"format-1-structure-space-planar.yaml", "structure", "space: planar", "dimension: planar"},
      {"format-1-structure-space-spatial.yaml", "structure", "space: spatial", "dimension: spatial"},
      {"format-1-network-dimension-3.yaml", "analyze", "dimension: 3", "dimension: planar"},
      {"format-1-network-dimension-6.yaml", "analyze", "dimension: 6", "dimension: spatial"},
      {"format-1-framework-dimension-2.yaml", "analyze", "dimension: 2", "dimension: planar"},
      {"format-1-framework-dimension-3.yaml", "analyze", "dimension: 3", "dimension: spatial"},
  };
  for (const auto& f : files) {
    SCOPED_TRACE(f.file);
    const std::string path = spelling_data_path(f.file);
    const auto old_run = run_cli(f.command + " --json " + path);
    ASSERT_EQ(old_run.exit_code, 0) << old_run.err;
    const std::string at = spelling_value_position(spelling_file_text(path), f.old_line);
    EXPECT_NE(old_run.err.find(path + ":" + at + ": note: '" + f.old_line + "' is the older spelling of '" + f.new_line + "'"),
              std::string::npos)
        << old_run.err;
    EXPECT_NE(old_run.err.find("write '" + f.new_line + "'"), std::string::npos) << old_run.err;
    EXPECT_EQ(std::count(old_run.err.begin(), old_run.err.end(), '\n'), 1) << old_run.err;
    const std::string new_path =
        write_temp_file("new-" + f.file, spelling_replaced(spelling_file_text(path), "\n" + f.old_line + "\n", "\n" + f.new_line + "\n"));
    const auto new_run = run_cli(f.command + " --json " + new_path);
    ASSERT_EQ(new_run.exit_code, 0) << new_run.err;
    EXPECT_TRUE(new_run.err.empty()) << new_run.err;
    // The notice is in the JSON report too (the line printed on standard error), and nothing
    // else differs.
    nlohmann::json old_report = nlohmann::json::parse(old_run.out);
    ASSERT_TRUE(old_report.contains("notices")) << old_run.out;
    EXPECT_EQ(old_report["notices"], nlohmann::json::array({old_run.err.substr(0, old_run.err.size() - 1)}));
    old_report.erase("notices");
    const nlohmann::json new_report = nlohmann::json::parse(new_run.out);
    EXPECT_FALSE(new_report.contains("notices")) << new_run.out;
    EXPECT_EQ(old_report, new_report);
  }
}

// The counts of the old-spelling files, derived by hand in each file's comment.
TEST(FormatVersionOne, OldSpellingsGiveTheCountsDerivedByHand) {
  auto json = [](const std::string& command, const std::string& file) {
    const auto run = run_cli(command + " --json " + spelling_data_path(file));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return nlohmann::json::parse(run.out);
  };
  EXPECT_EQ(json("structure", "format-1-structure-space-planar.yaml")["mobility"], 1);
  EXPECT_EQ(json("structure", "format-1-structure-space-planar.yaml")["space"], "planar");
  EXPECT_EQ(json("structure", "format-1-structure-space-spatial.yaml")["mobility"], 2);
  EXPECT_EQ(json("structure", "format-1-structure-space-spatial.yaml")["space"], "spatial");
  const auto planar = json("analyze", "format-1-network-dimension-3.yaml");
  EXPECT_EQ(planar["FN"], 1);
  EXPECT_EQ(planar["CN"], 0);
  EXPECT_EQ(planar["dimension"], 3);
  const auto spatial = json("analyze", "format-1-network-dimension-6.yaml");
  EXPECT_EQ(spatial["FN"], 1);
  EXPECT_EQ(spatial["CN"], 3);
  for (const char* file : {"format-1-framework-dimension-2.yaml", "format-1-framework-dimension-3.yaml"}) {
    const auto framework = json("analyze", file);
    EXPECT_EQ(framework["rows"], framework["cols"]) << file;
    EXPECT_EQ(framework["mechanisms"], 0) << file;
    EXPECT_EQ(framework["self_stresses"], 0) << file;
  }
  EXPECT_EQ(json("analyze", "format-1-framework-dimension-2.yaml")["rows"], 2);
  EXPECT_EQ(json("analyze", "format-1-framework-dimension-3.yaml")["rows"], 3);
}

// What was never a spelling of version 1 stays an error that says what to write.
TEST(FormatVersionOne, WhatWasNeverASpellingIsStillRefused) {
  const std::string planar_structure = spelling_file_text(spelling_data_path("format-1-structure-space-planar.yaml"));
  const auto number = run_cli("structure " + write_temp_file("st-3.yaml", spelling_replaced(planar_structure, "space: planar", "dimension: 3")));
  EXPECT_EQ(number.exit_code, 2);
  EXPECT_NE(number.err.find("dimension: planar"), std::string::npos) << number.err;
  const auto both =
      run_cli("structure " + write_temp_file("st-both.yaml", spelling_replaced(planar_structure, "space: planar", "space: planar\ndimension: planar")));
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find(":7:8: error: 'space' is the older spelling of 'dimension'"), std::string::npos) << both.err;
  const std::string framework = spelling_file_text(spelling_data_path("format-1-framework-dimension-2.yaml"));
  const auto six = run_cli("analyze " + write_temp_file("fw-6.yaml", spelling_replaced(framework, "dimension: 2", "dimension: 6")));
  EXPECT_EQ(six.exit_code, 2);
  EXPECT_NE(six.err.find("dimension: spatial"), std::string::npos) << six.err;
  const std::string network = spelling_file_text(spelling_data_path("format-1-network-dimension-3.yaml"));
  const auto two = run_cli("analyze " + write_temp_file("nw-2.yaml", spelling_replaced(network, "dimension: 3", "dimension: 2")));
  EXPECT_EQ(two.exit_code, 2);
  EXPECT_NE(two.err.find("dimension: planar"), std::string::npos) << two.err;
}

TEST(ModelSchemaKey, IsAcceptedAndIgnoredInEveryKind) {
  for (const auto& [file, command] : std::vector<std::pair<std::string, std::string>>{{"json/davies-2-circuit.json", "analyze"},
                                                                                     {"json/truss-12.json", "analyze"},
                                                                                     {"json/class-iii-triad.json", "structure"}}) {
    SCOPED_TRACE(file);
    const std::string text = spelling_file_text(example_path(file));
    const std::string with_schema = spelling_replaced(text, "{", "{\n  \"$schema\": \"https://example.org/kinestat/model-v1.schema.json\",");
    const auto plain = run_cli(command + " --json " + example_path(file));
    const auto marked = run_cli(command + " --json " + write_temp_file("schema-" + file.substr(5), with_schema));
    ASSERT_EQ(marked.exit_code, 0) << marked.err;
    EXPECT_TRUE(marked.err.empty()) << marked.err;
    EXPECT_EQ(nlohmann::json::parse(marked.out), nlohmann::json::parse(plain.out));
  }
  const std::string sweep = "kinestat: 1\n$schema: sweep-v1.schema.json\nkind: sweep\nmodel: " + example_path("sweeps/two-bars.yaml") +
                            "\nparameters:\n  - {name: b, node: B, coordinate: y, values: [0.5, 1]}\n";
  const auto run = run_cli("sweep " + write_temp_file("schema-sweep.yaml", sweep));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 2) << run.out;
}

// Every JSON output carries kinestat's version (as --version prints it) and report_version 1,
// after its other keys: the verdict stays first.
TEST(ReportVersions, EveryJsonOutputCarriesThem) {
  const auto version_run = run_cli("--version");
  ASSERT_EQ(version_run.exit_code, 0);
  const std::string version = version_run.out.substr(std::string("kinestat ").size(), version_run.out.find('\n') - 9);
  ASSERT_FALSE(version.empty());
  const std::vector<std::string> commands{
      "analyze --json " + example_path("davies-2-circuit.yaml"),
      "analyze --json --sparse " + example_path("davies-2-circuit.yaml"),
      "analyze --json " + example_path("truss-12.yaml"),
      "structure --json " + example_path("saura-eq2.yaml"),
      "move --json --mode 1 " + example_path("four-bar-planar.yaml"),
  };
  for (const std::string& command : commands) {
    SCOPED_TRACE(command);
    const auto run = run_cli(command);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto report = nlohmann::ordered_json::parse(run.out);
    EXPECT_EQ(report["kinestat_version"], version);
    EXPECT_EQ(report["report_version"], 1);
    const auto last = std::prev(report.end());
    EXPECT_EQ(last.key(), "report_version");
    if (command.rfind("move", 0) != 0) {
      EXPECT_EQ(report.begin().key(), "verdict");
    }
  }
  const auto sweep = run_cli("sweep " + example_path("sweeps/collinear-bars.yaml"));
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  std::istringstream lines(sweep.out);
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    const auto parsed = nlohmann::json::parse(line);
    EXPECT_EQ(parsed["kinestat_version"], version);
    EXPECT_EQ(parsed["report_version"], 1);
  }
  EXPECT_EQ(count, 21);
}

}  // namespace
}  // namespace kinestat
