// SPDX-License-Identifier: BSD-3-Clause
// The composition layer (src/kinestat/pipeline/): one choice of the network path, one result
// per kind, the same report as the command, one shape of rank evidence.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>

#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "support/cli_run.hpp"
#include "support/network_generator.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;

std::set<std::string> keys(const nlohmann::json& object) {
  std::set<std::string> names;
  for (const auto& [key, value] : object.items()) names.insert(key);
  return names;
}

TEST(NetworkPath, SparseAboveTheDenseLimitUnlessADenseOutputIsAsked) {
  // A ladder of 3L + 1 couplings: L = 101 gives 304 couplings, above the limit of 300.
  const network::Model large = network::generated_ladder(304);
  ASSERT_GT(static_cast<int>(large.couplings.size()), network::kDenseNetworkLimit);
  pipeline::NetworkRequest request;
  EXPECT_EQ(pipeline::network_path(large, request), pipeline::NetworkPath::sparse);
  request.options.arithmetic = network::Arithmetic::exact;  // only the dense path is exact
  EXPECT_EQ(pipeline::network_path(large, request), pipeline::NetworkPath::dense);
  request = {};
  request.matrices = true;
  EXPECT_EQ(pipeline::network_path(large, request), pipeline::NetworkPath::dense);
  request = {};
  request.options.primary = std::vector<std::string>{"ta"};
  EXPECT_EQ(pipeline::network_path(large, request), pipeline::NetworkPath::dense);

  const network::Model small = network::generated_ladder(31);
  request = {};
  EXPECT_EQ(pipeline::network_path(small, request), pipeline::NetworkPath::dense);
  request.path = pipeline::NetworkRequest::Path::sparse;
  EXPECT_EQ(pipeline::network_path(small, request), pipeline::NetworkPath::sparse);
}

// Seed 000, Appendix 3 (Davies' 2-circuit network): FN = 3, CN = 2 (the paper's numbers).
TEST(ModelPipeline, NetworkAnalysedAsTheSeedSays) {
  const io::ModelFile file = io::read_model_file(example_path("davies-2-circuit.yaml"));
  const pipeline::ModelAnalysis analysis = pipeline::analyse_model(file);
  EXPECT_EQ(analysis.kind, io::ModelKind::network);
  ASSERT_TRUE(analysis.network);
  EXPECT_FALSE(analysis.sparse_network || analysis.framework || analysis.structure);
  EXPECT_EQ(analysis.network->result.FN, 3);
  EXPECT_EQ(analysis.network->result.CN, 2);
  EXPECT_EQ(&analysis.verdict(), &analysis.network->verdict);
}

// Seed 004, Eq. 2: three structural groups, formed as {2, 3}, then {4}, then {5}.
TEST(ModelPipeline, StructureDecomposedAsTheSeedSays) {
  const io::ModelFile file = io::read_model_file(example_path("saura-eq2.yaml"));
  const pipeline::ModelAnalysis analysis = pipeline::analyse_model(file);
  EXPECT_EQ(analysis.kind, io::ModelKind::structure);
  ASSERT_TRUE(analysis.structure);
  EXPECT_EQ(analysis.structure->decomposition.groups.size(), 3U);
  EXPECT_TRUE(analysis.structure->decomposition.complete());
}

// The braced square (6 bars, 4 joints, 3 support constraints): Maxwell's rule
// s − m = 6 − (8 − 3) = 1, and the square is rigid: 0 mechanisms, 1 self-stress.
TEST(ModelPipeline, FrameworkReportIsTheCommands) {
  const io::ModelFile file = io::read_model_file(example_path("braced-square.yaml"));
  const pipeline::ModelAnalysis analysis = pipeline::analyse_model(file);
  ASSERT_TRUE(analysis.framework);
  EXPECT_EQ(analysis.verdict().redundant_constraints, 1);
  EXPECT_EQ(analysis.verdict().extra_motions, 0);
  const auto run = run_cli("analyze --json " + example_path("braced-square.yaml"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(pipeline::report_json_text(file, analysis), run.out);
}

TEST(ModelPipeline, StructureOfAFrameworkIsAnInputError) {
  const io::ModelFile file = io::read_model_file(example_path("braced-square.yaml"));
  EXPECT_THROW(pipeline::decompose_model(file), io::InputError);
  EXPECT_THROW(pipeline::analyze_report_json(io::read_model_file(example_path("saura-eq2.yaml"))), io::InputError);
}

// One rank-evidence shape: a floating-point network decision and a framework's decision have
// the same keys, and `largest_singular_value` names σ_max in both.
TEST(RankEvidence, OneShapeForNetworksAndFrameworks) {
  const auto network = run_cli("analyze --json --float " + example_path("davies-2-circuit.yaml"));
  const auto framework = run_cli("analyze --json " + example_path("braced-square.yaml"));
  ASSERT_EQ(network.exit_code, 0) << network.err;
  ASSERT_EQ(framework.exit_code, 0) << framework.err;
  const nlohmann::json motion = nlohmann::json::parse(network.out).at("rank_evidence").at("motion");
  const nlohmann::json decision = nlohmann::json::parse(framework.out).at("rank_decision");
  EXPECT_EQ(keys(motion), keys(decision));
  EXPECT_TRUE(motion.contains("largest_singular_value"));
  EXPECT_FALSE(decision.contains("largest"));
  // The braced square's D(c) is 6 x 5 of full column rank 5 (rigid, one self-stress).
  EXPECT_EQ(decision.at("rank"), 5);
  EXPECT_EQ(decision.at("exact"), false);
}

}  // namespace
}  // namespace kinestat
