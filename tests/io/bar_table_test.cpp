// SPDX-License-Identifier: BSD-3-Clause
// Bar tables (.bars, issue 41 item 4): small frameworks whose counts are derived by hand
// (Maxwell's rule on free coordinates with the rank known by inspection), every refusal at its
// line and column, and the command's --max-input-size (the limit on model files raised or
// lowered explicitly, named in the message that refuses a large file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/bar_table_reader.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "support/cli_run.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;

bool contains_text(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string bar_table_error(const std::string& text) {
  try {
    (void)parse_bar_table("in.bars", text);
    return "accepted";
  } catch (const InputError& error) {
    return error.what();
  }
}

// A unit square 0(0,0) 1(1,0) 2(1,1) 3(0,1), node 0 pinned (x, y) and node 1 on a roller (y):
// 8 − 3 = 5 free coordinates. Its 4 sides alone leave the shear: 1 mechanism, no self-stress
// (the 4 side bars are independent). With both diagonals, 6 bars on 5 free coordinates of a
// rigid square: 0 mechanisms, 6 − 5 = 1 self-stress.
std::string square(bool diagonals) {
  std::string text = "kinestat bars 1\n# a unit square\ndimension 2\nnodes 4\n0 0\n1 0\n1 1\n0 1\n";
  text += diagonals ? "bars 6\n0 1\n1 2\n2 3\n3 0\n0 2\n1 3\n" : "bars 4\n0 1\n1 2\n2 3\n3 0\n";
  text += "supports 2\n0 xy\n1 y\n";
  return text;
}

TEST(BarTable, SquareCountsByHand) {
  const framework::FrameworkModel shear = parse_bar_table("in.bars", square(false));
  ASSERT_EQ(shear.nodes.size(), 4u);
  ASSERT_EQ(shear.elements.size(), 4u);
  EXPECT_EQ(shear.dimension, 2);
  EXPECT_EQ(shear.nodes[2].name, "2");
  EXPECT_EQ(shear.elements[3].name, "4");
  EXPECT_EQ(shear.elements[3].nodes, (std::vector<std::size_t>{3, 0}));
  EXPECT_EQ(shear.nodes[0].roles[0], framework::CoordinateRole::fixed);
  EXPECT_EQ(shear.nodes[0].roles[1], framework::CoordinateRole::fixed);
  EXPECT_EQ(shear.nodes[1].roles[0], framework::CoordinateRole::dependent);
  EXPECT_EQ(shear.nodes[1].roles[1], framework::CoordinateRole::fixed);
  const framework::FrameworkResult loose = framework::analyse_framework(shear);
  EXPECT_EQ(loose.mechanisms, 1);
  EXPECT_EQ(loose.self_stresses, 0);
  const framework::FrameworkResult braced = framework::analyse_framework(parse_bar_table("in.bars", square(true)));
  EXPECT_EQ(braced.mechanisms, 0);
  EXPECT_EQ(braced.self_stresses, 1);
}

TEST(BarTable, SpatialTetrahedronOnSixSupportsIsExactlyConstrained) {
  // 4 nodes × 3 − 6 held translations (0: xyz, 1: yz, 2: z) = 6 free coordinates, 6 bars of a
  // rigid tetrahedron: 0 mechanisms, 0 self-stresses. No supports section: 12 free, 6 rigid motions.
  const std::string body = "kinestat bars 1\ndimension 3\nnodes 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nbars 6\n0 1\n0 2\n0 3\n1 2\n1 3\n2 3\n";
  const framework::FrameworkResult held = framework::analyse_framework(parse_bar_table("in.bars", body + "supports 3\n0 xyz\n1 yz\n2 z\n"));
  EXPECT_EQ(held.mechanisms, 0);
  EXPECT_EQ(held.self_stresses, 0);
  const framework::FrameworkResult free = framework::analyse_framework(parse_bar_table("in.bars", body));
  EXPECT_EQ(free.mechanisms, 6);
  EXPECT_EQ(free.self_stresses, 0);
}

TEST(BarTable, EveryRefusalIsLocated) {
  EXPECT_EQ(bar_table_error("kinestat bars 2\n"), "in.bars:1:1: error: expected the header 'kinestat bars 1'");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 4\n"), "in.bars:2:11: error: expected the dimension 2 or 3");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 x\n"),
            "in.bars:5:3: error: expected the coordinates (x y) of node 1 (finite numbers), found 'x'");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 0 0\n"),
            "in.bars:5:5: error: expected the end of the line after the 2 coordinates (x y) of node 1, found '0'");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 0\nbars 1\n0 2\n"),
            "in.bars:7:3: error: expected the second node of bar 1 (a node index from 0 to 1), found '2'");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 0\nbars 1\n1 1\n"),
            "in.bars:7:3: error: bar 1 joins node 1 to itself");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n0 0\nbars 1\n0 1\n"),
            "in.bars:7:1: error: zero-length bar 1: nodes 0 and 1 coincide");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 0\nbars 1\n0 1\nsupports 2\n0 x\n0 y\n"),
            "in.bars:10:1: error: node 0 is supported twice");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 0\nbars 1\n0 1\nsupports 1\n0 xz\n"),
            "in.bars:9:4: error: expected the translations node 0 holds (x, y or xy)");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2\n0 0\n1 0\nbars 1\n0 1\nsupports 0\nmore\n"),
            "in.bars:9:1: error: expected the end of the bar table after its supports");
  // No node: refused as a YAML framework is ('nodes' is empty), not analysed as an empty structure.
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 0\nbars 0\n"),
            "in.bars:3:7: error: expected at least one node: a framework needs one");
}

