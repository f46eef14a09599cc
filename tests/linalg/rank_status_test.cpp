// SPDX-License-Identifier: BSD-3-Clause
// The status of a rank decision (exact, certain, close, unproven) and its distance, on matrices
// whose singular values are known by construction (diagonal matrices: the singular values are
// the absolute diagonal entries, computed exactly by any SVD).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {
namespace {

Eigen::MatrixXd diagonal(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v(i++) = x;
  return v.asDiagonal();
}

TEST(RankStatus, ErrorBoundIsTheStatedFormula) {
  // (m n ε + 2 max(m, n) ρ) σ_max: 3 × 2, σ_max 4.
  EXPECT_DOUBLE_EQ(singular_value_error_bound(3, 2, 0.0, 4.0), 6 * kEpsilon * 4.0);
  EXPECT_DOUBLE_EQ(singular_value_error_bound(3, 2, 1e-14, 4.0), (6 * kEpsilon + 2 * 3 * 1e-14) * 4.0);
}

TEST(RankStatus, ClearGapIsCertain) {
  // 1e-3 kept is far above the bound 9 ε; 1e-20 dropped is below it.
  const RankDecision d = numerical_rank(diagonal({1, 1e-3, 1e-20}));
  EXPECT_EQ(d.rank, 2);
  EXPECT_EQ(d.status(), RankStatus::certain);
  EXPECT_FALSE(d.close());
  EXPECT_DOUBLE_EQ(*d.distance(), 1e-3);
  EXPECT_DOUBLE_EQ(*d.relative_dropped(), 1e-20);
  EXPECT_EQ(d.full_rank(), 3);
  EXPECT_STREQ(rank_status_name(d.status()), "certain");
}

TEST(RankStatus, KeptValueWithinTheMarginOfTheBoundIsClose) {
  // Bound 9 ε ≈ 2e-15; threshold 3 ε ≈ 6.7e-16 keeps 1e-14, but 1e-14 < 100 × 2e-15.
  const RankDecision d = numerical_rank(diagonal({1, 1e-14, 0}));
  EXPECT_EQ(d.rank, 2);
  EXPECT_EQ(d.status(), RankStatus::close);
  EXPECT_DOUBLE_EQ(*d.distance(), 1e-14);
  // 1e-12 is 500 times the bound: certain, though near a rank change (distance 1e-12).
  const RankDecision far = numerical_rank(diagonal({1, 1e-12, 0}));
  EXPECT_EQ(far.status(), RankStatus::certain);
  EXPECT_LT(*far.distance(), kNearRankChange);
}

TEST(RankStatus, ValueDroppedByALooseToleranceIsClose) {
  RankTolerance loose;
  loose.relative = 1e-5;
  const RankDecision d = numerical_rank(diagonal({1, 1e-6}), loose);
  EXPECT_EQ(d.rank, 1);
  EXPECT_EQ(d.status(), RankStatus::close);  // 1e-6 is no rounding: the tolerance decided
  EXPECT_DOUBLE_EQ(*d.distance(), 1.0);
  EXPECT_DOUBLE_EQ(*d.relative_dropped(), 1e-6);
}

TEST(RankStatus, InputRoundingWidensTheBound) {
  // ρ = 1e-13 (coordinates 450 times the model's size): bound ≈ 2 · 2 · 1e-13 = 4e-13, so a kept
  // 1e-11 (25 × the bound) is close where it would be certain for coordinates near the origin.
  RankTolerance rounded;
  rounded.input_rounding = 1e-13;
  EXPECT_EQ(numerical_rank(diagonal({1, 1e-11}), rounded).status(), RankStatus::close);
  EXPECT_EQ(numerical_rank(diagonal({1, 1e-11})).status(), RankStatus::certain);
}

TEST(RankStatus, ZeroMatrixAndRankZero) {
  const RankDecision zero = numerical_rank(Eigen::MatrixXd::Zero(2, 3));
  EXPECT_EQ(zero.rank, 0);
  EXPECT_EQ(zero.status(), RankStatus::certain);
  EXPECT_FALSE(zero.distance().has_value());
}

// The distributed backend decides a rank without computing the smallest kept singular value
// (smallest_kept stays 0): the distance to a rank change is then unknown, not 0.
TEST(RankStatus, UncomputedSmallestKeptGivesNoDistance) {
  RankDecision d;
  d.rank = 5;
  d.largest = 2.0;
  d.threshold = 1e-12;
  d.sparse = true;
  EXPECT_FALSE(d.distance().has_value());
  d.smallest_kept = 0.5;
  EXPECT_DOUBLE_EQ(*d.distance(), 0.25);
}

TEST(RankStatus, ExactDecisionsKeepTheirStatusAndGainADistance) {
  RankDecision d;
  d.exact = true;
  d.rank = 2;
  d.rows = d.cols = 3;
  EXPECT_EQ(d.status(), RankStatus::exact);
  EXPECT_FALSE(d.distance().has_value());  // no floating-point copy yet
  Eigen::VectorXd sigma(3);
  sigma << 2, 1e-9, 1e-17;
  add_floating_evidence(d, sigma);
  EXPECT_EQ(d.status(), RankStatus::exact);
  EXPECT_DOUBLE_EQ(*d.distance(), 0.5e-9);
  EXPECT_DOUBLE_EQ(*d.relative_dropped(), 0.5e-17);
}

// A sparse decision of rank 3 whose smallest kept |R_ii| (0.5) is far above its threshold.
RankDecision clear_sparse_decision() {
  RankDecision d;
  d.sparse = true;
  d.rank = 3;
  d.largest = 1;
  d.threshold = 1e-13;
  d.smallest_kept = 0.5;
  return d;
}

TEST(RankStatus, SparseDecisionsAreNeverCertain) {
  RankDecision d = clear_sparse_decision();
  EXPECT_EQ(d.status(), RankStatus::unproven);
  d.smallest_kept = 1e-12;  // within 100 × the threshold
  EXPECT_EQ(d.status(), RankStatus::close);
}

TEST(RankStatus, SparseDecisionWithANearlySingularLiveBlockIsClose) {
  RankDecision d = clear_sparse_decision();  // the pivots alone: clear
  d.factor_smallest = 1e-14;
  EXPECT_EQ(d.status(), RankStatus::unproven);  // not marked as estimated: ignored
  d.factor_estimated = true;
  EXPECT_EQ(d.status(), RankStatus::close);
  d.factor_smallest = 1e-10;  // above 100 × the threshold
  EXPECT_EQ(d.status(), RankStatus::unproven);
}

}  // namespace
}  // namespace kinestat::linalg
