#include "kinestat/linalg/sparse_rank.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinestat::linalg {

double estimate_largest_singular_value(const Eigen::SparseMatrix<double>& a) {
  if (a.rows() == 0 || a.cols() == 0) return 0.0;
  // A fixed, non-symmetric start vector keeps the estimate deterministic.
  Eigen::VectorXd v(a.cols());
  for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = 1.0 + 0.5 * std::sin(static_cast<double>(i) + 1.0);
  v.normalize();
  double sigma = 0.0;
  Eigen::VectorXd av(a.rows()), w(a.cols());
  for (int step = 0; step < 60; ++step) {
    av.noalias() = a * v;
    w.noalias() = a.transpose() * av;
    const double norm = w.norm();
    if (norm == 0.0) return 0.0;
    sigma = std::sqrt(norm);
    v = w / norm;
  }
  return sigma;
}

RankDecision sparse_rank_threshold(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance) {
  RankDecision decision;
  decision.rows = a.rows();
  decision.cols = a.cols();
  decision.sparse = true;
  if (a.rows() == 0 || a.cols() == 0) return decision;
  decision.largest = estimate_largest_singular_value(a);
  decision.input_rounding = tolerance.input_rounding;
  decision.rounding_level = default_relative_tolerance(a.rows(), a.cols(), tolerance.input_rounding) * decision.largest;
  decision.threshold = tolerance.relative.value_or(kSparseToleranceFactor * static_cast<double>(a.rows() + a.cols()) *
                                                   std::max(kEpsilon, kInputRoundingFactor * tolerance.input_rounding)) *
                       decision.largest;
  return decision;
}

void record_rank(RankDecision& decision, const SparseQr& qr) {
  decision.rank = qr.rank();
  decision.smallest_kept = decision.rank > 0 ? std::min(decision.largest, qr.smallest_pivot()) : 0.0;
}

RankDecision sparse_numerical_rank(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance,
                                   std::size_t* peak_memory) {
  RankDecision decision = sparse_rank_threshold(a, tolerance);
  if (a.rows() == 0 || a.cols() == 0) return decision;
  // SPQR is fastest on tall matrices; rank(A) = rank(Aᵀ).
  const SparseQr qr = a.rows() >= a.cols() ? SparseQr(a, decision.threshold)
                                           : SparseQr(Eigen::SparseMatrix<double>(a.transpose()), decision.threshold);
  record_rank(decision, qr);
  if (peak_memory != nullptr) *peak_memory = qr.peak_memory();
  return decision;
}

}  // namespace kinestat::linalg
