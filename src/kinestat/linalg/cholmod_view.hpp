// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CHOLMOD's description of an Eigen compressed-column matrix with 64-bit indices, without a copy:
// how SuiteSparseQR and CHOLMOD are handed a matrix. Internal (not installed): it includes
// SuiteSparse's headers, a private dependency.

#include <Eigen/SparseCore>
#include <cholmod.h>

#include <cstddef>

namespace kinestat::linalg {

/// Compressed-column real matrix with SuiteSparse's 64-bit indices.
using CholmodMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;

/// An unsymmetric, sorted, packed view of `a` (compressed first); valid while `a` lives unchanged.
inline cholmod_sparse cholmod_view(CholmodMatrix& a) {
  a.makeCompressed();
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(a.rows());
  view.ncol = static_cast<std::size_t>(a.cols());
  view.nzmax = static_cast<std::size_t>(a.nonZeros());
  view.p = a.outerIndexPtr();
  view.i = a.innerIndexPtr();
  view.x = a.valuePtr();
  view.stype = 0;
  view.itype = CHOLMOD_LONG;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

}  // namespace kinestat::linalg
