// SPDX-License-Identifier: BSD-3-Clause
// `kinestat sweep` (issue 17, docs/sweep.md). Expected values: the parameter values from the
// spec's arithmetic (k-th of `steps` equal steps), the counts from seed 002 (the folded-sheet
// guide: D(c) 42 × 41 of rank 41) and from hand derivations (two bars, or three revolutes,
// become a mechanism with a self-stress exactly when their pivots are collinear); the sharded
// run is compared byte for byte with the single run.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace {

using kinestat::testing::example_path;
using kinestat::testing::run_cli;

namespace fs = std::filesystem;

// A fresh folder for one test's files.
fs::path test_folder(const std::string& name) {
  const fs::path dir = kinestat::testing::scratch_folder() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<nlohmann::json> lines_of(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// Two bars A–B–C, A and C held, B at (1, 0.5): rigid unless B lies on AC (y = 0).
const char* kTwoBars = R"(kinestat: 1
kind: framework
name: two bars
dimension: planar
nodes: {A: [0, 0], B: [1, 0.5], C: [2, 0]}
supports: {A: fixed, C: fixed}
elements:
  - {name: ab, type: truss, nodes: [A, B]}
  - {name: bc, type: truss, nodes: [B, C]}
)";

// The same as a planar coupling network: three revolutes in one circuit.
const char* kThreeRevolutes = R"(kinestat: 1
kind: network
name: three revolutes
dimension: planar
couplings:
  - {name: A, type: revolute, between: [ground, b1], point: [0, 0]}
  - {name: B, type: revolute, between: [b1, b2], point: [1, 0.5]}
  - {name: C, type: revolute, between: [b2, ground], point: [2, 0]}
)";

TEST(SweepCli, FoldedSheetGuideThousandVariantsInFourShardsMergeToTheSingleRun) {
  const fs::path dir = test_folder("folded");
  const std::string spec = example_path("sweeps/folded-sheet-guide-6.yaml");  // A1's z from 28 to 37.99, steps: 999
  const std::string cli = KINESTAT_CLI;
  // One run, and four shards run side by side (as GNU parallel or a job array would), then merged.
  std::string command = cli + " sweep " + spec + " -o " + (dir / "one.jsonl").string() + " 2>" + (dir / "one.err").string();
  for (int i = 0; i < 4; ++i)
    command += " && { " + cli + " sweep " + spec + " --shard " + std::to_string(i) + "/4 -o " + (dir / ("part-" + std::to_string(i) + ".jsonl")).string() +
               " 2>>" + (dir / "parts.err").string() + " & }";
  command += " && wait";
  ASSERT_EQ(std::system(("sh -c '" + command + "'").c_str()), 0);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(fs::exists(dir / ("part-" + std::to_string(i) + ".jsonl"))) << i;
  EXPECT_EQ(read(dir / "one.err"), "");  // no progress bar when standard error is a file
  EXPECT_EQ(read(dir / "parts.err"), "");
  const auto merged = run_cli("sweep --merge " + (dir / "part-3.jsonl").string() + " " + (dir / "part-1.jsonl").string() + " " +
                              (dir / "part-0.jsonl").string() + " " + (dir / "part-2.jsonl").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const std::string one = read(dir / "one.jsonl");
  EXPECT_EQ(merged.out, one);  // byte for byte

  const auto lines = lines_of(one);
  ASSERT_EQ(lines.size(), 1000u);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto& line = lines[k];
    ASSERT_EQ(line["variant"], k);
    EXPECT_EQ(line["of"], 1000);
    EXPECT_NEAR(line["parameters"]["a1_z"].get<double>(), 28 + 0.01 * static_cast<double>(k), 1e-12) << k;
    ASSERT_FALSE(line.contains("error")) << line["error"];
    // D(c) is 42 × 41: one self-stress more than mechanisms, whatever the rank.
    EXPECT_EQ(line["rows"], 42);
    EXPECT_EQ(line["cols"], 41);
    EXPECT_EQ(line["self_stresses"].get<int>(), 1 + line["mechanisms"].get<int>());
    EXPECT_TRUE(line["rank_decision"].contains("status"));
  }
  // Seed 002, Fig. 6: no mechanism and one self-stress, as designed (A1 at z = 28).
  EXPECT_EQ(lines[0]["mechanisms"], 0);
  EXPECT_EQ(lines[0]["self_stresses"], 1);
  EXPECT_EQ(lines[999]["parameters"]["a1_z"], 37.99);
  // Variant 0 is the model file itself: its line carries the keys of `analyze --json` unchanged.
  const auto analyze = run_cli("analyze --json " + example_path("folded-sheet-guide-6.yaml"));
  ASSERT_EQ(analyze.exit_code, 0) << analyze.err;
  const auto report = nlohmann::json::parse(analyze.out);
  for (const char* key : {"kind", "verdict", "rows", "cols", "rank", "mechanisms", "self_stresses", "classification", "rank_decision"})
    EXPECT_EQ(lines[0][key], report[key]) << key;
  EXPECT_EQ(lines[0].contains("generic"), report.contains("generic"));
  fs::remove_all(dir);
}

