// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/svd_analysis.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "kinestat/linalg/non_finite_matrix.hpp"

// LAPACK (Fortran interface; the trailing argument is the hidden length of `jobz`).
extern "C" void dgesdd_(const char* jobz, const int* m, const int* n, double* a, const int* lda, double* s, double* u,
                        const int* ldu, double* vt, const int* ldvt, double* work, const int* lwork, int* iwork, int* info,
                        std::size_t jobz_length);

namespace kinestat::linalg {

namespace {

// Probe vectors of the SVD check.
constexpr Eigen::Index kSvdProbes = 4;

struct ThinFactors {
  Eigen::MatrixXd u, v;
  Eigen::VectorXd s;
  bool used_jacobi = false;
};

// The check of the factors, on probe vectors rather than whole products so that it costs
// O((m + n) p) per probe instead of O(m n p): A X = U S Vᵀ X and UᵀU Y = Y, VᵀV Y = Y for
// kSvdProbes generic X, Y. A wrong factor (BDCSVD's failure: |A − U S Vᵀ| = 0.76) shows on
// generic probes with probability one.
bool factors_check(const Eigen::MatrixXd& a, const ThinFactors& f) {
  const double scale = std::max(1.0, a.norm());
  const auto p = f.s.size();
  const Eigen::MatrixXd x = probe_vectors(a.cols(), kSvdProbes);
  const double residual =
      (a * x - f.u.leftCols(p) * (f.s.asDiagonal() * (f.v.leftCols(p).transpose() * x))).norm() / x.norm();
  auto orthogonality = [](const Eigen::MatrixXd& q) {
    const Eigen::MatrixXd y = probe_vectors(q.cols(), kSvdProbes);
    return (q.transpose() * (q * y) - y).norm() / y.norm();
  };
  const double limit = kSvdResidualTolerance * std::max<double>(1.0, static_cast<double>(std::max(f.u.cols(), f.v.cols())));
  return residual <= kSvdResidualTolerance * scale && orthogonality(f.u) <= limit && orthogonality(f.v) <= limit;
}

// SVD by LAPACK's divide and conquer (dgesdd, from the optimised LAPACK kinestat links:
// OpenBLAS): thin (jobz 'S') or with U and V completed to full orthonormal bases (jobz 'A');
// false when LAPACK reports a failure.
bool lapack_svd(const Eigen::MatrixXd& a, bool full, ThinFactors& f) {
  int m = static_cast<int>(a.rows()), n = static_cast<int>(a.cols());
  const int p = std::min(m, n);
  const int u_cols = full ? m : p, vt_rows = full ? n : p;
  Eigen::MatrixXd work_a = a;
  f.s.resize(p);
  f.u.resize(m, u_cols);
  Eigen::MatrixXd vt(vt_rows, n);
  int lda = std::max(1, m), ldu = std::max(1, m), ldvt = std::max(1, vt_rows), info = 0, lwork = -1;
  std::vector<int> iwork(static_cast<std::size_t>(8 * p));
  double query = 0.0;
  const char jobz = full ? 'A' : 'S';
  dgesdd_(&jobz, &m, &n, work_a.data(), &lda, f.s.data(), f.u.data(), &ldu, vt.data(), &ldvt, &query, &lwork, iwork.data(), &info, 1);
  if (info != 0) return false;
  lwork = static_cast<int>(query);
  std::vector<double> work(static_cast<std::size_t>(std::max(1, lwork)));
  dgesdd_(&jobz, &m, &n, work_a.data(), &lda, f.s.data(), f.u.data(), &ldu, vt.data(), &ldvt, work.data(), &lwork, iwork.data(), &info, 1);
  if (info != 0) return false;
  f.v = vt.transpose();
  return true;
}

// Singular values alone (dgesdd, jobz 'N'): LAPACK then finds them by QR iteration on the
// bidiagonal form (dlasdq), not by divide and conquer, whose wrong vectors the probe check
// guards against. Checked by decreasing order and the Frobenius identity Σσ² = ‖A‖²_F; false
// when LAPACK fails or the check does.
bool lapack_singular_values(const Eigen::MatrixXd& a, Eigen::VectorXd& s) {
  int m = static_cast<int>(a.rows()), n = static_cast<int>(a.cols()), lda = std::max(1, m), one = 1, info = 0, lwork = -1;
  const int p = std::min(m, n);
  Eigen::MatrixXd work_a = a;
  s.resize(p);
  std::vector<int> iwork(static_cast<std::size_t>(8 * std::max(1, p)));
  double query = 0.0, unused = 0.0;
  const char jobz = 'N';
  dgesdd_(&jobz, &m, &n, work_a.data(), &lda, s.data(), &unused, &one, &unused, &one, &query, &lwork, iwork.data(), &info, 1);
  if (info != 0) return false;
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(static_cast<std::size_t>(lwork));
  dgesdd_(&jobz, &m, &n, work_a.data(), &lda, s.data(), &unused, &one, &unused, &one, work.data(), &lwork, iwork.data(), &info, 1);
  if (info != 0 || !s.allFinite()) return false;
  for (Eigen::Index i = 0; i < p; ++i)
    if (s(i) < 0.0 || (i > 0 && s(i) > s(i - 1))) return false;
  const double frobenius = a.squaredNorm();
  return std::abs(s.squaredNorm() - frobenius) <= kSvdResidualTolerance * std::max(1.0, frobenius);
}

// Checked SVD: LAPACK first, the one-sided Jacobi SVD when LAPACK fails or its factors fail the
// check. `full`: U and V completed to square orthonormal matrices.
ThinFactors checked_svd(const Eigen::MatrixXd& a, bool full) {
  require_finite(a);
  ThinFactors f;
  if (lapack_svd(a, full, f) && factors_check(a, f)) return f;
  Eigen::JacobiSVD<Eigen::MatrixXd, Eigen::ColPivHouseholderQRPreconditioner> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto p = std::min(a.rows(), a.cols());
  f.u = full ? Eigen::MatrixXd(svd.matrixU()) : Eigen::MatrixXd(svd.matrixU().leftCols(p));
  f.v = full ? Eigen::MatrixXd(svd.matrixV()) : Eigen::MatrixXd(svd.matrixV().leftCols(p));
  f.s = svd.singularValues();
  f.used_jacobi = true;
  return f;
}

// [q, orthonormal complement of q]: q has orthonormal columns.
Eigen::MatrixXd completed_basis(const Eigen::MatrixXd& q) {
  const auto n = q.rows(), p = q.cols();
  Eigen::MatrixXd full(n, n);
  full.leftCols(p) = q;
  if (p < n) {
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(q);
    const Eigen::MatrixXd householder = qr.householderQ();
    full.rightCols(n - p) = householder.rightCols(n - p);
  }
  return full;
}

}  // namespace

Eigen::MatrixXd probe_vectors(Eigen::Index rows, Eigen::Index count) {
  Eigen::MatrixXd x(rows, count);
  for (Eigen::Index j = 0; j < count; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) x(i, j) = std::sin(1.0 + 0.7 * static_cast<double>(i) + 2.3 * static_cast<double>(j));
  return x;
}

SvdAnalysis analyse_svd(const Eigen::MatrixXd& a, const RankTolerance& tolerance, SvdVectors vectors) {
  SvdAnalysis result;
  if (a.rows() == 0 || a.cols() == 0) {
    if (vectors == SvdVectors::both) result.u = Eigen::MatrixXd::Identity(a.rows(), a.rows());
    result.v = Eigen::MatrixXd::Identity(a.cols(), a.cols());
    return result;
  }
  // Full V always (the null space is its last columns); full U only when asked for.
  ThinFactors f = checked_svd(a, vectors == SvdVectors::both);
  result.singular_values = f.s;
  result.used_jacobi = f.used_jacobi;
  result.rank = decide_rank(result.singular_values, a.rows(), a.cols(), tolerance);
  if (vectors == SvdVectors::both) {
    result.u = std::move(f.u);
    result.v = std::move(f.v);
  } else {
    result.v = completed_basis(f.v);
  }
  return result;
}

Eigen::VectorXd singular_values(const Eigen::MatrixXd& a) {
  if (a.rows() == 0 || a.cols() == 0) return {};
  require_finite(a);
  Eigen::VectorXd s;
  if (lapack_singular_values(a, s)) return s;
  return checked_svd(a, false).s;
}

RankDecision numerical_rank(const Eigen::MatrixXd& a, const RankTolerance& tolerance) {
  if (a.rows() == 0 || a.cols() == 0) return {};
  return decide_rank(singular_values(a), a.rows(), a.cols(), tolerance);
}

}  // namespace kinestat::linalg
