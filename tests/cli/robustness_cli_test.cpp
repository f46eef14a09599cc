// SPDX-License-Identifier: BSD-3-Clause
// Issue 16 at the command line: tolerances and values that are not usable numbers, results
// that overflow, geometry that must be given, and the messages that used to mislead.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/report/markup_escape.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;
using testing::write_temp_file;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RobustCli, TolerancesMustBePositiveAndFinite) {
  for (const char* bad : {"nan", "inf", "-inf", "-1", "0", "1e999", "abc"}) {
    for (const char* command : {"analyze", "draw", "report"}) {
      const auto run = run_cli(std::string(command) + " " + example_path("braced-square.yaml") + " --tolerance " + bad);
      EXPECT_EQ(run.exit_code, 2) << command << " " << bad << ": " << run.err;
      EXPECT_EQ(run.out, "") << command << " " << bad;
      EXPECT_TRUE(has(run.err, "expected a positive number")) << command << " " << bad << ": " << run.err;
      EXPECT_FALSE(has(run.err, "17976931348623157")) << run.err;  // DBL_MAX written out
      EXPECT_LT(run.err.size(), 300u) << run.err;
    }
  }
}

TEST(RobustCli, CountsMustBeWholeNumbers) {
  const auto run = run_cli("analyze " + example_path("braced-square.yaml") + " --dense-limit -1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, "'-1' is not a whole number")) << run.err;
  EXPECT_FALSE(has(run.err, "17976931348623157")) << run.err;
}

TEST(RobustCli, ValueOutOfRangeIsRefused) {
  const auto run = run_cli("analyze " + example_path("davies-2-circuit.yaml") + " --value sa=1e999");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_TRUE(has(run.err, "--value: error: 'sa=1e999' is out of range")) << run.err;
}

// One revolute 1e200 from the origin turning at 1e200 rad/s: the velocity of the body point at
// the origin, |p x w| = 1e400, overflows a double.
TEST(RobustCli, ResultsThatOverflowAreAnError) {
  const std::string path = write_temp_file(
      "overflow.yaml",
      "kinestat: 1\ncouplings:\n  - {name: A, type: revolute, between: [1, 2], point: [1e200, 0, 0], axis: [0, 0, 1]}\n"
      "values: {ta: 1e200}\n");
  const auto run = run_cli("analyze " + path);
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_EQ(run.out, "");
  EXPECT_TRUE(has(run.err, "overflows a double")) << run.err;
  EXPECT_FALSE(has(run.out + run.err, "inf")) << run.err;
}

TEST(RobustCli, PointDependentCouplingsNeedAPoint) {
  for (const char* coupling : {"{name: R1, type: revolute, between: [1, 2], axis: [0, 0, 1]}",
                               "{name: R1, type: spherical, between: [1, 2]}",
                               "{name: R1, type: cylindrical, between: [1, 2], axis: [0, 0, 1]}",
                               "{name: R1, type: helical, between: [1, 2], axis: [0, 0, 1], pitch: 1}",
                               "{name: R1, type: universal, between: [1, 2], axis: [0, 0, 1], axis2: [1, 0, 0]}",
                               "{name: R1, type: planar, between: [1, 2], normal: [0, 0, 1]}",
                               "{name: R1, type: point_on_plane, between: [1, 2], normal: [0, 0, 1]}"}) {
    const std::string path = write_temp_file("no-point.yaml", std::string("kinestat: 1\ncouplings:\n  - ") + coupling + "\n");
    const auto run = run_cli("analyze " + path);
    EXPECT_EQ(run.exit_code, 2) << coupling;
    EXPECT_TRUE(has(run.err, path + ":3:5: error:")) << run.err;
    EXPECT_TRUE(has(run.err, "coupling 'R1' needs a 'point'")) << run.err;
  }
  // A prismatic's motion does not depend on a point: none is needed.
  const std::string path = write_temp_file(
      "prismatic.yaml", "kinestat: 1\ncouplings:\n  - {name: P, type: prismatic, between: [1, 2], axis: [1, 0, 0]}\n");
  EXPECT_EQ(run_cli("analyze " + path).exit_code, 0);
}

TEST(RobustCli, FolderAsModel) {
  const auto run = run_cli("analyze " + std::string(KINESTAT_SOURCE_DIR) + "/examples");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, "this is a folder, not a model file")) << run.err;
}

TEST(RobustCli, SecondDocumentAndEscapedControlCharacters) {
  const std::string two = write_temp_file("two.yaml", "kinestat: 1\nkind: framework\nnodes: {A: [0, 0, 0]}\nelements: []\n---\nx: 1\n");
  auto run = run_cli("analyze " + two);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, two + ":5:1: error: a second YAML document")) << run.err;
  const std::string escaped = write_temp_file(
      "escaped.yaml",
      "kinestat: 1\nname: \"\\e[31mred\"\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\n");
  for (const char* command : {"analyze", "draw"}) {
    run = run_cli(std::string(command) + " " + escaped);
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_EQ(run.out, "") << command;
    EXPECT_TRUE(has(run.err, escaped + ":2:7: error: this string contains the control character U+001B")) << run.err;
  }
}

