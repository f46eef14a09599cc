// SPDX-License-Identifier: BSD-3-Clause
// The `kinestat` command on a large network (the sparse path) gives the library's answer, on
// every run: the fill orders of METIS (which draws from rand()), and with them the ladder's close
// rank evidence and supports, must not change from run to run. (Until issue 36 the command
// factored K and Kᵀ on two threads with a rand() per thread; this test guarded that.)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/io/network_yaml_writer.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "support/cli_run.hpp"
#include "support/network_generator.hpp"

namespace kinestat::network {
namespace {

std::vector<std::string> coupling_names(const Model& model, const std::vector<int>& indices) {
  std::vector<std::string> names;
  for (const int i : indices) names.push_back(model.couplings[static_cast<std::size_t>(i)].name);
  return names;
}

TEST(RepeatableSparseAnswer, CommandGivesTheLibrarysAnswerOnEveryRun) {
  const Model model = generated_ladder(10000);
  const SparseNetworkResult sequential = analyse_network_sparse(model, {}, design::kSparseVerdictStates);
  ASSERT_GT(sequential.FN, 0);
  ASSERT_GT(sequential.CN, 0);

  const std::string file = kinestat::testing::write_temp_file("concurrent_ladder.yaml", io::network_yaml(model));
  const auto first = kinestat::testing::run_cli("analyze --json " + file);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  for (int run = 0; run < 2; ++run)
    EXPECT_TRUE(kinestat::testing::run_cli("analyze --json " + file).out == first.out) << "run " << run + 2 << " differs";
  std::filesystem::remove(file);

  const auto j = nlohmann::json::parse(first.out);
  EXPECT_EQ(j["FN"], sequential.FN);
  EXPECT_EQ(j["CN"], sequential.CN);
  EXPECT_TRUE(j["stressed_couplings"].get<std::vector<std::string>>() == coupling_names(model, sequential.stressed));
  EXPECT_TRUE(j["moving_couplings"].get<std::vector<std::string>>() == coupling_names(model, sequential.moving));
  // Each factor's own evidence, which depends on its fill order.
  const auto& rank = j["rank_evidence"]["body_twist"];
  EXPECT_EQ(rank["smallest_kept"].get<double>(), sequential.rank.smallest_kept);
  EXPECT_EQ(rank["r11_smallest_singular_value"].get<double>(), sequential.rank.factor_smallest);
  const auto& k_factor = j["basis_vectors"]["motion_factor_rank"];
  EXPECT_EQ(k_factor["rank"], sequential.motion_factor_rank.rank);
  EXPECT_EQ(k_factor["smallest_kept"].get<double>(), sequential.motion_factor_rank.smallest_kept);
  EXPECT_EQ(k_factor["r11_smallest_singular_value"].get<double>(), sequential.motion_factor_rank.factor_smallest);
  EXPECT_EQ(j["support_zero"]["self_stresses"].get<double>(), sequential.stress_support_zero);
  EXPECT_EQ(j["support_zero"]["motions"].get<double>(), sequential.motion_support_zero);
}

}  // namespace
}  // namespace kinestat::network
