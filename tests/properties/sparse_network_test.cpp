// SPDX-License-Identifier: BSD-3-Clause
// The sparse body-twist path against Davies' dense exact path (an independent method: circuit
// and cutset laws over a spanning tree) on seeded random networks and on every example: FN, CN,
// the couplings that carry a self-stress and the couplings that move, and the pair freedoms
// fij, cij of every pair of bodies (dense: ranks of the pair systems in the primaries).
#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <filesystem>
#include <set>

#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/sparse_network_verdict.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/network/sparse_pair_freedoms.hpp"
#include "kinestat/tolerances.hpp"
#include "random_network.hpp"

namespace kinestat::network {
namespace {

// Couplings with a non-zero row in the magnitudes (motions or actions in their primaries).
std::vector<int> support(const std::vector<Magnitude>& magnitudes, const LinearForms& forms) {
  std::set<int> couplings;
  for (Eigen::Index i = 0; i < forms.values.rows(); ++i)
    if (forms.values.row(i).cwiseAbs().maxCoeff() > 0.0) couplings.insert(magnitudes[static_cast<std::size_t>(i)].coupling);
  return {couplings.begin(), couplings.end()};
}

// `arithmetic`: exact for the random networks (rational geometry); the default for the
// examples, whose long literals are rounded irrationals meant in floating point.
void expect_same_answers(const Model& model, const std::string& what, Arithmetic arithmetic = Arithmetic::exact) {
  SCOPED_TRACE(what);
  AnalysisOptions options;
  options.arithmetic = arithmetic;
  options.all_pairs = false;
  const NetworkResult dense = analyse_network(model, options);
  const SparseNetworkResult sparse = analyse_network_sparse(model);
  EXPECT_EQ(sparse.FN, dense.FN);
  EXPECT_EQ(sparse.CN, dense.CN);
  EXPECT_EQ(sparse.F, dense.F);
  EXPECT_EQ(sparse.C, dense.C);
  EXPECT_EQ(sparse.l, dense.l);
  const std::vector<int> stressed = dense.CN > 0 ? support(dense.actions, dense.action_magnitudes) : std::vector<int>{};
  const std::vector<int> moving = dense.FN > 0 ? support(dense.motions, dense.motion_magnitudes) : std::vector<int>{};
  EXPECT_EQ(sparse.stressed, stressed);
  EXPECT_EQ(sparse.moving, moving);
  EXPECT_LT(sparse.residual, 1e-10);
}

// Every pair of bodies, row by row in the dense path's order (i < j, one row per direct coupling
// in coupling order, one row for an uncoupled pair).
void expect_same_pairs(const Model& model, const std::string& what, Arithmetic arithmetic = Arithmetic::exact) {
  SCOPED_TRACE(what);
  AnalysisOptions options;
  options.arithmetic = arithmetic;
  options.all_pairs = true;
  const NetworkResult dense = analyse_network(model, options);
  const SparseNetworkResult sparse = analyse_network_sparse(model, {}, 0, true);
  std::vector<std::pair<int, int>> all;
  const int n = static_cast<int>(model.bodies.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) all.emplace_back(j, i);  // either order is accepted
  const std::vector<SparsePairFreedom> pairs = sparse_pair_freedoms(model, sparse, all, false);
  ASSERT_EQ(pairs.size(), dense.pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    SCOPED_TRACE("row " + std::to_string(k));
    EXPECT_EQ(pairs[k].body_i, dense.pairs[k].body_i);
    EXPECT_EQ(pairs[k].body_j, dense.pairs[k].body_j);
    EXPECT_EQ(pairs[k].coupling, dense.pairs[k].coupling);
    EXPECT_EQ(pairs[k].f, dense.pairs[k].f);
    EXPECT_EQ(pairs[k].c, dense.pairs[k].c);
    EXPECT_EQ(pairs[k].fij, dense.pairs[k].fij);
    EXPECT_EQ(pairs[k].cij, dense.pairs[k].cij);
  }
  // --coupled-pairs: the rows of the direct couplings only, each pair once.
  const std::vector<SparsePairFreedom> coupled = sparse_pair_freedoms(model, sparse, {}, true);
  std::size_t with_coupling = 0;
  for (const auto& p : dense.pairs) with_coupling += p.coupling ? 1U : 0U;
  EXPECT_EQ(coupled.size(), with_coupling);
}

TEST(SparseNetwork, SamePairFreedomsAsDaviesOnRandomNetworks) {
  for (int seed = 0; seed < 40; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(11000 + seed));
    expect_same_pairs(testing::random_network(rng, 2 + seed % 7, seed % 4, seed % 2 == 0), "seed " + std::to_string(seed));
  }
}

TEST(SparseNetwork, SamePairFreedomsAsDaviesOnEveryExample) {
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto file = io::YamlFile::load(entry.path().string());
    if (io::model_kind(file) != "network") continue;
    expect_same_pairs(io::read_network_model(file).model, entry.path().filename().string(), Arithmetic::automatic);
    ++examples;
  }
  EXPECT_GT(examples, 10);
}

