// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/distributed/interior_reduction.hpp"

#include <SuiteSparseQR.hpp>

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinestat/linalg/cholmod_view.hpp"
#include "kinestat/linalg/sparse_qr.hpp"

namespace kinestat::distributed {

namespace {

// SuiteSparseQR's [C, E] = qr(A, B) without R (its expert interface with R not asked for), and
// what it allocated, released on every path. R, assembled from the fronts in two copies, was
// half of a process's factor memory (a 268,801-bar lattice at P = 2: 168 MB with R, 92 MB
// without; docs/scaling.md), and only its pivots were read: they come from a counts-only
// factorisation instead (reduce_interior).
class QrWithRightHandSide {
 public:
  QrWithRightHandSide(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b, double threshold)
      : a_(a), b_(b) {
    cholmod_l_start(&cc_);
    cc_.print = 0;  // failures reach the caller as exceptions
    cholmod_sparse a_view = linalg::cholmod_view(a_), b_view = linalg::cholmod_view(b_);
    // econ = m: every row of C = QᵀB, those beyond the rank included; getCTX 0: C itself.
    rank_ = SuiteSparseQR<double>(SPQR_ORDERING_METIS, threshold, static_cast<SuiteSparse_long>(a.rows()), 0, &a_view, &b_view,
                                  nullptr, &c_, nullptr, nullptr, &e_, nullptr, nullptr, nullptr, &cc_);
    if (rank_ >= 0 && cc_.status >= CHOLMOD_OK && c_ != nullptr) return;
    const int status = cc_.status;
    release();
    if (status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    throw std::runtime_error("SuiteSparseQR failed on a process's interior (status " + std::to_string(status) + ")");
  }
  ~QrWithRightHandSide() { release(); }
  QrWithRightHandSide(const QrWithRightHandSide&) = delete;
  QrWithRightHandSide& operator=(const QrWithRightHandSide&) = delete;

  Eigen::Index rank() const { return static_cast<Eigen::Index>(rank_); }
  std::size_t peak_memory() const { return cc_.memory_usage; }

  // Rows rank … m − 1 of C = QᵀB: B's part outside range(A), in an orthonormal basis of it.
  Eigen::SparseMatrix<double> rows_beyond_rank() const {
    std::vector<Eigen::Triplet<double>> entries;
    const auto* p = static_cast<const SuiteSparse_long*>(c_->p);
    const auto* i = static_cast<const SuiteSparse_long*>(c_->i);
    const auto* x = static_cast<const double*>(c_->x);
    for (SuiteSparse_long j = 0; j < static_cast<SuiteSparse_long>(c_->ncol); ++j)
      for (SuiteSparse_long k = p[j]; k < p[j + 1]; ++k)
        if (i[k] >= rank_ && x[k] != 0.0)
          entries.emplace_back(static_cast<Eigen::Index>(i[k] - rank_), static_cast<Eigen::Index>(j), x[k]);
    Eigen::SparseMatrix<double> tail(static_cast<Eigen::Index>(c_->nrow) - rank(), static_cast<Eigen::Index>(c_->ncol));
    tail.setFromTriplets(entries.begin(), entries.end());
    return tail;
  }

 private:
  void release() {
    if (c_ != nullptr) cholmod_l_free_sparse(&c_, &cc_);
    if (e_ != nullptr) cholmod_l_free(a_.cols(), sizeof(SuiteSparse_long), e_, &cc_);
    e_ = nullptr;
    if (started_) cholmod_l_finish(&cc_);
    started_ = false;
  }
  linalg::CholmodMatrix a_, b_;  // 64-bit index copies, as SuiteSparseQR's long interface needs
  cholmod_common cc_{};
  cholmod_sparse* c_ = nullptr;
  SuiteSparse_long* e_ = nullptr;
  SuiteSparse_long rank_ = -1;
  bool started_ = true;
};

// The compressed block: R of a second rank-revealing QR of `tail` at the same threshold, its
// columns back in tail's order (RᵀR = Pᵀ tailᵀ tail P up to the dropped remainders).
Eigen::SparseMatrix<double> compress(const Eigen::SparseMatrix<double>& tail, double threshold, std::size_t& peak_memory) {
  if (tail.nonZeros() == 0) return Eigen::SparseMatrix<double>(0, tail.cols());
  const linalg::SparseQr qr(tail, threshold);
  peak_memory = std::max(peak_memory, qr.peak_memory());
  const linalg::SparseFactorView r = qr.r();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(r.nonZeros()));
  for (Eigen::Index k = 0; k < r.outerSize(); ++k)
    for (linalg::SparseFactorView::InnerIterator it(r, k); it; ++it)
      entries.emplace_back(static_cast<Eigen::Index>(it.row()), qr.permutation()[static_cast<std::size_t>(k)], it.value());
  Eigen::SparseMatrix<double> block(qr.rank(), tail.cols());
  block.setFromTriplets(entries.begin(), entries.end());
  return block;
}

}  // namespace

InteriorReduction reduce_interior(const Eigen::SparseMatrix<double>& interior, const Eigen::SparseMatrix<double>& interface,
                                  double threshold) {
  InteriorReduction out;
  if (interior.rows() == 0) {
    out.interface_block = Eigen::SparseMatrix<double>(0, interface.cols());
    return out;
  }
  if (interface.cols() == 0) {  // nothing to carry along: the counts-only factorisation
    const linalg::SparseRankCount count = linalg::sparse_qr_rank(interior, threshold);
    out.rank = count.rank;
    out.smallest_kept = count.smallest_pivot;
    out.peak_memory = count.peak_memory;
    out.interface_block = Eigen::SparseMatrix<double>(0, 0);
    return out;
  }
  // The rank and its evidence (the smallest kept pivot) from the counts-only factorisation,
  // which keeps no R; then QᵀA_Γ from a second factorisation of the same A_I in the same METIS
  // order at the same threshold (B's columns come after A's in every front, so A's pivots are
  // the same operations): both must find the same rank.
  const linalg::SparseRankCount count = linalg::sparse_qr_rank(interior, threshold);
  out.rank = count.rank;
  out.smallest_kept = count.smallest_pivot;
  Eigen::SparseMatrix<double> tail;
  {
    const QrWithRightHandSide qr(interior, interface, threshold);
    if (qr.rank() != count.rank)
      throw std::runtime_error("SuiteSparseQR's two factorisations of a process's interior found ranks " +
                               std::to_string(count.rank) + " and " + std::to_string(qr.rank()));
    out.peak_memory = std::max(count.peak_memory, qr.peak_memory());
    Eigen::SparseMatrix<double> rows = qr.rows_beyond_rank();
    tail.swap(rows);  // no copy (Eigen's SparseMatrix has no move assignment)
  }  // the interior's factor is released before the second QR
  out.interface_block = compress(tail, threshold, out.peak_memory);
  return out;
}

}  // namespace kinestat::distributed
