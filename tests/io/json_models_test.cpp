// SPDX-License-Identifier: BSD-3-Clause
// Model files may be JSON (exported from other tools): YAML 1.2 reads JSON, so the same
// readers apply. Each JSON file under examples/json/ is a shipped YAML example written as
// JSON; the reports must be byte-identical, and JSON syntax errors must name line and column.
#include <gtest/gtest.h>

#include <string>

#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::run_cli;

struct JsonModel {
  const char* name;     // examples/json/<name>.json and examples/<name>.yaml
  const char* command;  // analyze or structure
};

class JsonModels : public ::testing::TestWithParam<JsonModel> {};

TEST_P(JsonModels, ReportIsTheSameAsForTheYamlFile) {
  const JsonModel m = GetParam();
  const auto from_yaml = run_cli(std::string(m.command) + " --json " + testing::example_path(std::string(m.name) + ".yaml"));
  const auto from_json = run_cli(std::string(m.command) + " --json " + testing::example_path(std::string("json/") + m.name + ".json"));
  ASSERT_EQ(from_yaml.exit_code, 0) << from_yaml.err;
  ASSERT_EQ(from_json.exit_code, 0) << from_json.err;
  EXPECT_EQ(from_json.out, from_yaml.out);
  EXPECT_GT(from_json.out.size(), 100u);
}

INSTANTIATE_TEST_SUITE_P(EveryKind, JsonModels,
                         ::testing::Values(JsonModel{"davies-2-circuit", "analyze"}, JsonModel{"truss-12", "analyze"},
                                           JsonModel{"wire-flexure-guide", "analyze"}, JsonModel{"saura-eq2", "structure"},
                                           JsonModel{"class-iii-triad", "structure"}),
                         [](const auto& instance) {
                           std::string name = instance.param.name;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(JsonModels, SyntaxErrorNamesLineAndColumn) {
  // A missing comma between two couplings on line 4.
  const std::string path = testing::write_temp_file(
      "broken.json",
      "{\n  \"kinestat\": 1,\n  \"couplings\": [\n    {\"name\": \"A\", \"type\": \"revolute\", \"between\": [1, 2]}\n"
      "    {\"name\": \"B\", \"type\": \"revolute\", \"between\": [1, 2]}\n  ]\n}\n");
  const auto run = run_cli("analyze " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find(path + ":5:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("error"), std::string::npos) << run.err;
}

TEST(JsonModels, WrongTypeNamesTheValue) {
  const std::string path = testing::write_temp_file(
      "wrong.json", "{\"kinestat\": 1, \"kind\": \"structure\", \"bodies\": [\"f\", \"a\"],\n \"adjacency\": [[0, \"x\"], [3, 0]]}\n");
  const auto run = run_cli("structure " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path + ":2:"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace kinestat
