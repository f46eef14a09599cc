// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Matrix products and solves on the optimised BLAS/LAPACK kinestat links (Debian's OpenBLAS; its
// thread count is the process's to set: the command pins it, cli/process/process_setup.hpp).
// Eigen's own kernels are compiled for the baseline x86-64 instruction set (SSE2); OpenBLAS picks kernels for the machine it runs on, several times faster on the
// products of the dense path. Single-threaded OpenBLAS gives the same bits on every run.

#include <Eigen/Core>

#include <optional>

namespace kinestat::linalg {

/// B A⁻¹ for a square A (LAPACK dgesv: LU with partial pivoting, then triangular solves);
/// nothing when A is exactly singular. Sizes must agree (b.cols() == a.rows()).
std::optional<Eigen::MatrixXd> lapack_right_divide(const Eigen::MatrixXd& b, const Eigen::MatrixXd& a);

/// block −= B (Bᵀ block) with B the first `kept` columns of `basis` (orthonormal columns:
/// removes block's components along them; dimensionless).
void blas_subtract_projection(const Eigen::MatrixXd& basis, Eigen::Index kept, Eigen::MatrixXd& block);

/// y = α Aᵀ x for a column-major block A of `rows` × `cols` with leading dimension `stride`
/// (x has `rows` entries, y `cols`).
void blas_transposed_vector_product(double alpha, const double* a, Eigen::Index rows, Eigen::Index cols,
                                    Eigen::Index stride, const double* x, double* y);

/// C −= V Fᵀ for column-major blocks: C `rows` × `cols`, V `rows` × `depth`, F `cols` × `depth`,
/// each with its leading dimension.
void blas_subtract_product_transposed(const double* v, Eigen::Index ldv, const double* f, Eigen::Index ldf, double* c,
                                      Eigen::Index ldc, Eigen::Index rows, Eigen::Index cols, Eigen::Index depth);

}  // namespace kinestat::linalg
