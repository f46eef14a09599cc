// SPDX-License-Identifier: BSD-3-Clause
// Issue 39, item 5: `-` for standard input in every command that reads a model, `--fail-unless
// exactly-constrained` (exit 1 on any other verdict), an unknown command that names the
// nearest, and help texts that name every format read.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "support/cli_run.hpp"
#include "support/scratch_folder.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;
using testing::write_temp_file;

std::string conventions_file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every command that reads a model reads it from standard input as `-`, with the same output as
// from the file (messages name it "<stdin>").
TEST(StandardInput, EveryCommandReadsAModelAsDash) {
  const std::string framework = conventions_file_text(example_path("truss-12.yaml"));
  const std::string network = conventions_file_text(example_path("four-bar-planar.yaml"));
  const std::vector<std::pair<std::string, std::string>> commands{
      {"analyze --json", framework}, {"analyze", network},        {"draw", framework},
      {"move --json --mode 1", network},      {"export --what modes", framework},
      {"move --json --mode 1", framework},    {"move --json --input A=1", network},
      {"structure --json", network},          {"analyze --json --brief", network},
      {"structure --json", conventions_file_text(example_path("saura-eq2.yaml"))},
  };
  for (const auto& [command, text] : commands) {
    SCOPED_TRACE(command);
    const std::string path = write_temp_file("stdin-model.yaml", text);
    const auto from_file = run_cli(command + " " + path);
    ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
    const auto from_stdin = run_cli(command + " -", text);
    EXPECT_EQ(from_stdin.exit_code, 0) << from_stdin.err;
    EXPECT_EQ(from_stdin.out, from_file.out);
  }
  const std::string out = (testing::scratch_folder() / "converted.yaml").string();
  const auto convert = run_cli("convert - " + out, framework);
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_EQ(run_cli("analyze --json " + out).out, run_cli("analyze --json " + example_path("truss-12.yaml")).out);
  const std::string spec = "kinestat: 1\nkind: sweep\nmodel: " + example_path("sweeps/two-bars.yaml") +
                           "\nparameters:\n  - {name: b, node: B, coordinate: y, values: [0, 0.5]}\n";
  const auto sweep = run_cli("sweep -", spec);
  EXPECT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_EQ(std::count(sweep.out.begin(), sweep.out.end(), '\n'), 2);
  const auto bad = run_cli("analyze -", "kinestat: 1\nkind: framework\nnodes: 3\n");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err.rfind("<stdin>:", 0), 0u) << bad.err;
}

// --fail-unless exactly-constrained: 0 for an exactly constrained design, 1 for any other
// verdict (the report is still written), 2 for bad input; FN/CN of the examples by hand:
// planar four-bar 1/0 with one intended motion (Grübler 3*3 - 2*4 = 1), spatial four-bar
// 1/3, the 12-truss has a mechanism and a self-stress.
TEST(FailUnless, ExitStatusTellsTheVerdict) {
  const auto exact = run_cli("analyze --fail-unless exactly-constrained " + example_path("slider-crank-planar.yaml"));
  EXPECT_EQ(exact.exit_code, 0) << exact.out << exact.err;
  EXPECT_EQ(exact.out.rfind("Verdict: Exactly constrained", 0), 0u) << exact.out;
  for (const char* example : {"four-bar-spatial.yaml", "truss-12.yaml"}) {
    const auto run = run_cli("analyze --json --fail-unless exactly-constrained " + example_path(example));
    EXPECT_EQ(run.exit_code, 1) << example << run.err;
    EXPECT_FALSE(nlohmann::json::parse(run.out)["verdict"]["exactly_constrained"].get<bool>()) << example;
  }
  EXPECT_EQ(run_cli("analyze " + example_path("truss-12.yaml")).exit_code, 0);  // without the option: 0
  EXPECT_EQ(run_cli("structure --fail-unless exactly-constrained " + example_path("saura-eq2.yaml")).exit_code, 0);
  const std::string over = "kinestat: 1\nkind: structure\nbodies: [f, a]\npairs:\n  - {between: [f, a], pair: lower, inputs: 1}\n"
                           "  - {between: [a, f], pair: lower}\n";
  const auto over_run = run_cli("structure --brief --fail-unless exactly-constrained -", over);
  EXPECT_EQ(over_run.exit_code, 1) << over_run.out << over_run.err;
  EXPECT_EQ(over_run.out.rfind("Verdict: Not exactly constrained", 0), 0u) << over_run.out;
  const auto wrong = run_cli("analyze --fail-unless rigid " + example_path("truss-12.yaml"));
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("exactly-constrained"), std::string::npos) << wrong.err;
  EXPECT_EQ(run_cli("analyze --fail-unless exactly-constrained " + example_path("no-such-file.yaml")).exit_code, 2);
}

TEST(UnknownCommand, NamesTheNearestCommand) {
  for (const auto& [typed, meant] : std::vector<std::pair<std::string, std::string>>{
           {"analyse", "analyze"}, {"strucure", "structure"}, {"raport", "report"}, {"exprot", "export"}}) {
    const auto run = run_cli(typed + " " + example_path("truss-12.yaml"));
    EXPECT_EQ(run.exit_code, 2) << typed;
    EXPECT_TRUE(run.out.empty());
    EXPECT_EQ(run.err, "kinestat: error: unknown command '" + typed + "'; did you mean '" + meant + "'?\n");
  }
  const auto far = run_cli("frobnicate");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_NE(far.err.find("unknown command 'frobnicate'; the commands are analyze, structure"), std::string::npos) << far.err;
  EXPECT_EQ(run_cli("analyze " + example_path("truss-12.yaml")).exit_code, 0);
}

TEST(HelpTexts, NameEveryFormatRead) {
  for (const char* command : {"analyze", "draw", "report", "move", "export", "structure", "convert"}) {
    const auto help = run_cli(std::string(command) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command;
    for (const char* format : {"YAML", "JSON", "URDF", "SDFormat", "MJCF"})
      EXPECT_NE(help.out.find(format), std::string::npos) << command << " --help does not name " << format;
    EXPECT_NE(help.out.find("'-'"), std::string::npos) << command << " --help does not name standard input";
  }
}

}  // namespace
}  // namespace kinestat
