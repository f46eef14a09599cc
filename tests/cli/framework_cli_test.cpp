// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze` on framework files: examples succeed with the expected JSON, output is
// byte-identical between runs, and bad input exits with code 2 and one line
// `file:line:col: error: ...` on stderr.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "support/scratch_folder.hpp"

namespace {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::filesystem::path temp_dir() {
  return kinestat::testing::scratch_subfolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
}

// Runs a whole shell command line (for commands that set the environment).
CliRun run_shell(const std::string& command_line) {
  const auto dir = temp_dir();
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const int status = std::system((command_line + " >" + out.string() + " 2>" + err.string()).c_str());
  CliRun result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

CliRun run(const std::string& arguments) { return run_shell(std::string(KINESTAT_CLI) + " " + arguments); }

std::string example(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name; }

TEST(FrameworkCli, Truss12JsonHasTheRequiredKeysAndValues) {
  const CliRun r = run("analyze --json " + example("truss-12.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"rows", "cols", "rank", "classification", "mechanisms", "self_stresses", "singular_values", "modes",
                          "stresses", "releases"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["rows"], 12);
  EXPECT_EQ(j["cols"], 12);
  EXPECT_EQ(j["rank"], 11);
  EXPECT_EQ(j["mechanisms"], 1);
  EXPECT_EQ(j["self_stresses"], 1);
  EXPECT_EQ(j["classification"], "statically indeterminate, kinematically indeterminate");
  EXPECT_EQ(j["singular_values"].size(), 12u);
  EXPECT_NEAR(std::abs(j["modes"][0]["velocities"]["E"]["y"].get<double>()), 0.5, 1e-9);
  EXPECT_EQ(j["stresses"][0]["resultants"].size(), 12u);
  EXPECT_NEAR(std::abs(j["stresses"][0]["resultants"][0]["value"].get<double>()), std::sqrt(3.0) / 6, 1e-9);
  EXPECT_EQ(j["releases"].size(), 1u);
}

// glibc's dynamic loader prints its statistics once for each program it starts: the count of
// them tells whether the command started itself again on huge pages (src/cli/huge_pages.cpp).
int program_starts(const std::string& standard_error) {
  int starts = 0;
  for (std::size_t at = standard_error.find("total startup time"); at != std::string::npos;
       at = standard_error.find("total startup time", at + 1))
    ++starts;
  return starts;
}

TEST(FrameworkCli, LargeInputRestartsOnHugePagesAndPrefaultsWithTheSameAnswer) {
  // truss-12 with over 1 MiB of comments: the threshold of the restart and of the heap's prefault
  // (src/cli/heap_prefault.cpp), and the seed's answer.
  const auto path = temp_dir() / "truss-12-padded.yaml";
  {
    std::ofstream out(path);
    out << slurp(example("truss-12.yaml")) << '\n';
    for (int line = 0; line < 1100; ++line) out << "# " << std::string(1000, 'x') << '\n';
  }
  ASSERT_GE(std::filesystem::file_size(path), std::uintmax_t{1} << 20);
  const std::string analyse = " " + std::string(KINESTAT_CLI) + " analyze --json " + path.string();
  const CliRun restarted = run_shell("env -u GLIBC_TUNABLES -u KINESTAT_PREFAULT LD_DEBUG=statistics" + analyse);
  const CliRun kept = run_shell("env GLIBC_TUNABLES=glibc.malloc.hugetlb=0 LD_DEBUG=statistics" + analyse);
  const CliRun other = run_shell("env GLIBC_TUNABLES=glibc.malloc.tcache_count=0 LD_DEBUG=statistics" + analyse);
  const CliRun small = run_shell("env -u GLIBC_TUNABLES LD_DEBUG=statistics " + std::string(KINESTAT_CLI) +
                                 " analyze --json " + example("truss-12.yaml"));
  const CliRun not_prefaulted = run_shell("env -u GLIBC_TUNABLES KINESTAT_PREFAULT=0" + analyse);
  for (const CliRun* r : {&restarted, &kept, &other, &small, &not_prefaulted}) ASSERT_EQ(r->exit_code, 0) << r->err;
  EXPECT_EQ(program_starts(restarted.err), 2);
  EXPECT_EQ(program_starts(kept.err), 1);  // the user's own hugetlb setting is left alone
  EXPECT_EQ(program_starts(other.err), 2);  // other tunables are kept and the setting added
  EXPECT_EQ(program_starts(small.err), 1);
  EXPECT_EQ(restarted.out, kept.out);
  EXPECT_EQ(other.out, kept.out);
  EXPECT_EQ(not_prefaulted.out, restarted.out);
  const auto j = nlohmann::json::parse(restarted.out);
  EXPECT_EQ(j["rank"], 11);
  EXPECT_EQ(j["mechanisms"], 1);
  EXPECT_EQ(j["self_stresses"], 1);
}

TEST(FrameworkCli, JsonIsByteIdenticalBetweenRuns) {
  for (const char* name : {"truss-12.yaml", "folded-sheet-guide-5-symmetric.yaml", "cube-frame.yaml"}) {
    const CliRun a = run("analyze --json " + example(name));
    const CliRun b = run("analyze --json " + example(name));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(a.out, b.out) << name;
  }
}

TEST(FrameworkCli, EveryExampleAnalysesAsText) {
  for (const char* name : {"truss-12.yaml", "wire-flexure-guide.yaml", "folded-sheet-flexure.yaml", "folded-sheet-double-clamped.yaml",
                           "folded-sheet-guide-5.yaml", "folded-sheet-guide-5-symmetric.yaml", "folded-sheet-guide-6.yaml",
                           "pellegrino-calladine-two-bar.yaml", "braced-square.yaml", "four-bar-linkage.yaml", "octahedron.yaml",
                           "cube-frame.yaml", "simplex-tensegrity.yaml"}) {
    const CliRun r = run("analyze " + example(name));
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_NE(r.out.find("classification: "), std::string::npos) << name;
    EXPECT_TRUE(r.err.empty()) << name;
  }
}

TEST(FrameworkCli, OutputFileAndSparsePath) {
  const auto path = temp_dir() / "report.json";
  const CliRun r = run("analyze --json --dense-limit 5 -o " + path.string() + " " + example("folded-sheet-guide-6.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(path));
  EXPECT_EQ(j["method"], "sparse_qr");  // 42 x 41 is above the limit of 5: counts from sparse QR
  EXPECT_EQ(j["rank"], 41);
  EXPECT_EQ(j["self_stresses"], 1);
  EXPECT_EQ(j["mechanisms"], 0);
}

TEST(FrameworkCli, SparsePathWithVectors) {
  // folded-sheet-guide-6 (seed 002, Fig. 6): one state of self-stress, in the sheets' in-plane
  // bending (the published result); --vectors 3 asks for at most three of each.
  const auto path = temp_dir() / "report.json";
  const CliRun r =
      run("analyze --json --dense-limit 5 --vectors 3 -o " + path.string() + " " + example("folded-sheet-guide-6.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(path));
  EXPECT_EQ(j["method"], "sparse_qr");
  EXPECT_EQ(j["vectors"], true);
  EXPECT_EQ(j["vector_limit"], 3);
  EXPECT_EQ(j["modes"].size(), 0u);
  ASSERT_EQ(j["stresses"].size(), 1u);
  EXPECT_EQ(j["releases"].size(), 1u);  // one self-stress: one release
  EXPECT_EQ(j["constrain"].size(), 0u);
  EXPECT_LT(j["null_space_residual"].get<double>(), 1e-12);
  // Compact: only non-zero resultants are written.
  for (const auto& entry : j["stresses"][0]["resultants"]) EXPECT_NE(entry["value"].get<double>(), 0.0);
}

struct BadFile {
  const char* name;
  const char* text;
  const char* problem;
};

class FrameworkCliRejects : public ::testing::TestWithParam<BadFile> {};

TEST_P(FrameworkCliRejects, WithExitCode2AndOneLine) {
  const auto path = temp_dir() / (std::string(GetParam().name) + ".yaml");
  std::ofstream(path) << "kinestat: 1\nkind: framework\n" << GetParam().text;
  const CliRun r = run("analyze " + path.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  const std::regex one_line("^" + std::regex_replace(path.string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                            R"(:\d+:\d+: error: [^\n]+\n$)");
  EXPECT_TRUE(std::regex_match(r.err, one_line)) << r.err;
  EXPECT_NE(r.err.find(GetParam().problem), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FrameworkCliRejects,
    ::testing::Values(
        BadFile{"zero_length", "nodes: {A: [0, 0, 0], B: [0, 0, 0]}\nelements: [{type: truss, nodes: [A, B]}]\n", "zero-length"},
        BadFile{"unknown_node", "nodes: {A: [0, 0, 0]}\nelements: [{type: truss, nodes: [A, Q]}]\n", "unknown node 'Q'"},
        BadFile{"fixed_and_independent",
                "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nsupports: {B: fixed}\nindependent: {B: [y]}\n"
                "elements: [{type: truss, nodes: [A, B]}]\n",
                "both fixed"},
        BadFile{"bad_release", "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nelements: [{type: beam, nodes: [A, B], released: [shear]}]\n",
                "has no deformation 'shear'"},
        BadFile{"not_orthonormal",
                "nodes: {A: {position: [0, 0, 0], orientation: [[1, 0, 0], [0, 2, 0], [0, 0, 1]]}, B: [1, 0, 0]}\n"
                "elements: [{type: beam, nodes: [A, B]}]\n",
                "not orthonormal"},
        BadFile{"malformed", "nodes: {A: [0, 0, 0\n", "malformed YAML"}),
    [](const ::testing::TestParamInfo<BadFile>& param) { return std::string(param.param.name); });

}  // namespace
