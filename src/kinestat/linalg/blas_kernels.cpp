// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/blas_kernels.hpp"

#include <cstddef>
#include <vector>

// BLAS (Fortran interface; trailing arguments are the hidden lengths of character arguments).
extern "C" void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a, const int* lda,
                       const double* x, const int* incx, const double* beta, double* y, const int* incy, std::size_t trans_length);
extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
                       const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
                       const int* ldc, std::size_t transa_length, std::size_t transb_length);

extern "C" void dgesv_(const int* n, const int* nrhs, double* a, const int* lda, int* ipiv, double* b, const int* ldb,
                       int* info);

namespace kinestat::linalg {

std::optional<Eigen::MatrixXd> lapack_right_divide(const Eigen::MatrixXd& b, const Eigen::MatrixXd& a) {
  // B A⁻¹ = (A⁻ᵀ Bᵀ)ᵀ: one solve with Aᵀ and the rows of B as right-hand sides.
  Eigen::MatrixXd at = a.transpose(), x = b.transpose();
  if (x.size() == 0) return Eigen::MatrixXd(b.rows(), a.cols());
  const int n = static_cast<int>(at.rows()), rhs = static_cast<int>(x.cols());
  std::vector<int> pivots(static_cast<std::size_t>(n));
  int info = 0;
  dgesv_(&n, &rhs, at.data(), &n, pivots.data(), x.data(), &n, &info);
  if (info != 0) return std::nullopt;
  return Eigen::MatrixXd(x.transpose());
}

void blas_subtract_projection(const Eigen::MatrixXd& basis, Eigen::Index kept, Eigen::MatrixXd& block) {
  if (kept == 0 || block.size() == 0) return;
  const int rows = static_cast<int>(basis.rows()), depth = static_cast<int>(kept), cols = static_cast<int>(block.cols());
  Eigen::MatrixXd along(kept, block.cols());
  const double one = 1.0, zero = 0.0, minus_one = -1.0;
  dgemm_("T", "N", &depth, &cols, &rows, &one, basis.data(), &rows, block.data(), &rows, &zero, along.data(), &depth, 1, 1);
  dgemm_("N", "N", &rows, &cols, &depth, &minus_one, basis.data(), &rows, along.data(), &depth, &one, block.data(), &rows, 1, 1);
}

void blas_transposed_vector_product(double alpha, const double* a, Eigen::Index rows, Eigen::Index cols,
                                    Eigen::Index stride, const double* x, double* y) {
  if (cols == 0) return;
  const int m = static_cast<int>(rows), n = static_cast<int>(cols), lda = static_cast<int>(stride), one = 1;
  const double zero = 0.0;
  dgemv_("T", &m, &n, &alpha, a, &lda, x, &one, &zero, y, &one, 1);
}

void blas_subtract_product_transposed(const double* v, Eigen::Index ldv, const double* f, Eigen::Index ldf, double* c,
                                      Eigen::Index ldc, Eigen::Index rows, Eigen::Index cols, Eigen::Index depth) {
  if (rows == 0 || cols == 0 || depth == 0) return;
  const int m = static_cast<int>(rows), n = static_cast<int>(cols), k = static_cast<int>(depth);
  const int lda = static_cast<int>(ldv), ldb = static_cast<int>(ldf), ldcc = static_cast<int>(ldc);
  const double minus_one = -1.0, one = 1.0;
  dgemm_("N", "T", &m, &n, &k, &minus_one, v, &lda, f, &ldb, &one, c, &ldcc, 1, 1);
}

}  // namespace kinestat::linalg
