// SPDX-License-Identifier: BSD-3-Clause
// Semantic properties on valid models (issue 40): random model files that the readers accept
// never crash the analyses, verdicts or reports, and satisfy the counting identities; the
// degenerate models (every node supported, no element, one body, a body on one coupling, all
// couplings rigid, collinear bars) have the counts derived by hand below.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"
#include "support/valid_models.hpp"

namespace kinestat::testing {
namespace {

// Each seed is one random model; a failure prints the model file, ready to save and run. The
// fuzz harness fuzz_valid_models runs the same checks for as long as it is given. Under
// AddressSanitizer the first quarter of the seeds (support/sanitizer_sample.hpp).
constexpr int kSeedsPerKind = sampled_seed_count(150);

// Checks `kSeedsPerKind` models of one generator; at least half must be accepted by the reader,
// or the generator tests nothing.
template <typename Generate>
void check_random_models(std::uint32_t first_seed, Generate generate) {
  int read = 0;
  for (int seed = 0; seed < kSeedsPerKind; ++seed) {
    SeededChoices choices(first_seed + static_cast<std::uint32_t>(seed));
    const std::string text = generate(choices);
    const ModelCheck check = check_model_text(text);
    EXPECT_EQ(check.failed, "") << "seed " << seed << ":\n" << text;
    read += check.read ? 1 : 0;
  }
  EXPECT_GE(read, kSeedsPerKind / 2);
}

TEST(ValidModels, RandomFrameworksKeepMaxwellsRuleAndTheirProposal) { check_random_models(0, random_framework_yaml); }

TEST(ValidModels, RandomNetworksKeepDaviesIdentities) { check_random_models(10000, random_network_yaml); }

TEST(ValidModels, RandomStructuresAreDecomposed) { check_random_models(20000, random_structure_yaml); }

framework::FrameworkResult framework_of(const std::string& text) {
  return framework::analyse_framework(io::read_framework_model(io::YamlFile::parse("degenerate.yaml", text)));
}

network::NetworkResult network_of(const std::string& text) {
  return network::analyse_network(io::read_network_model(io::YamlFile::parse("degenerate.yaml", text)).model);
}

// A bar between two fixed nodes: D(c) has the bar's one row and no column (nothing can move),
// so rank 0, no mechanism, and the bar's force is one self-stress (CN = 1 in the issue).
TEST(DegenerateModels, OneBarBetweenTwoSupportsIsOneSelfStress) {
  const auto a = framework_of(
      "kinestat: 1\nkind: framework\ndimension: planar\nnodes: {A: [0, 0], B: [1, 0]}\n"
      "supports: {A: fixed, B: fixed}\nelements:\n  - {type: truss, nodes: [A, B]}\n");
  EXPECT_EQ(a.m, 1);
  EXPECT_EQ(a.n, 0);
  EXPECT_EQ(a.rank, 0);
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.self_stresses, 1);
}

// Every node of a spatial triangle supported: three rows, no column: three self-stresses.
TEST(DegenerateModels, EveryNodeSupportedGivesASelfStressPerBar) {
  const auto a = framework_of(
      "kinestat: 1\nkind: framework\nnodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0, 1, 0]}\n"
      "supports: {A: fixed, B: fixed, C: fixed}\n"
      "elements:\n  - {type: truss, nodes: [A, B]}\n  - {type: truss, nodes: [B, C]}\n  - {type: truss, nodes: [C, A]}\n");
  EXPECT_EQ(a.m, 3);
  EXPECT_EQ(a.n, 0);
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.self_stresses, 3);
}

// No element: every coordinate of the two free planar nodes is a mechanism (2 x 2 = 4).
TEST(DegenerateModels, NoElementLeavesEveryCoordinateFree) {
  const auto a = framework_of("kinestat: 1\nkind: framework\ndimension: planar\nnodes: {A: [0, 0], B: [1, 0]}\nelements: []\n");
  EXPECT_EQ(a.m, 0);
  EXPECT_EQ(a.n, 4);
  EXPECT_EQ(a.mechanisms, 4);
  EXPECT_EQ(a.self_stresses, 0);
}

// A, B, C collinear on the x axis, A and C fixed, bars A-B and B-C: both rows of D(c) are
// ±(1, 0) in B's coordinates, rank 1: B moves along y to first order (one mechanism) and the two
// bars carry equal tension (one self-stress).
TEST(DegenerateModels, CollinearBarsHaveOneMechanismAndOneSelfStress) {
  const auto a = framework_of(
      "kinestat: 1\nkind: framework\ndimension: planar\nnodes: {A: [0, 0], B: [1, 0], C: [2, 0]}\n"
      "supports: {A: fixed, C: fixed}\nelements:\n  - {type: truss, nodes: [A, B]}\n  - {type: truss, nodes: [B, C]}\n");
  EXPECT_EQ(a.rank, 1);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 1);
}

// One body on one planar revolute to the ground: F = 1, no circuit (l = 0): FN = 1, CN = 0.
TEST(DegenerateModels, ABodyOnOneCouplingMovesOnIt) {
  const auto r = network_of(
      "kinestat: 1\nkind: network\ndimension: planar\nground: g\n"
      "couplings:\n  - {name: A, type: revolute, between: [g, b], point: [0, 0]}\n");
  EXPECT_EQ(r.l, 0);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 0);
}

// Two planar bodies joined by two rigid couplings: F = 0, C = 6, one circuit (l = 1):
// FN − CN = F − 3 l = −3 and FN = F − m = 0, so CN = 3.
TEST(DegenerateModels, TwoRigidCouplingsInOneCircuitAreThreeSelfStresses) {
  const auto r = network_of(
      "kinestat: 1\nkind: network\ndimension: planar\nground: g\n"
      "couplings:\n  - {name: A, type: rigid, between: [g, b]}\n  - {name: B, type: rigid, between: [g, b]}\n");
  EXPECT_EQ(r.F, 0);
  EXPECT_EQ(r.C, 6);
  EXPECT_EQ(r.FN, 0);
  EXPECT_EQ(r.CN, 3);
}

// The command on the framework that used to crash (a segmentation fault in analyse_framework):
// exit 0 and the counts derived above, in text and JSON.
TEST(DegenerateModels, TheCommandAnalysesAFrameworkWithEveryNodeSupported) {
  const std::string path = write_temp_file("every_node_supported.yaml",
                                           "kinestat: 1\nkind: framework\ndimension: planar\nnodes: {A: [0, 0], B: [1, 0]}\n"
                                           "supports: {A: fixed, B: fixed}\nelements:\n  - {type: truss, nodes: [A, B]}\n");
  const CliRun text = run_cli("analyze " + path);
  EXPECT_EQ(text.exit_code, 0) << text.err;
  const CliRun json = run_cli("analyze --json " + path);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"self_stresses\": 1"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"mechanisms\": 0"), std::string::npos) << json.out;
}

// A zero-length bar (two nodes at one point) is refused by the reader with its position, exit 2.
TEST(DegenerateModels, CoincidentNodesOfABarAreRefusedWithTheirPlace) {
  const std::string path = write_temp_file("coincident.yaml",
                                           "kinestat: 1\nkind: framework\ndimension: planar\nnodes: {A: [0, 0], B: [0, 0]}\n"
                                           "elements:\n  - {type: truss, nodes: [A, B]}\n");
  const CliRun run = run_cli("analyze " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("coincident.yaml:"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace kinestat::testing
