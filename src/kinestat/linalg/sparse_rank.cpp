// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/sparse_rank.hpp"

#include "kinestat/linalg/nested_dissection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

namespace kinestat::linalg {

namespace {

// Lanczos steps for σ_max: at most as many as the power iteration it replaces took (60); it
// stops once the largest Ritz value of aᵀa changes by less than kSigmaMaxSettled of itself
// between two steps. Not a rank tolerance: the rank threshold is a multiple of σ_max and its
// decision's margin is orders of magnitude (the status is 'close' within 100×), so a few digits
// of σ_max suffice. The 60-step power iteration was low by 1e-4 relative on a ladder network of
// 10⁴ couplings; Lanczos stops after 24-28 steps on the networks of 10⁵ couplings of
// bench/network_bench.cpp.
constexpr int kLanczosMaxSteps = 60;
constexpr double kSigmaMaxSettled = 1e-6;

// The grouped order (grouped_nested_dissection_order) is used when the group graph keeps at
// least this share of the column couplings; below it the fill it adds costs more than METIS on
// the columns saves. Measured on lattices (bench/README.md, session 9): a planar lattice with a
// third of its bars along an axis keeps 0.75 (node order: −12 % CPU for the whole command on
// 10⁶ bars), the triangulated grid of bench/lattice_model.py 0.5 (node order: −10 % CPU, +12 %
// factor memory), the cubic lattice 0.19 (node order: +35 % CPU, +25 % factor memory).
constexpr double kGroupedOrderMinShare = 0.4;

}  // namespace

double estimate_largest_singular_value(const Eigen::SparseMatrix<double>& a) {
  if (a.rows() == 0 || a.cols() == 0) return 0.0;
  // Lanczos on aᵀa from a fixed, non-symmetric start vector (deterministic): the largest
  // eigenvalue θ of the tridiagonal T_j is a Ritz value of aᵀa, never above σ_max² (up to
  // rounding) and much closer to it after j steps than the power iteration's estimate after
  // the same j products; no reorthogonalisation (its loss of orthogonality repeats converged
  // Ritz values but does not move the largest).
  Eigen::VectorXd v(a.cols());
  for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = 1.0 + 0.5 * std::sin(static_cast<double>(i) + 1.0);
  v.normalize();
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(a.cols()), av(a.rows()), w(a.cols());
  std::vector<double> alpha, beta;
  double theta = 0.0;
  for (int step = 0; step < kLanczosMaxSteps; ++step) {
    av.noalias() = a * v;
    w.noalias() = a.transpose() * av;
    if (step > 0) w -= beta.back() * previous;
    alpha.push_back(w.dot(v));
    w -= alpha.back() * v;
    const auto j = static_cast<Eigen::Index>(alpha.size());
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(j, j);
    for (Eigen::Index i = 0; i < j; ++i) {
      t(i, i) = alpha[static_cast<std::size_t>(i)];
      if (i + 1 < j) t(i, i + 1) = t(i + 1, i) = beta[static_cast<std::size_t>(i)];
    }
    const double last = theta;
    theta = std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(t, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff());
    const double norm = w.norm();
    // Converged, or an invariant subspace of aᵀa (then θ is one of its eigenvalues, exactly).
    if ((step > 0 && std::abs(theta - last) <= kSigmaMaxSettled * theta) || norm <= kEpsilon * std::max(theta, alpha.front()))
      break;
    beta.push_back(norm);
    previous.swap(v);
    v = w / norm;
  }
  return std::sqrt(theta);
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

void record_rank(RankDecision& decision, const SparseRankCount& count) {
  decision.rank = count.rank;
  decision.smallest_kept = decision.rank > 0 ? std::min(decision.largest, count.smallest_pivot) : 0.0;
}

void record_rank(RankDecision& decision, const SparseQr& qr) {
  record_rank(decision, SparseRankCount{qr.rank(), qr.rank() > 0 ? qr.smallest_pivot() : 0.0, qr.peak_memory()});
}

void record_factor_smallest(RankDecision& decision, const SparseQr& qr) {
  decision.factor_smallest = qr.smallest_singular_estimate();
  decision.factor_estimated = decision.rank > 0;
}

RankDecision sparse_numerical_rank(const Eigen::SparseMatrix<double>& a, const RankTolerance& tolerance,
                                   std::size_t* peak_memory, const std::vector<Eigen::Index>& column_groups,
                                   MemoryLimit memory_limit) {
  if (a.rows() == 0 || a.cols() == 0) return sparse_rank_threshold(a, tolerance);
  // SPQR is fastest on tall matrices; rank(A) = rank(Aᵀ).
  const bool tall = a.rows() >= a.cols();
  const bool grouped = tall && !column_groups.empty();
  // One thread: σ_max's Lanczos beside the order saved 2 % of a 10⁶-bar lattice (bench/README.md,
  // session 18), too little for a thread of the library's own (issue 36).
  const std::vector<Eigen::Index> order =
      grouped ? grouped_nested_dissection_order(a, column_groups, kGroupedOrderMinShare) : std::vector<Eigen::Index>{};
  RankDecision decision = sparse_rank_threshold(a, tolerance);
  // Counts only: R is not needed beyond its pivots (sparse_qr_rank).
  const SparseRankCount count =
      tall ? sparse_qr_rank(a, decision.threshold, order, memory_limit)
           : sparse_qr_rank(Eigen::SparseMatrix<double>(a.transpose()), decision.threshold, {}, memory_limit);
  record_rank(decision, count);
  if (peak_memory != nullptr) *peak_memory = count.peak_memory;
  return decision;
}

}  // namespace kinestat::linalg
