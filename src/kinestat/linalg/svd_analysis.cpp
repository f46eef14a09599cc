#include "kinestat/linalg/svd_analysis.hpp"

#include <Eigen/SVD>

namespace kinestat::linalg {

SvdAnalysis analyse_svd(const Eigen::MatrixXd& a, const RankTolerance& tolerance) {
  SvdAnalysis result;
  if (a.rows() == 0 || a.cols() == 0) {
    result.u = Eigen::MatrixXd::Identity(a.rows(), a.rows());
    result.v = Eigen::MatrixXd::Identity(a.cols(), a.cols());
    return result;
  }
  Eigen::BDCSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  result.u = svd.matrixU();
  result.v = svd.matrixV();
  result.singular_values = svd.singularValues();
  result.rank = decide_rank(result.singular_values, a.rows(), a.cols(), tolerance);
  return result;
}

RankDecision numerical_rank(const Eigen::MatrixXd& a, const RankTolerance& tolerance) {
  if (a.rows() == 0 || a.cols() == 0) return {};
  Eigen::BDCSVD<Eigen::MatrixXd> svd(a);
  return decide_rank(svd.singularValues(), a.rows(), a.cols(), tolerance);
}

}  // namespace kinestat::linalg
