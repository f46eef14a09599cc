#include "kinestat/linalg/svd_analysis.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>

namespace kinestat::linalg {

namespace {

struct ThinFactors {
  Eigen::MatrixXd u, v;
  Eigen::VectorXd s;
  bool used_jacobi = false;
};

bool factors_check(const Eigen::MatrixXd& a, const ThinFactors& f) {
  const double scale = std::max(1.0, a.norm());
  const auto p = f.s.size();
  const double residual = (a - f.u * f.s.asDiagonal() * f.v.transpose()).norm();
  const double u_orthogonality = (f.u.transpose() * f.u - Eigen::MatrixXd::Identity(p, p)).norm();
  const double v_orthogonality = (f.v.transpose() * f.v - Eigen::MatrixXd::Identity(p, p)).norm();
  return residual <= kSvdResidualTolerance * scale && u_orthogonality <= kSvdResidualTolerance * std::max<double>(1.0, static_cast<double>(p)) &&
         v_orthogonality <= kSvdResidualTolerance * std::max<double>(1.0, static_cast<double>(p));
}

ThinFactors thin_svd(const Eigen::MatrixXd& a) {
  ThinFactors f;
  {
    Eigen::BDCSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
    f.u = svd.matrixU();
    f.v = svd.matrixV();
    f.s = svd.singularValues();
  }
  if (factors_check(a, f)) return f;
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