// Nodes and no bar (found by fuzz_bar_table): a valid table whose YAML must read back; it wrote
// "elements:" with nothing after it, which YAML reads as null, not as an empty list. By hand:
// three free nodes in the plane, 2 × 3 = 6 mechanisms, no self-stress.
TEST(BarTable, NodesWithoutBarsAreWrittenAsYamlThatReadsBack) {
  const framework::FrameworkModel model = parse_bar_table("in.bars", "kinestat bars 1\ndimension 2\nnodes 3\n0 0\n0 0\n0 1\nbars 0\n");
  const std::string yaml = framework_yaml(model, {});
  EXPECT_NE(yaml.find("elements: []\n"), std::string::npos) << yaml;
  const framework::FrameworkModel again = read_framework_model(YamlFile::parse("again.yaml", yaml));
  EXPECT_EQ(again.nodes.size(), 3u);
  EXPECT_TRUE(again.elements.empty());
  const auto result = framework::analyse_framework(again);
  EXPECT_EQ(result.mechanisms, 6);
  EXPECT_EQ(result.self_stresses, 0);
}

TEST(BarTable, CountsAreNotTrustedForMemory) {
  // Two billion nodes announced in a 40-byte file: refused at the end of the file, after
  // reserving only what the text could hold.
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 2000000000\n0 0\n"),
            "in.bars:5:1: error: expected the coordinates (x y) of node 1 of 2000000000, found the end of the file");
  EXPECT_EQ(bar_table_error("kinestat bars 1\ndimension 2\nnodes 99999999999\n"),
            "in.bars:3:7: error: expected the number of nodes (a whole number up to 2147483647), found '99999999999'");
}

class BarTableCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::scratch_folder() / "bar_table_command";
    fs::create_directories(dir_);
  }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  fs::path dir_;
};

TEST_F(BarTableCommand, AnalyzeReadsABarTable) {
  const auto run = testing::run_cli("analyze --json " + write("square.bars", square(true)));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(contains_text(run.out, "\"self_stresses\": 1")) << run.out.substr(0, 2000);
  const auto bad = testing::run_cli("analyze " + write("bad.bars", "kinestat bars 1\ndimension 5\n"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(contains_text(bad.err, "bad.bars:2:11: error: expected the dimension 2 or 3")) << bad.err;
  EXPECT_EQ(bad.out, "");
}

TEST_F(BarTableCommand, MaxInputSizeRaisesAndLowersTheLimit) {
  // A 2,000-byte bar table: 16 nodes on a line and 15 bars, padded by a comment.
  std::string text = "kinestat bars 1\ndimension 2\nnodes 16\n";
  for (int i = 0; i < 16; ++i) text += std::to_string(i) + " 0\n";
  text += "bars 15\n";
  for (int i = 0; i < 15; ++i) text += std::to_string(i) + " " + std::to_string(i + 1) + "\n";
  text += "# " + std::string(2000 - text.size() - 3, 'x') + "\n";
  ASSERT_EQ(text.size(), 2000u);
  const std::string path = write("line.bars", text);
  const auto refused = testing::run_cli("analyze --max-input-size 1KiB " + path);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_TRUE(contains_text(refused.err, "larger than the 1024 bytes limit on model files")) << refused.err;
  EXPECT_TRUE(contains_text(refused.err, "--max-input-size")) << refused.err;
  const auto read = testing::run_cli("analyze --max-input-size 2000 " + path);
  EXPECT_EQ(read.exit_code, 0) << read.err;
  const auto yaml = testing::run_cli("analyze --max-input-size 1K " + std::string(KINESTAT_SOURCE_DIR) + "/examples/truss-12.yaml");
  EXPECT_EQ(yaml.exit_code, 2);
  EXPECT_TRUE(contains_text(yaml.err, "--max-input-size SIZE raises it")) << yaml.err;
  const auto nonsense = testing::run_cli("analyze --max-input-size 12parsecs " + path);
  EXPECT_EQ(nonsense.exit_code, 2);
  EXPECT_TRUE(contains_text(nonsense.err, "--max-input-size")) << nonsense.err;
}

}  // namespace
}  // namespace kinestat::io
