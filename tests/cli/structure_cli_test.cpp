// SPDX-License-Identifier: BSD-3-Clause
// The `kinestat structure` command: examples, standard input, diagrams, and bad input
// (exit code 2 with one line on standard error).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/scratch_folder.hpp"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code = -1;
  std::string out;
  std::string err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path temp_dir() {
  return kinestat::testing::scratch_subfolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
}

// Runs the CLI with `args`, optionally feeding `input` on standard input.
CliRun run(const std::string& args, const std::string& input = "") {
  const fs::path dir = temp_dir();
  const fs::path in = dir / "stdin.txt", out = dir / "stdout.txt", err = dir / "stderr.txt";
  std::ofstream(in) << input;
  const std::string command = std::string("'") + KINESTAT_CLI + "' " + args + " < '" + in.string() + "' > '" + out.string() +
                              "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  CliRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::string example(const std::string& name) { return std::string("'") + KINESTAT_SOURCE_DIR + "/examples/" + name + "'"; }

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST(StructureCli, Eq2Json) {
  const CliRun r = run("structure --json " + example("saura-eq2.yaml"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["order"], nlohmann::json({{2, 3}, {4}, {5}}));
  EXPECT_EQ(j["result_matrix"], nlohmann::json({{0, 1, 1, 2, 3}, {1, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, {1, 0, 2, 0, 0}, {0, 0, 0, 2, 0}}));
}

TEST(StructureCli, EveryExampleRuns) {
  for (const auto& entry : fs::directory_iterator(fs::path(KINESTAT_SOURCE_DIR) / "examples")) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".yaml" || slurp(entry.path()).find("kind: structure") == std::string::npos) continue;
    const CliRun r = run("structure " + example(name));
    EXPECT_EQ(r.code, 0) << name << ": " << r.err;
    EXPECT_NE(r.out.find("Structural groups in order of formation"), std::string::npos) << name;
  }
}

TEST(StructureCli, MatrixOnStandardInput) {
  const std::string four_bar = "0 3 0 1\n3 0 1 0\n0 1 0 1\n1 0 1 0\n";
  for (const std::string how : {"structure --json -", "structure --json --stdin"}) {
    const CliRun r = run(how, four_bar);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["order"], nlohmann::json({{2}, {3, 4}})) << how;
  }
}

TEST(StructureCli, DiagramsAndOutputFile) {
  const fs::path out = temp_dir() / "diagram.svg";
  CliRun r = run("structure --diagram svg -o '" + out.string() + "' " + example("saura-eq2.yaml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(out).rfind("<svg", 0), 0u);
  r = run("structure --diagram dot " + example("saura-eq2.yaml"));
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("g1 -> g2;"), std::string::npos);
  EXPECT_NE(r.out.find("g2 -> g3;"), std::string::npos);
}

TEST(StructureCli, SeedMethodGivesTheSameReport) {
  const CliRun a = run("structure --json " + example("saura-eq3.yaml"));
  const CliRun b = run("structure --json --method seed " + example("saura-eq3.yaml"));
  ASSERT_EQ(a.code, 0);
  ASSERT_EQ(b.code, 0);
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja["groups"], jb["groups"]);
  EXPECT_EQ(ja["result_matrix"], jb["result_matrix"]);
}

void expect_bad(const std::string& input, const std::string& expected) {
  const CliRun r = run("structure -", input);
  EXPECT_EQ(r.code, 2) << input;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
}

TEST(StructureCli, BadInputOnStdin) {
  expect_bad("0 1 0\n1 0 1\n0 0 0\n", "<stdin>:3:3: error: adjacency is not symmetric: row 2, column 3 is 1 but row 3, column 2 is 0");
  expect_bad("0 6\n6 0\n", "<stdin>:1:3: error: adjacency code at row 1, column 2 is 6; expected 0 to 5");
  expect_bad("0 0 0\n0 0 1\n0 1 0\n", "<stdin>:1:1: error: the frame (row 1) forms no pair");
  expect_bad("0 1 0\n1 0 0\n0 0 0\n", "<stdin>:3:1: error: body 3 is isolated: row 3 forms no pair");
}

TEST(StructureCli, BadFileNamesLineAndColumn) {
  const fs::path file = temp_dir() / "bad.yaml";
  std::ofstream(file) << "kinestat: 1\nkind: structure\nadjacency:\n  - [0, 1, 1]\n  - [1, 0, 1]\n  - [1, 0, 0]\n";
  const CliRun r = run("structure '" + file.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.yaml:6:9: error: adjacency is not symmetric: row 2, column 3 is 1 but row 3, column 2 is 0"),
            std::string::npos)
      << r.err;
  const CliRun missing = run("structure '" + (temp_dir() / "nope.yaml").string() + "'");
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(lines(missing.err), 1);
}

}  // namespace

namespace {

TEST(StructureCli, YamlModelOnStandardInputAndCommentedMatrix) {
  const CliRun yaml = run("structure --json -", "kinestat: 1\nkind: structure\nadjacency: [[0, 3], [3, 0]]\n");
  ASSERT_EQ(yaml.code, 0) << yaml.err;
  EXPECT_EQ(nlohmann::json::parse(yaml.out)["order"], nlohmann::json({{2}}));
  const CliRun matrix = run("structure --json -", "# crank: driven lower pair\n0 3\n3 0\n");
  ASSERT_EQ(matrix.code, 0) << matrix.err;
  EXPECT_EQ(nlohmann::json::parse(matrix.out)["order"], nlohmann::json({{2}}));
}

}  // namespace

namespace {

TEST(StructureCli, OutputIsByteIdenticalAcrossRuns) {
  for (const std::string args : {"structure --json ", "structure --diagram svg ", "structure "}) {
    const CliRun a = run(args + example("class-iii-triad.yaml"));
    const CliRun b = run(args + example("class-iii-triad.yaml"));
    ASSERT_EQ(a.code, 0) << a.err;
    EXPECT_EQ(a.out, b.out) << args;
    EXPECT_FALSE(a.out.empty());
  }
}

}  // namespace