TEST(SweepCli, CollinearBarsAreAMechanismExactlyAtTheKnownValue) {
  // B of examples/sweeps/two-bars.yaml (A (0, 0), C (2, 0) held) from y = -1 to 1 in 20 steps.
  const auto r = run_cli("sweep " + example_path("sweeps/collinear-bars.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 21u);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const double y = -1.0 + 0.1 * static_cast<double>(k);
    EXPECT_NEAR(lines[k]["parameters"]["b_y"].get<double>(), y, 1e-15);
    // Two bars on two free coordinates of B: rank 2 unless A, B, C are collinear (y = 0), where
    // both bars are along x: rank 1, one mechanism (B moves along y) and one self-stress.
    const int special = k == 10 ? 1 : 0;
    EXPECT_EQ(lines[k]["rank"], 2 - special) << k;
    EXPECT_EQ(lines[k]["mechanisms"], special) << k;
    EXPECT_EQ(lines[k]["self_stresses"], special) << k;
    EXPECT_EQ(lines[k]["verdict"]["exactly_constrained"], special == 0) << k;
  }
  EXPECT_EQ(lines[10]["parameters"]["b_y"], 0.0);
}

TEST(SweepCli, CollinearRevolutesOfANetworkMoveExactlyAtTheKnownValue) {
  const fs::path dir = test_folder("revolutes");
  write(dir / "three-revolutes.yaml", kThreeRevolutes);
  const std::string spec = write(dir / "spec.yaml", R"(kinestat: 1
kind: sweep
model: three-revolutes.yaml
parameters:
  - {name: b_y, coupling: B, coordinate: y, from: -1, to: 1, steps: 20}
)");
  const auto r = run_cli("sweep " + spec + " --shard 0/2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 11u);  // variants 0, 2, ..., 20
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t k = 2 * i;
    EXPECT_EQ(lines[i]["variant"], k);
    // One circuit of three planar revolutes (d = 3, F = 3): FN − CN = F − 3 = 0, and the three
    // unit twists are dependent exactly when the pivots are collinear: FN = CN = 1 at y = 0.
    const int special = k == 10 ? 1 : 0;
    EXPECT_EQ(lines[i]["FN"], special) << k;
    EXPECT_EQ(lines[i]["CN"], special) << k;
  }
  fs::remove_all(dir);
}

TEST(SweepCli, GridOfTwoParametersIsRowMajor) {
  const fs::path dir = test_folder("grid");
  write(dir / "two-bars.yaml", kTwoBars);
  const std::string spec = write(dir / "spec.yaml", R"(kinestat: 1
kind: sweep
model: two-bars.yaml
parameters:
  - {name: b_x, node: B, coordinate: x, values: [0.5, 1.5]}
  - {name: c_y, path: [nodes, C, 1], values: [0, 0.25, 0.5]}
)");
  const auto r = run_cli("sweep " + spec);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[4]["parameters"], nlohmann::json::parse(R"({"b_x": 1.5, "c_y": 0.25})"));
  // B = (b_x, 0.5) lies on AC (A at the origin, C = (2, c_y)) only when c_y = 1 / b_x, i.e. 2 or
  // 2/3: not on this grid, so every variant is rigid.
  for (const auto& line : lines) EXPECT_EQ(line["mechanisms"], 0);
  fs::remove_all(dir);
}

