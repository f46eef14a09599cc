// SPDX-License-Identifier: BSD-3-Clause
// Model numbers too large for doubles. A network with a 120-digit coordinate (found by
// fuzz_model_file) made the verdict's change search convert exact coupling actions of a candidate
// beyond 1.8e308 to doubles and hand the infinite entries to LAPACK, whose SVD never returned.
// The screen now decides such a body exactly, and no floating-point decomposition accepts a
// non-finite matrix (linalg::NonFiniteMatrix).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <string>

#include "kinestat/design/network_verdict.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/linalg/non_finite_matrix.hpp"
#include "kinestat/linalg/null_spaces.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/network/analyse_network.hpp"

namespace kinestat {
namespace {

// The fuzzer's input as it found it (a mutated 3-UPU platform; its body names were mutated too).
// Hand count: 9 bodies, 9 couplings, connected, so one loop: U2b and U3b both join leg3_upper to
// the platform. Two universals at different points with different axis pairs share no twist, so
// that loop is rigid: its 4 freedoms against 6 equations leave CN = 6 − 4 = 2. The rest is trees
// hanging off it: base–leg1_lower–leg1_upper–platform (U1a 2 + P1 1 + U1b 2 = 5), leg2_lower and
// legZ_upper on base (U2a 2 + P2 1 = 3), leg3_lower on base (U3a 2), leg0_lower on leg3_upper
// (P3 1): FN = 5 + 3 + 2 + 1 = 11 (and FN − CN = 9 = ΣF − 6·l = 15 − 6, Grübler–Kutzbach).
constexpr const char* kHugeCoordinate = R"(kinestat: 1
kind: network
name: Tsai 3-UPU translational platform
dimension: spatial
ground: base
couplings:
  - {name: U1a, type: universal, between: [base, leg1_lower], point: [10, 0, 0], axis: [0, 1, 0], axis2: [1, 0, 1]}
  - {name: P1, type: prismatic, between: [leg1_lower, leg1_upper], axis: [-7, 1, 7]}
  - {name: U1b, type: universal, between: [leg1_upper, platform], point: [2, 1, 7], axis: [1, 0, 1], axis2: [0, 1, 0]}
  - {name: U2a, type: universal, between: [base, leg2_lower], point: [-5, 9, 0], axis: [-9, -5, 0], axis2: [-10, 18, 15]}
  - {name: P2, type: prismatic, between: [leg2_lower, legZ_upper], axis: [3, -5, 8]}
  - {name: U2b, type: universal, between: [leg3_upper, platform], point: [-2, 4, 8], axis: [-10, 18, 15], axis2: [-9, -5, 0]}
  - {name: U3a, type: universal, between: [base, leg3_lower], point: [-4, -8, 0], axis: [2, -1, 0], axis2: [-7, -14, 13]}
  - {name: P3, type: prismatic, between: [leg0_lower, leg3_upper], axis: [3, 5, 7]}
  - {name: U3b, type: universal, between: [leg3_upper, platform], point: [-0, -3, 111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111117], axis: [-7, -14, 13], axis2: [2, -1, 0]}
)";

TEST(OverflowingNumbers, AHugeCoordinateGetsItsCountsAndVerdict) {
  const auto loaded = io::read_network_model(io::YamlFile::parse("huge.yaml", kHugeCoordinate));
  const auto result = network::analyse_network(loaded.model);
  EXPECT_EQ(result.FN, 11);
  EXPECT_EQ(result.CN, 2);
  const design::Verdict verdict = design::network_verdict(loaded.model, result);  // returned: no hang
  EXPECT_EQ(verdict.extra_motions - verdict.redundant_constraints, 11 - 2);
}

TEST(OverflowingNumbers, NoDecompositionAcceptsANonFiniteMatrix) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(7, 3);
  a(4, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(linalg::singular_values(a), linalg::NonFiniteMatrix);
  EXPECT_THROW(linalg::numerical_rank(a), linalg::NonFiniteMatrix);
  EXPECT_THROW(linalg::analyse_svd(a), linalg::NonFiniteMatrix);
  EXPECT_THROW(linalg::analyse_null_spaces(a, {}), linalg::NonFiniteMatrix);
  a(4, 1) = std::nan("");
  EXPECT_THROW(linalg::numerical_rank(a), linalg::NonFiniteMatrix);
  // Bad input, not an internal error: exit code 2, and a message that says what to do.
  try {
    linalg::require_finite(a);
    FAIL() << "no exception";
  } catch (const linalg::NonFiniteMatrix& error) {
    EXPECT_EQ(error.exit_code(), kExitBadInput);
    EXPECT_NE(std::string(error.what()).find("smaller unit"), std::string::npos);
  }
  // Large but finite: decomposed. The other two columns are unit vectors, 1e-300 of the largest
  // singular value, far below the relative tolerance: rank 1.
  a(4, 1) = 1e300;
  EXPECT_EQ(linalg::numerical_rank(a).rank, 1);
}

}  // namespace
}  // namespace kinestat
