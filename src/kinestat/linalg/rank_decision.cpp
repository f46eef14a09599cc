// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/rank_decision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinestat::linalg {

double default_relative_tolerance(Eigen::Index rows, Eigen::Index cols, double input_rounding) {
  return static_cast<double>(std::max<Eigen::Index>({rows, cols, 1})) *
         std::max(kEpsilon, kInputRoundingFactor * input_rounding);
}

double input_rounding_level(double largest_coordinate, double size) {
  if (!(size > 0.0) || !std::isfinite(largest_coordinate)) return kEpsilon;
  return kEpsilon * std::max(1.0, largest_coordinate / size);
}

const char* rank_status_name(RankStatus status) {
  switch (status) {
    case RankStatus::exact: return "exact";
    case RankStatus::certain: return "certain";
    case RankStatus::close: return "close";
    case RankStatus::unproven: return "unproven";
  }
  return "close";
}

double singular_value_error_bound(Eigen::Index rows, Eigen::Index cols, double input_rounding, double largest) {
  const double m = static_cast<double>(std::max<Eigen::Index>(rows, 1)), n = static_cast<double>(std::max<Eigen::Index>(cols, 1));
  return (m * n * kEpsilon + kInputRoundingFactor * std::max(m, n) * input_rounding) * largest;
}

double RankDecision::gap() const {
  if (exact || largest_dropped == 0.0) return std::numeric_limits<double>::infinity();
  return smallest_kept / largest_dropped;
}

RankStatus RankDecision::status() const {
  if (exact) return RankStatus::exact;
  if (sparse) {
    const double kept = factor_estimated ? std::min(smallest_kept, factor_smallest) : smallest_kept;
    return rank > 0 && kept < kCertainMargin * threshold ? RankStatus::close : RankStatus::unproven;
  }
  // A zero matrix has zero computed singular values: nothing to decide.
  if (largest <= 0.0) return RankStatus::certain;
  const bool kept_clear = rank == 0 || smallest_kept >= kCertainMargin * error_bound;
  const bool dropped_noise = largest_dropped <= error_bound;
  return kept_clear && dropped_noise ? RankStatus::certain : RankStatus::close;
}

bool RankDecision::close() const { return status() == RankStatus::close; }

std::optional<double> RankDecision::distance() const {
  // A kept singular value is positive: 0 means it was not computed (the distributed backend
  // computes it only for small null spaces), and "0 from a mechanism" would be a false claim.
  if (rank == 0 || !(largest > 0.0) || !(smallest_kept > 0.0)) return std::nullopt;
  // σ_min(R11), when estimated, is the nearer rank-deficient block (at most the smallest pivot).
  if (factor_estimated) return std::min(smallest_kept, factor_smallest) / largest;
  return smallest_kept / largest;
}

std::optional<double> RankDecision::relative_dropped() const {
  if (!(largest > 0.0)) return std::nullopt;
  return largest_dropped / largest;
}

void add_floating_evidence(RankDecision& decision, const Eigen::VectorXd& singular_values) {
  const Eigen::Index r = decision.rank;
  if (singular_values.size() == 0 || r > singular_values.size()) return;
  decision.largest = singular_values(0);
  decision.smallest_kept = r > 0 ? singular_values(r - 1) : 0.0;
  decision.largest_dropped = r < singular_values.size() ? singular_values(r) : 0.0;
}

RankDecision decide_rank(const Eigen::VectorXd& singular_values, Eigen::Index rows, Eigen::Index cols,
                         const RankTolerance& tolerance) {
  RankDecision decision;
  decision.rows = rows;
  decision.cols = cols;
  decision.largest = singular_values.size() > 0 ? singular_values(0) : 0.0;
  decision.input_rounding = tolerance.input_rounding;
  decision.rounding_level = default_relative_tolerance(rows, cols, tolerance.input_rounding) * decision.largest;
  const double relative = tolerance.relative.value_or(default_relative_tolerance(rows, cols, tolerance.input_rounding));
  decision.threshold = relative * decision.largest;
  decision.error_bound = singular_value_error_bound(rows, cols, tolerance.input_rounding, decision.largest);
  for (Eigen::Index i = 0; i < singular_values.size(); ++i) {
    const double sigma = singular_values(i);
    if (sigma > decision.threshold) {
      ++decision.rank;
      decision.smallest_kept = sigma;
    } else {
      decision.largest_dropped = std::max(decision.largest_dropped, sigma);
    }
  }
  return decision;
}

}  // namespace kinestat::linalg
