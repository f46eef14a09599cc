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

double RankDecision::gap() const {
  if (exact || largest_dropped == 0.0) return std::numeric_limits<double>::infinity();
  return smallest_kept / largest_dropped;
}

bool RankDecision::close() const {
  if (exact || largest <= 0.0) return false;
  if (gap() < kCloseRankGap) return true;
  const double nearly_singular = std::sqrt(std::numeric_limits<double>::epsilon()) * largest;
  return largest_dropped > kAboveRounding * rounding_level || (rank > 0 && smallest_kept < nearly_singular);
}

RankDecision decide_rank(const Eigen::VectorXd& singular_values, Eigen::Index rows, Eigen::Index cols,
                         const RankTolerance& tolerance) {
  RankDecision decision;
  decision.largest = singular_values.size() > 0 ? singular_values(0) : 0.0;
  decision.input_rounding = tolerance.input_rounding;
  decision.rounding_level = default_relative_tolerance(rows, cols, tolerance.input_rounding) * decision.largest;
  const double relative = tolerance.relative.value_or(default_relative_tolerance(rows, cols, tolerance.input_rounding));
  decision.threshold = relative * decision.largest;
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
