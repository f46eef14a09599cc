#include "kinestat/linalg/svd_analysis.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kinestat/linalg/blas_threads.hpp"

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

// A few fixed probe vectors (deterministic pseudo-random entries in [-1, 1]).
Eigen::MatrixXd probes(Eigen::Index rows, Eigen::Index count) {
  Eigen::MatrixXd x(rows, count);
  for (Eigen::Index j = 0; j < count; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) x(i, j) = std::sin(1.0 + 0.7 * static_cast<double>(i) + 2.3 * static_cast<double>(j));
  return x;
}

// The check of the factors, on probe vectors rather than whole products so that it costs
// O((m + n) p) per probe instead of O(m n p): A X = U S Vᵀ X and UᵀU Y = Y, VᵀV Y = Y for
// kSvdProbes generic X, Y. A wrong factor (BDCSVD's failure: |A − U S Vᵀ| = 0.76) shows on
// generic probes with probability one.
bool factors_check(const Eigen::MatrixXd& a, const ThinFactors& f) {
  const double scale = std::max(1.0, a.norm());
  const auto p = f.s.size();
  const Eigen::MatrixXd x = probes(a.cols(), kSvdProbes), y = probes(p, kSvdProbes);
  const double x_norm = x.norm(), y_norm = y.norm();
  const double residual = (a * x - f.u * (f.s.asDiagonal() * (f.v.transpose() * x))).norm() / x_norm;
  const double u_orthogonality = (f.u.transpose() * (f.u * y) - y).norm() / y_norm;
  const double v_orthogonality = (f.v.transpose() * (f.v * y) - y).norm() / y_norm;
  return residual <= kSvdResidualTolerance * scale && u_orthogonality <= kSvdResidualTolerance * std::max<double>(1.0, static_cast<double>(p)) &&
         v_orthogonality <= kSvdResidualTolerance * std::max<double>(1.0, static_cast<double>(p));
}

// Thin SVD by LAPACK's divide and conquer (dgesdd, from the optimised LAPACK kinestat links:
// OpenBLAS); false when LAPACK reports a failure.
bool lapack_thin_svd(const Eigen::MatrixXd& a, ThinFactors& f) {
  int m = static_cast<int>(a.rows()), n = static_cast<int>(a.cols());
  const int p = std::min(m, n);
  Eigen::MatrixXd work_a = a;
  f.s.resize(p);
  f.u.resize(m, p);
  Eigen::MatrixXd vt(p, n);
  int lda = std::max(1, m), ldu = std::max(1, m), ldvt = std::max(1, p), info = 0, lwork = -1;
  std::vector<int> iwork(static_cast<std::size_t>(8 * p));
  double query = 0.0;
  const char jobz = 'S';
  dgesdd_(&jobz, &m, &n, work_a.data(), &lda, f.s.data(), f.u.data(), &ldu, vt.data(), &ldvt, &query, &lwork, iwork.data(), &info, 1);
  if (info != 0) return false;
  lwork = static_cast<int>(query);
  std::vector<double> work(static_cast<std::size_t>(std::max(1, lwork)));
  dgesdd_(&jobz, &m, &n, work_a.data(), &lda, f.s.data(), f.u.data(), &ldu, vt.data(), &ldvt, work.data(), &lwork, iwork.data(), &info, 1);
  if (info != 0) return false;
  f.v = vt.transpose();
  return true;
}

ThinFactors thin_svd(const Eigen::MatrixXd& a) {
  pin_blas_threads();
  ThinFactors f;
  if (lapack_thin_svd(a, f) && factors_check(a, f)) return f;
  Eigen::JacobiSVD<Eigen::MatrixXd, Eigen::ColPivHouseholderQRPreconditioner> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto p = std::min(a.rows(), a.cols());
  f.u = svd.matrixU().leftCols(p);
  f.v = svd.matrixV().leftCols(p);
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

SvdAnalysis analyse_svd(const Eigen::MatrixXd& a, const RankTolerance& tolerance, SvdVectors vectors) {
  SvdAnalysis result;
  if (a.rows() == 0 || a.cols() == 0) {
    if (vectors == SvdVectors::both) result.u = Eigen::MatrixXd::Identity(a.rows(), a.rows());
    result.v = Eigen::MatrixXd::Identity(a.cols(), a.cols());
    return result;
  }
  ThinFactors f = thin_svd(a);
  result.singular_values = f.s;
  result.used_jacobi = f.used_jacobi;
  result.rank = decide_rank(result.singular_values, a.rows(), a.cols(), tolerance);
  result.v = completed_basis(f.v);
  if (vectors == SvdVectors::both) result.u = completed_basis(f.u);
  return result;
}

Eigen::VectorXd singular_values(const Eigen::MatrixXd& a) {
  if (a.rows() == 0 || a.cols() == 0) return {};
  return thin_svd(a).s;
}

RankDecision numerical_rank(const Eigen::MatrixXd& a, const RankTolerance& tolerance) {
  if (a.rows() == 0 || a.cols() == 0) return {};
  return decide_rank(singular_values(a), a.rows(), a.cols(), tolerance);
}

}  // namespace kinestat::linalg