TEST(SparseNetwork, PairFreedomsOfDaviesTwoCircuit) {
  // Fig. 1 of seed 000: 4 bodies, 5 couplings each joining a different pair (the file), so 5
  // rows for the coupled pairs; a pair asked twice (both orders) has one row (each pair here has
  // at most one coupling); refused: a body twice, an analysis without the generic vectors.
  const auto file = io::YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/davies-2-circuit.yaml");
  const Model model = io::read_network_model(file).model;
  const SparseNetworkResult r = analyse_network_sparse(model, {}, 0, true);
  EXPECT_EQ(sparse_pair_freedoms(model, r, {}, true).size(), 5U);
  EXPECT_EQ(sparse_pair_freedoms(model, r, {{0, 1}, {1, 0}}, false).size(), 1U);  // one pair, asked twice
  EXPECT_THROW((void)sparse_pair_freedoms(model, r, {{2, 2}}, false), ModelError);
  const SparseNetworkResult without = analyse_network_sparse(model);
  EXPECT_THROW((void)sparse_pair_freedoms(model, without, {{0, 1}}, false), ModelError);
}

// A pair rank counts only what the generic vectors resolve: hand-made generic vectors in which
// the pair of coupling 0 has one clear relative twist (1) and one of 10⁻⁸ of the whole, and
// coupling 0 one clear action magnitude and one of 10⁻⁸ (the largest entry being 1). At the
// default level (kSupportZero ≈ 9.3·10⁻¹⁰ of the largest entry, above 2¹⁹ε ≈ 1.2·10⁻¹⁰ of the
// whole) both count: fij = cij = 2. When the factors are accurate only to 10⁻⁶ (support_zero of
// an ill-conditioned kept block) the 10⁻⁸ is rounding: fij = cij = 1.
TEST(SparseNetwork, PairRanksCountOnlyWhatTheFactorsResolve) {
  const auto file = io::YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/davies-2-circuit.yaml");
  const Model model = io::read_network_model(file).model;
  SparseNetworkResult r = analyse_network_sparse(model, {}, 0, true);
  const Coupling& coupling = model.couplings.front();
  const int moving = coupling.to != r.ground ? coupling.to : coupling.from;
  const Eigen::Index column = (moving < r.ground ? moving : moving - 1) * r.d;
  r.generic_motions.setZero();
  r.generic_motions(column, 0) = 1.0;
  r.generic_motions(column + 1, 1) = 1e-8;
  r.generic_stresses.setZero();
  std::vector<Eigen::Index> rows;
  for (std::size_t row = 0; row < r.row_coupling.size(); ++row)
    if (r.row_coupling[row] == 0) rows.push_back(static_cast<Eigen::Index>(row));
  ASSERT_EQ(rows.size(), 3U);  // coupling A is spherical: three unit actions
  r.generic_stresses(rows[0], 0) = 1.0;
  r.generic_stresses(rows[1], 1) = 1e-8;
  auto row_of_coupling_0 = [&model](const SparseNetworkResult& result) {
    const auto table = sparse_pair_freedoms(model, result, {{model.couplings.front().from, model.couplings.front().to}}, false);
    for (const auto& row : table)
      if (row.coupling == 0) return row;
    ADD_FAILURE() << "no row for coupling 0";
    return SparsePairFreedom{};
  };
  r.motion_support_zero = r.stress_support_zero = kSupportZero;
  const SparsePairFreedom fine = row_of_coupling_0(r);
  EXPECT_EQ(fine.fij, 2);
  EXPECT_EQ(fine.cij, 2);
  r.motion_support_zero = r.stress_support_zero = 1e-6;
  const SparsePairFreedom coarse = row_of_coupling_0(r);
  EXPECT_EQ(coarse.fij, 1);
  EXPECT_EQ(coarse.cij, 1);
}

TEST(SparseNetwork, SameAnswersAsDaviesOnRandomSpatialNetworks) {
  for (int seed = 0; seed < 60; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(5000 + seed));
    expect_same_answers(testing::random_network(rng, 2 + seed % 7, 1 + seed % 4, false), "spatial seed " + std::to_string(seed));
  }
}

TEST(SparseNetwork, SameAnswersAsDaviesOnRandomPlanarNetworks) {
  for (int seed = 0; seed < 60; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(7000 + seed));
    expect_same_answers(testing::random_network(rng, 3 + seed % 7, 1 + seed % 4, true), "planar seed " + std::to_string(seed));
  }
}

