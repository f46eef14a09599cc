// SPDX-License-Identifier: BSD-3-Clause
// `kinestat structure` on a coupling-network model: the four-bar of seed 004, Fig. 2, written
// as a planar network with the crank's revolute as input, gives SG-I = {2}, SG-II = {3, 4}.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace {

using kinestat::testing::run_cli;
using kinestat::testing::write_temp_file;

const char* const kFourBar =
    "kinestat: 1\n"
    "kind: network\n"
    "dimension: planar\n"
    "ground: 1\n"
    "couplings:\n"
    "  - {name: A, type: revolute, between: [1, 2], point: [0, 0]}\n"
    "  - {name: B, type: revolute, between: [2, 3], point: [1, 2]}\n"
    "  - {name: C, type: revolute, between: [3, 4], point: [4, 3]}\n"
    "  - {name: D, type: revolute, between: [4, 1], point: [5, 0]}\n"
    "inputs: [A]\n";

TEST(StructureOfNetwork, FourBarOfSeedFigure2) {
  const std::string path = write_temp_file("network-four-bar.yaml", kFourBar);
  const auto run = run_cli("structure --json " + path);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["groups"].size(), 2u);
  EXPECT_EQ(j["groups"][0]["bodies"], nlohmann::json({2}));
  EXPECT_EQ(j["groups"][1]["bodies"], nlohmann::json({3, 4}));
  // The same network still analyses as a mechanism: FN = 1 (planar four-bar).
  const auto analysis = run_cli("analyze --json " + path);
  ASSERT_EQ(analysis.exit_code, 0) << analysis.err;
  EXPECT_EQ(nlohmann::json::parse(analysis.out)["FN"], 1);
  std::filesystem::remove(path);
}

TEST(StructureOfNetwork, RigidCouplingIsNotAPair) {
  const std::string path = write_temp_file(
      "network-rigid.yaml",
      "kinestat: 1\ncouplings:\n  - {name: A, type: rigid, between: [1, 2]}\n");
  const auto run = run_cli("structure " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path + ":3:5: error: coupling 'A' of type rigid is neither a lower nor a higher pair"), std::string::npos)
      << run.err;
  std::filesystem::remove(path);
}

TEST(StructureOfNetwork, UnknownInput) {
  const std::string path = write_temp_file(
      "network-bad-input.yaml",
      "kinestat: 1\ncouplings:\n  - {name: A, type: spherical, between: [1, 2], point: [0, 0, 0]}\ninputs: [Z]\n");
  const auto run = run_cli("structure " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path + ":4:10: error: 'inputs' names 'Z'"), std::string::npos) << run.err;
  std::filesystem::remove(path);
}

}  // namespace
