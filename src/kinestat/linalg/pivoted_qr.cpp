#include "kinestat/linalg/pivoted_qr.hpp"

#include <Eigen/Householder>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

std::vector<Eigen::Index> pivoted_column_order(const Eigen::MatrixXd& a) {
  const Eigen::Index m = a.rows(), n = a.cols();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  if (m == 0 || n == 0) return order;
  Eigen::MatrixXd r = a;
  // Remaining norms, downdated after each reflection as LAPACK's dgeqp3 does, and recomputed
  // when the downdate has cancelled too much to be trusted (the norm at the last recompute kept
  // beside it).
  Eigen::VectorXd norms = r.colwise().norm().transpose(), trusted = norms;
  const double recompute_below = std::sqrt(kEpsilon);
  Eigen::VectorXd workspace(n);
  const Eigen::Index steps = std::min(m, n);
  Eigen::Index k = 0;
  for (; k < steps; ++k) {
    const double largest = norms.segment(k, n - k).maxCoeff();
    if (largest == 0.0) break;  // the rest is zero: the order of the rest is their original order
    Eigen::Index pivot = -1;
    for (Eigen::Index j = k; j < n; ++j)
      if (norms(j) >= (1.0 - kPivotTie) * largest &&
          (pivot < 0 || order[static_cast<std::size_t>(j)] < order[static_cast<std::size_t>(pivot)]))
        pivot = j;
    if (pivot != k) {
      r.col(k).swap(r.col(pivot));
      std::swap(norms(k), norms(pivot));
      std::swap(trusted(k), trusted(pivot));
      std::swap(order[static_cast<std::size_t>(k)], order[static_cast<std::size_t>(pivot)]);
    }
    double tau = 0.0, beta = 0.0;
    r.col(k).tail(m - k).makeHouseholderInPlace(tau, beta);
    r(k, k) = beta;
    if (k + 1 < n)
      r.bottomRightCorner(m - k, n - k - 1).applyHouseholderOnTheLeft(r.col(k).tail(m - k - 1), tau, workspace.data());
    for (Eigen::Index j = k + 1; j < n; ++j) {
      if (norms(j) == 0.0) continue;
      const double ratio = std::abs(r(k, j)) / norms(j);
      const double kept = std::max(0.0, (1.0 + ratio) * (1.0 - ratio));
      const double share = kept * (norms(j) / trusted(j)) * (norms(j) / trusted(j));
      if (share <= recompute_below) {
        norms(j) = k + 1 < m ? r.col(j).tail(m - k - 1).norm() : 0.0;
        trusted(j) = norms(j);
      } else {
        norms(j) *= std::sqrt(kept);
      }
    }
  }
  // Columns not taken (after a zero remainder, or beyond min(m, n)) in their original order.
  std::sort(order.begin() + k, order.end());
  return order;
}

}  // namespace kinestat::linalg