// σ_min(R11) of each factor, as estimated, against the dense SVD of K (independent): R11 is a
// block of R, whose singular values are K's, so σ_min(R11) ≤ σ_rank(K); the estimate approaches
// σ_min(R11) from above and settles to 10⁻³ (5 % allowed for slow convergence), and it is at
// most the smallest kept |R_ii|. The supports are decided at support_zero of each factor.
TEST(SparseNetwork, FactorEstimatesAreBoundedByTheSingularValuesOfK) {
  for (int seed = 0; seed < 30; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(static_cast<unsigned>(5000 + seed));
    const Model model = testing::random_network(rng, 2 + seed % 7, 1 + seed % 4, seed % 2 == 1);
    const SparseNetworkResult sparse = analyse_network_sparse(model);
    if (sparse.rank.rank == 0) continue;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(sparse.K)};
    const double sigma_rank = svd.singularValues()(sparse.rank.rank - 1);
    for (const linalg::RankDecision* factor : {&sparse.rank, &sparse.motion_factor_rank}) {
      ASSERT_TRUE(factor->factor_estimated);
      EXPECT_GT(factor->factor_smallest, 0.0);
      EXPECT_LE(factor->factor_smallest, sigma_rank * 1.05);
      EXPECT_LE(factor->factor_smallest, factor->smallest_kept * (1.0 + 1e-12));
    }
    EXPECT_EQ(sparse.motion_support_zero, support_zero(sparse.rank));
    EXPECT_EQ(sparse.stress_support_zero, support_zero(sparse.motion_factor_rank));
  }
}

TEST(SparseNetwork, SupportZeroIsTheFactorsAttainableAccuracy) {
  linalg::RankDecision factor;
  factor.sparse = true;
  factor.rank = 5;
  factor.largest = 4.0;
  EXPECT_EQ(support_zero(factor), kSupportZero);  // not estimated
  factor.factor_estimated = true;
  factor.factor_smallest = 0.5;  // ε·8 is far below 2²²ε
  EXPECT_EQ(support_zero(factor), kSupportZero);
  factor.factor_smallest = 1e-9;  // ε·4·10⁹ ≈ 8.9·10⁻⁷
  EXPECT_DOUBLE_EQ(support_zero(factor), kEpsilon * 4e9);
  factor.factor_smallest = 1e-18;  // no accuracy left: nothing is told from zero
  EXPECT_EQ(support_zero(factor), 1.0);
  factor.factor_smallest = 0.0;  // R11 singular in floating point
  EXPECT_EQ(support_zero(factor), 1.0);
}

// The sparse verdict screens each body's own actions in floating point before the exact
// small-model analysis of its idle spins: the screen must not hide one. Independent count:
// design::idle_motions on the whole model in exact arithmetic (every body, no screen). Without
// inputs the extra motions are exactly the idle spins, the redundant constraints CN.
TEST(SparseNetwork, VerdictFindsTheIdleSpinsTheExactCountFinds) {
  int spins = 0, bodies_that_spin = 0;
  for (int seed = 0; seed < 80; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(9000 + seed));
    const Model model = testing::random_network(rng, 3 + seed % 8, seed % 4, seed % 3 == 0);
    SCOPED_TRACE("seed " + std::to_string(seed));
    int exact = 0;
    for (const auto& idle : design::idle_motions(model, true, {})) {
      exact += idle.count;
      ++bodies_that_spin;
    }
    const SparseNetworkResult r = analyse_network_sparse(model, {}, design::kSparseVerdictStates);
    const design::Verdict v = design::sparse_network_verdict(model, r);
    EXPECT_EQ(v.extra_motions, exact);
    EXPECT_EQ(v.redundant_constraints, r.CN);
    spins += exact;
  }
  EXPECT_GT(bodies_that_spin, 10);  // the seeds do exercise the screen's doubtful side
  EXPECT_GT(spins, 10);
}

TEST(SparseNetwork, SameAnswersAsDaviesOnEveryExample) {
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto file = io::YamlFile::load(entry.path().string());
    if (io::model_kind(file) != "network") continue;
    expect_same_answers(io::read_network_model(file).model, entry.path().filename().string(), Arithmetic::automatic);
    ++examples;
  }
  EXPECT_GT(examples, 10);
}

TEST(SparseNetwork, DaviesTwoCircuitCounts) {
  // Seed 000, Appendix 3: FN = 3, CN = 2.
  const auto file = io::YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/davies-2-circuit.yaml");
  const SparseNetworkResult r = analyse_network_sparse(io::read_network_model(file).model);
  EXPECT_EQ(r.FN, 3);
  EXPECT_EQ(r.CN, 2);
}

}  // namespace
}  // namespace kinestat::network
