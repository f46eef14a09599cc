#include "kinestat/linalg/sparse_rank.hpp"

#include <Eigen/SPQRSupport>

#include <algorithm>
#include <cmath>

namespace kinestat::linalg {

double estimate_largest_singular_value(const Eigen::SparseMatrix<double>& a) {
  if (a.rows() == 0 || a.cols() == 0) return 0.0;
  // A fixed, non-symmetric start vector keeps the estimate deterministic.
  Eigen::VectorXd v(a.cols());
  for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = 1.0 + 0.5 * std::sin(static_cast<double>(i) + 1.0);
  v.normalize();
  double sigma = 0.0;
  for (int step = 0; step < 60; ++step) {
    Eigen::VectorXd w = a.transpose() * (a * v);
    const double norm = w.norm();
    if (norm == 0.0) return 0.0;
    sigma = std::sqrt(norm);
    v = w / norm;
  }
  return sigma;
}

RankDecision sparse_numerical_rank(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance) {
  RankDecision decision;
  if (a.rows() == 0 || a.cols() == 0) return decision;
  decision.largest = estimate_largest_singular_value(a);
  decision.threshold = tolerance.relative.value_or(default_relative_tolerance(a.rows(), a.cols())) * decision.largest;
  // SPQR is fastest on tall matrices; rank(A) = rank(Aᵀ).
  Eigen::SparseMatrix<double> tall = a.rows() >= a.cols() ? a : Eigen::SparseMatrix<double>(a.transpose());
  tall.makeCompressed();
  Eigen::SPQR<Eigen::SparseMatrix<double>> qr;
  qr.setPivotThreshold(decision.threshold);
  qr.compute(tall);
  decision.rank = qr.rank();
  double smallest = decision.largest;
  const auto& r = qr.matrixR();
  for (Eigen::Index i = 0; i < decision.rank && i < r.rows() && i < r.cols(); ++i)
    smallest = std::min(smallest, std::abs(r.coeff(i, i)));
  decision.smallest_kept = decision.rank > 0 ? smallest : 0.0;
  return decision;
}

}  // namespace kinestat::linalg
