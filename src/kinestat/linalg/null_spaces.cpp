// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/null_spaces.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "kinestat/linalg/non_finite_matrix.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

// LAPACK (Fortran interface; trailing arguments are the hidden lengths of character arguments).
extern "C" void dgeqrf_(const int* m, const int* n, double* a, const int* lda, double* tau, double* work, const int* lwork,
                        int* info);
extern "C" void dormqr_(const char* side, const char* trans, const int* m, const int* n, const int* k, const double* a,
                        const int* lda, const double* tau, double* c, const int* ldc, double* work, const int* lwork, int* info,
                        std::size_t side_length, std::size_t trans_length);

namespace kinestat::linalg {

namespace {

// Probe vectors of the QR route's check.
constexpr Eigen::Index kNullSpaceProbes = 4;

// A = Q R in place (dgeqrf): R in the upper triangle, the reflectors below it, their factors in `tau`.
bool lapack_householder_qr(Eigen::MatrixXd& qr, Eigen::VectorXd& tau) {
  int m = static_cast<int>(qr.rows()), n = static_cast<int>(qr.cols()), lda = std::max(1, m), info = 0, lwork = -1;
  tau.resize(std::min(m, n));
  double query = 0.0;
  dgeqrf_(&m, &n, qr.data(), &lda, tau.data(), &query, &lwork, &info);
  if (info != 0) return false;
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(static_cast<std::size_t>(lwork));
  dgeqrf_(&m, &n, qr.data(), &lda, tau.data(), work.data(), &lwork, &info);
  return info == 0;
}

// Q's last m − n columns: Q applied to [0; I] (dormqr), orthonormal up to rounding.
bool lapack_trailing_q(const Eigen::MatrixXd& qr, const Eigen::VectorXd& tau, Eigen::MatrixXd& trailing) {
  int m = static_cast<int>(qr.rows()), n = static_cast<int>(qr.cols()), k = static_cast<int>(tau.size());
  int columns = m - n, lda = std::max(1, m), ldc = std::max(1, m), info = 0, lwork = -1;
  trailing = Eigen::MatrixXd::Zero(m, columns);
  trailing.bottomRows(columns).setIdentity();
  const char side = 'L', trans = 'N';
  double query = 0.0;
  dormqr_(&side, &trans, &m, &columns, &k, qr.data(), &lda, tau.data(), trailing.data(), &ldc, &query, &lwork, &info, 1, 1);
  if (info != 0) return false;
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(static_cast<std::size_t>(lwork));
  dormqr_(&side, &trans, &m, &columns, &k, qr.data(), &lda, tau.data(), trailing.data(), &ldc, work.data(), &lwork, &info, 1, 1);
  return info == 0;
}

// The left null basis `left` on probe vectors: aᵀ (left x) vanishes relative to |a| |x|, and
// leftᵀ left y = y (the same tolerances as the SVD's check).
bool left_null_space_check(const Eigen::MatrixXd& a, const Eigen::MatrixXd& left) {
  const Eigen::MatrixXd x = probe_vectors(left.cols(), kNullSpaceProbes);
  const double scale = std::max(1.0, a.norm());
  const double residual = (a.transpose() * (left * x)).norm() / x.norm();
  const double orthogonality = (left.transpose() * (left * x) - x).norm() / x.norm();
  const double limit = kSvdResidualTolerance * std::max<double>(1.0, static_cast<double>(a.rows()));
  return residual <= kSvdResidualTolerance * scale && orthogonality <= limit;
}

}  // namespace

NullSpaces analyse_null_spaces(const Eigen::MatrixXd& a, const RankTolerance& tolerance) {
  const Eigen::Index m = a.rows(), n = a.cols();
  if (m > n && n > 0) {
    require_finite(a);
    Eigen::MatrixXd qr = a;
    Eigen::VectorXd tau;
    if (lapack_householder_qr(qr, tau)) {
      Eigen::VectorXd s = singular_values(Eigen::MatrixXd(qr.topRows(n).triangularView<Eigen::Upper>()));
      NullSpaces result;
      result.rank = decide_rank(s, m, n, tolerance);
      if (result.rank.rank == n && lapack_trailing_q(qr, tau, result.left_null_space) &&
          left_null_space_check(a, result.left_null_space)) {
        result.singular_values = std::move(s);
        result.null_space = Eigen::MatrixXd(n, 0);
        result.from_qr = true;
        return result;
      }
    }
  }
  const SvdAnalysis svd = analyse_svd(a, tolerance);
  NullSpaces result;
  result.singular_values = svd.singular_values;
  result.rank = svd.rank;
  result.null_space = svd.null_space();
  result.left_null_space = svd.left_null_space();
  result.used_jacobi = svd.used_jacobi;
  return result;
}

}  // namespace kinestat::linalg