TEST(RobustCli, SeventyThousandCharacterNameIsShortened) {
  const std::string name(70000, 'q');
  const std::string path = write_temp_file(
      "long-name.yaml",
      "kinestat: 1\ncouplings:\n  - {name: " + name + ", type: spherical, between: [1, 1], point: [0, 0, 0]}\n");
  const auto run = run_cli("analyze " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_LT(run.err.size(), 600u);
  EXPECT_TRUE(has(run.err, "coupling '" + std::string(59, 'q') + "\u2026 (70002 bytes) joins body '1' to itself"))
      << run.err;
}

TEST(RobustCli, MechanismNotConnectedToTheFrame) {
  const std::string path = write_temp_file(
      "floating.yaml",
      "kinestat: 1\nkind: structure\nbodies: [frame, crank, a, b]\npairs:\n"
      "  - {between: [frame, crank], pair: lower, inputs: 1}\n  - {between: [a, b], pair: lower}\n");
  const auto run = run_cli("structure " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, "bodies 'a', 'b' are not connected to the frame")) << run.err;
  EXPECT_FALSE(has(run.err + run.out, "drive more pairs"));
  const auto matrix = run_cli("structure -", "0 1 0 0\n1 0 0 0\n0 0 0 1\n0 0 1 0\n");
  EXPECT_EQ(matrix.exit_code, 2);
  EXPECT_TRUE(has(matrix.err, "<stdin>:3:1: error: bodies 3, 4 are not connected to the frame"))
      << matrix.err;
}

// Chords B and D leave A and C, which with the two bodies they join twice form a circuit.
TEST(RobustCli, ChordsThatAreNotACotreeNameTheCoupling) {
  const std::string path = write_temp_file(
      "chords.yaml",
      "kinestat: 1\ndimension: planar\ncouplings:\n"
      "  - {name: A, type: revolute, between: [1, 2], point: [0, 0]}\n"
      "  - {name: B, type: revolute, between: [2, 3], point: [1, 0]}\n"
      "  - {name: C, type: revolute, between: [1, 2], point: [0, 1]}\n"
      "  - {name: D, type: revolute, between: [3, 1], point: [1, 1]}\n"
      "chords: [B, D]\n");
  const auto run = run_cli("analyze " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, "contain a circuit, closed by coupling 'C'")) << run.err;
  EXPECT_FALSE(has(run.err, "coupling index")) << run.err;
}

TEST(RobustCli, MarkupEscapeNeverPassesControlCharacters) {
  EXPECT_EQ(report::markup_escape("a<b>&\"c\x1B[31m\x7F"), "a&lt;b&gt;&amp;&quot;c\xEF\xBF\xBD[31m\xEF\xBF\xBD");
  EXPECT_EQ(report::markup_escape("tab\tline\n"), "tab\tline\n");
}

// Control characters that arrive through the command line (an option, a --value name, a file
// name) are echoed in the error message as escapes (io::printable_text), never raw.
TEST(RobustCli, ErrorsShowControlCharactersFromTheCommandLineEscaped) {
  auto raw_control = [](const std::string& text) {
    for (char c : text)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\n') || c == 0x7F) return true;
    return false;
  };
  // sh's printf turns \033 into ESC.
  const auto option = run_cli("analyze " + example_path("davies-2-circuit.yaml") + " \"--x$(printf '\\033')[2J\"");
  EXPECT_EQ(option.exit_code, 2);
  EXPECT_TRUE(has(option.err, "--x\\x1B[2J")) << option.err;
  EXPECT_FALSE(raw_control(option.err)) << option.err;
  const auto value = run_cli("analyze " + example_path("davies-2-circuit.yaml") + " --value \"a$(printf '\\033')[31m=1\"");
  EXPECT_EQ(value.exit_code, 2);
  EXPECT_TRUE(has(value.err, "a\\x1B[31m")) << value.err;
  EXPECT_FALSE(raw_control(value.err)) << value.err;
  const auto file = run_cli("analyze \"no$(printf '\\033')such.yaml\"");
  EXPECT_EQ(file.exit_code, 2);
  EXPECT_TRUE(has(file.err, "no\\x1Bsuch.yaml")) << file.err;
  EXPECT_FALSE(raw_control(file.err)) << file.err;
}

// --max-input-size (issue 41, item 4) on every command that reads a model and in every reader:
// each file below is larger than 500 bytes, so a 500-byte limit refuses it with one line naming
// the file and the limit (exit 2), and the default limit (64 MiB) reads it.
TEST(RobustCli, MaxInputSizeReachesEveryCommandAndReader) {
  const std::string out = (testing::scratch_folder() / "max_input_size_converted.yaml").string();
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"structure", "four-bar-planar.yaml"},       {"structure", "robots/four-bar.urdf"},
      {"analyze", "robots/four-bar.sdf"},          {"analyze", "robots/four-bar.xml"},
      {"analyze", "spacar/folded-sheet-guide-5.dat"}, {"convert", "parallel-leaf-spring-guide.yaml"},
      {"convert", "robots/four-bar.urdf"},
  };
  for (const auto& [command, name] : runs) {
    const std::string path = example_path(name);
    ASSERT_GT(std::filesystem::file_size(path), 500U) << path;
    const std::string output = command == "convert" ? " " + out : "";
    const auto refused = run_cli(command + " " + path + output + " --max-input-size 500B");
    EXPECT_EQ(refused.exit_code, 2) << command << " " << name << ": " << refused.err;
    EXPECT_TRUE(has(refused.err, name + ": error: the input is larger than the 500 bytes limit")) << refused.err;
    EXPECT_EQ(refused.err.find('\n'), refused.err.size() - 1) << refused.err;
    const auto read = run_cli(command + " " + path + output);
    EXPECT_FALSE(has(read.err, "limit on model files")) << command << " " << name << ": " << read.err;
  }
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace kinestat