TEST(SweepCli, SubnormalCoordinatesAreAnalysedNotAnInternalError) {
  // Found by fuzz/fuzz_sweep_spec.cpp: B's y = -1.1e-319 (a subnormal double, nearly on AC)
  // made the report's rounding of rank evidence throw (std::stod on underflow) and
  // `analyze` exit 3. Such a B is collinear with A and C to within rounding.
  const fs::path dir = test_folder("subnormal");
  write(dir / "two-bars.yaml", kTwoBars);
  const std::string spec = write(dir / "spec.yaml", R"(kinestat: 1
kind: sweep
model: two-bars.yaml
parameters:
  - {name: b_y, node: B, coordinate: y, values: [-11e-320, 1e-310]}
)");
  const auto r = run_cli("sweep " + spec);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 2u);
  for (const auto& line : lines) EXPECT_FALSE(line.contains("error")) << line["error"];
  fs::remove_all(dir);
}

TEST(SweepCli, AVariantThatFailsGivesAnErrorLineAndTheSweepGoesOn) {
  const fs::path dir = test_folder("failing");
  write(dir / "two-bars.yaml", kTwoBars);
  write(dir / "broken.yaml", "kinestat: 1\nkind: framework\nnodes: [\n");
  const std::string spec = write(dir / "spec.yaml", R"(kinestat: 1
kind: sweep
variants: [two-bars.yaml, missing.yaml, broken.yaml, two-bars.yaml]
)");
  const auto r = run_cli("sweep " + spec);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("2 of 4 variants could not be analysed"), std::string::npos) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0]["file"], "two-bars.yaml");
  EXPECT_EQ(lines[0]["mechanisms"], 0);
  EXPECT_TRUE(lines[1].contains("error"));
  EXPECT_NE(lines[1]["error"].get<std::string>().find("spec.yaml:3:"), std::string::npos) << lines[1]["error"];
  EXPECT_EQ(lines[2]["error"].get<std::string>().rfind("broken.yaml:", 0), 0u) << lines[2]["error"];
  EXPECT_EQ(lines[3]["file"], "two-bars.yaml");
  EXPECT_FALSE(lines[3].contains("error"));
  fs::remove_all(dir);
}

TEST(SweepCli, LinesCarryTheKeysOfTheAnalyzeReportUnchanged) {
  // Networks (exact and floating point, with a verified change) and a bar framework: each line's
  // report keys are those of `kinestat analyze --json` of the same file, value for value.
  const std::vector<std::string> files{"davies-2-circuit.yaml", "four-bar-spatial.yaml", "bennett-perturbed.yaml",
                                       "slider-crank-planar.yaml", "truss-12.yaml"};
  const fs::path dir = test_folder("keys");
  std::string list;
  for (const auto& file : files) list += (list.empty() ? "" : ", ") + example_path(file);
  const std::string spec = write(dir / "spec.yaml", "kinestat: 1\nkind: sweep\nvariants: [" + list + "]\n");
  const auto r = run_cli("sweep " + spec);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), files.size());
  for (std::size_t k = 0; k < files.size(); ++k) {
    const auto analyze = run_cli("analyze --json " + example_path(files[k]));
    ASSERT_EQ(analyze.exit_code, 0) << analyze.err;
    const auto report = nlohmann::json::parse(analyze.out);
    EXPECT_EQ(lines[k]["file"], example_path(files[k]));
    std::size_t carried = 0;
    for (const auto& [key, value] : lines[k].items()) {
      if (key == "variant" || key == "of" || key == "file") continue;
      EXPECT_EQ(value, report[key]) << files[k] << " " << key;
      ++carried;
    }
    EXPECT_GE(carried, 6u) << files[k];  // kind, verdict, counts, classification, rank evidence at least
    for (const char* key : {"kind", "verdict", "classification"}) EXPECT_TRUE(lines[k].contains(key)) << files[k] << " " << key;
  }
  fs::remove_all(dir);
}

