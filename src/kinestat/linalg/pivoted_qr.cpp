// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/pivoted_qr.hpp"

#include <Eigen/Householder>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "kinestat/linalg/blas_kernels.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::linalg {

namespace {

// Columns per panel of the blocked factorisation: the reflectors of a panel reach the trailing
// columns in one matrix product instead of one rank-1 update per column.
constexpr Eigen::Index kPivotPanel = 32;

}  // namespace

// LAPACK's dgeqp3/dlaqps scheme with kinestat's pivot rule. Within a panel the trailing columns
// are not updated; A − V Fᵀ is their current value, with V the panel's reflectors (stored below
// the diagonal) and F = (A − V_prev F_prevᵀ)ᵀ V T built one column per step. Each step brings its
// pivot column and its row of R up to date, which is all the pivot choice and the norm
// downdates need. A norm that has cancelled too far ends the panel, so that it is recomputed
// from its updated column before the next choice, as the unblocked factorisation does. Kept
// whole (over 80 lines): one algorithm, LAPACK's, whose steps share all of its state (R, F, the
// norms and the order), to be read beside dlaqps.
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
  const Eigen::Index steps = std::min(m, n);
  Eigen::MatrixXd f(n, std::min(kPivotPanel, steps));
  Eigen::VectorXd earlier(f.cols());
  std::vector<Eigen::Index> stale;
  Eigen::Index k = 0;
  bool exhausted = false;
  while (k < steps && !exhausted) {
    const Eigen::Index first = k, panel = std::min(kPivotPanel, steps - first);
    f.bottomRows(n - first).leftCols(panel).setZero();
    Eigen::Index done = 0;
    while (done < panel && stale.empty()) {
      const double largest = norms.segment(k, n - k).maxCoeff();
      if (largest == 0.0) {  // the rest is zero: the order of the rest is their original order
        exhausted = true;
        break;
      }
      Eigen::Index pivot = -1;
      for (Eigen::Index j = k; j < n; ++j)
        if (norms(j) >= (1.0 - kPivotTie) * largest &&
            (pivot < 0 || order[static_cast<std::size_t>(j)] < order[static_cast<std::size_t>(pivot)]))
          pivot = j;
      if (pivot != k) {
        r.col(k).swap(r.col(pivot));
        f.row(k).swap(f.row(pivot));
        std::swap(norms(k), norms(pivot));
        std::swap(trusted(k), trusted(pivot));
        std::swap(order[static_cast<std::size_t>(k)], order[static_cast<std::size_t>(pivot)]);
      }
      const Eigen::Index rows = m - k, right = n - k - 1;
      // The pivot column with the panel's earlier reflections applied.
      if (done > 0) r.col(k).tail(rows).noalias() -= r.block(k, first, rows, done) * f.row(k).head(done).transpose();
      double tau = 0.0, beta = 0.0;
      r.col(k).tail(rows).makeHouseholderInPlace(tau, beta);
      r(k, k) = 1.0;  // the reflector v, with its implicit leading 1, for the products below
      if (right > 0) {
        // F's new column: τ (A − V Fᵀ)ᵀ v = τ Aᵀ v − τ F (Vᵀ v).
        blas_transposed_vector_product(tau, &r(k, k + 1), rows, right, m, &r(k, k), &f(k + 1, done));
        if (done > 0) {
          earlier.head(done).noalias() = -tau * (r.block(k, first, rows, done).transpose() * r.col(k).tail(rows));
          f.col(done).tail(right).noalias() += f.block(k + 1, 0, right, done) * earlier.head(done);
        }
        // Row k of R: A(k, ·) − V(k, ·) Fᵀ over the panel so far, this reflector included.
        r.row(k).tail(right).noalias() -= r.row(k).segment(first, done + 1) * f.block(k + 1, 0, right, done + 1).transpose();
      }
      r(k, k) = beta;
      for (Eigen::Index j = k + 1; j < n; ++j) {
        if (norms(j) == 0.0) continue;
        const double ratio = std::abs(r(k, j)) / norms(j);
        const double kept = std::max(0.0, (1.0 + ratio) * (1.0 - ratio));
        const double share = kept * (norms(j) / trusted(j)) * (norms(j) / trusted(j));
        if (share <= recompute_below)
          stale.push_back(j);  // recomputed from the updated column once the panel is applied
        else
          norms(j) *= std::sqrt(kept);
      }
      ++done;
      ++k;
    }
    // The panel's reflections reach the rest of the matrix in one product.
    if (done > 0 && k < n && k < m)
      blas_subtract_product_transposed(&r(k, first), m, &f(k, 0), n, &r(k, k), m, m - k, n - k, done);
    for (Eigen::Index j : stale) {
      norms(j) = k < m ? r.col(j).tail(m - k).norm() : 0.0;
      trusted(j) = norms(j);
    }
    stale.clear();
  }
  // Columns not taken (after a zero remainder, or beyond min(m, n)) in their original order.
  std::sort(order.begin() + k, order.end());
  return order;
}

}  // namespace kinestat::linalg