TEST(SweepCli, BadSpecsAreOneLineWithTheirPlaceAndExitTwo) {
  const fs::path dir = test_folder("bad");
  write(dir / "two-bars.yaml", kTwoBars);
  struct Case {
    std::string spec, expected;
  };
  const std::vector<Case> cases{
      {"kinestat: 1\nkind: sweep\nmodel: two-bars.yaml\nparameters:\n  - {name: h, node: D, coordinate: y, values: [1]}\n",
       "spec.yaml:5:5: error: the parameter 'h' (node D, coordinate y): 'nodes' (at "},
      {"kinestat: 1\nkind: sweep\nmodel: two-bars.yaml\nparameters:\n  - {name: h, node: B, coordinate: z, values: [1]}\n",
       "spec.yaml:5:5: error: the parameter 'h' (node B, coordinate z): 'B' (at "},
      {"kinestat: 1\nkind: sweep\nmodel: two-bars.yaml\nparameters:\n  - {name: h, node: B, coordinate: y, from: 0, to: 1, steps: 0}\n",
       "spec.yaml:5:62: error: 'steps' must be a whole number from 1"},
      {"kinestat: 1\nkind: sweep\nmodel: two-bars.yaml\nparameters:\n  - {name: h, path: [elements, 0, type], values: [1]}\n",
       "is not a number of the model"},
      {"kinestat: 1\nkind: sweep\nmodel: two-bars.yaml\nvariants: [two-bars.yaml]\n", "spec.yaml:3:8: error: a sweep has either"},
      {"kinestat: 1\nkind: sweep\nmodel: nowhere.yaml\nparameters:\n  - {name: h, node: B, coordinate: y, values: [1]}\n",
       "spec.yaml:3:8: error: the model '"},
      {"kinestat: 1\nkind: framework\n", "spec.yaml:2:7: error: a sweep spec has 'kind: sweep'"},
      // 10⁷ + 1 values twice: refused before any value is made (10¹⁴ variants).
      {"kinestat: 1\nkind: sweep\nmodel: two-bars.yaml\nparameters:\n  - {name: a, node: B, coordinate: x, from: 0, to: 1, steps: 10000000}\n"
       "  - {name: b, node: B, coordinate: y, from: 0, to: 1, steps: 10000000}\n",
       "spec.yaml:6:62: error: the parameters give more than 1000000000000 variants"},
  };
  for (const auto& c : cases) {
    const std::string spec = write(dir / "spec.yaml", c.spec);
    const auto r = run_cli("sweep " + spec);
    EXPECT_EQ(r.exit_code, 2) << c.spec;
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
  }
  const std::string spec = write(dir / "spec.yaml", "kinestat: 1\nkind: sweep\nvariants: [two-bars.yaml]\n");
  EXPECT_EQ(run_cli("sweep " + spec + " --shard 4/4").exit_code, 2);
  EXPECT_EQ(run_cli("sweep " + spec + " " + spec).exit_code, 2);
  fs::remove_all(dir);
}

TEST(SweepCli, MergeRefusesDuplicatesGapsAndForeignLines) {
  const fs::path dir = test_folder("merge");
  const std::string a = write(dir / "a.jsonl", "{\"variant\":0,\"of\":3}\n{\"variant\":2,\"of\":3}\n");
  const std::string b = write(dir / "b.jsonl", "{\"variant\":1,\"of\":3}\n");
  const std::string foreign = write(dir / "c.jsonl", "{\"variant\":1,\"of\":3}\nnot json\n");
  const std::string other = write(dir / "d.jsonl", "{\"variant\":1,\"of\":4}\n");
  const auto ok = run_cli("sweep --merge " + b + " " + a);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.out, "{\"variant\":0,\"of\":3}\n{\"variant\":1,\"of\":3}\n{\"variant\":2,\"of\":3}\n");
  const auto twice = run_cli("sweep --merge " + a + " " + b + " " + b);
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("b.jsonl:1:1: error: variant 1 appears twice"), std::string::npos) << twice.err;
  const auto gap = run_cli("sweep --merge " + a);
  EXPECT_EQ(gap.exit_code, 2);
  EXPECT_NE(gap.err.find("1 of the 3 variants are missing (1)"), std::string::npos) << gap.err;
  const auto bad = run_cli("sweep --merge " + a + " " + foreign);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("c.jsonl:2:1: error: expected a line of 'kinestat sweep' output"), std::string::npos) << bad.err;
  const auto mixed = run_cli("sweep --merge " + a + " " + other);
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("d.jsonl:1:1: error: this line is of a sweep of 4 variants"), std::string::npos) << mixed.err;
  const auto folder = run_cli("sweep --merge " + dir.string());
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
  fs::remove_all(dir);
}

}  // namespace
