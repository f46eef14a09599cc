#include "kinestat/linalg/sparse_qr.hpp"

#include "kinestat/linalg/blas_threads.hpp"

#include <SuiteSparseQR.hpp>

// SuiteSparseQR's factorisation without the conversion of R to a sparse matrix, and its release
// (exported by libspqr, declared in its internal header spqr.hpp, which defines macros of its own).
template <typename Entry>
SuiteSparseQR_factorization<Entry>* spqr_1factor(int ordering, double tol, SuiteSparse_long bncols, int keepH,
                                                 cholmod_sparse* A, SuiteSparse_long ldb, SuiteSparse_long* Bp,
                                                 SuiteSparse_long* Bi, Entry* Bx, cholmod_common* cc);
template <typename Entry>
void spqr_freefac(SuiteSparseQR_factorization<Entry>** QR_handle, cholmod_common* cc);

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>

namespace kinestat::linalg {

namespace {

// Right-hand sides solved together in one back substitution: one pass over R11 per block keeps
// R in cache-friendly column order and the work per entry vectorised.
constexpr Eigen::Index kNullVectorBlock = 32;
// Inverse iteration for σ_min(R11): on the networks of bench/README.md ("Rank evidence from the
// kept block") the third step was within 3 % of the twelfth, and on those of 10³ couplings the
// settled estimate matched a dense SVD of R11 to 3 digits; more steps help only when the two
// smallest singular values are close.
constexpr int kSigmaMinSteps = 8;
constexpr double kSigmaMinSettled = 1e-3;

// SuiteSparseQR's long-integer interface needs 64-bit indices: the one copy made is of A
// (with its columns in the given order, if any), and `view` describes it to CHOLMOD.
struct SpqrInput {
  Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long> matrix;
  cholmod_sparse view{};

  SpqrInput(const Eigen::SparseMatrix<double>& a, const std::vector<Eigen::Index>& column_order) {
    const Eigen::Index cols = a.cols();
    if (!column_order.empty()) {
      // Column k of the copy is column column_order[k] of a, copied whole into the compressed
      // arrays (the values and row indices exactly as in a).
      std::vector<bool> seen(static_cast<std::size_t>(cols), false);
      Eigen::Index entries = 0;
      for (const Eigen::Index j : column_order) {
        if (j < 0 || j >= cols || seen[static_cast<std::size_t>(j)])
          throw std::invalid_argument("SparseQr: the column order must list every column once");
        seen[static_cast<std::size_t>(j)] = true;
        entries += a.isCompressed() ? a.outerIndexPtr()[j + 1] - a.outerIndexPtr()[j] : a.innerNonZeroPtr()[j];
      }
      matrix.resize(a.rows(), cols);
      matrix.resizeNonZeros(entries);
      SuiteSparse_long* start = matrix.outerIndexPtr();
      SuiteSparse_long at = 0;
      for (Eigen::Index k = 0; k < cols; ++k) {
        start[k] = at;
        for (Eigen::SparseMatrix<double>::InnerIterator it(a, column_order[static_cast<std::size_t>(k)]); it; ++it, ++at) {
          matrix.innerIndexPtr()[at] = static_cast<SuiteSparse_long>(it.row());
          matrix.valuePtr()[at] = it.value();
        }
      }
      start[cols] = at;
    } else {
      matrix = a.cast<double>();
    }
    matrix.makeCompressed();
    view.nrow = static_cast<std::size_t>(a.rows());
    view.ncol = static_cast<std::size_t>(cols);
    view.nzmax = static_cast<std::size_t>(matrix.nonZeros());
    view.p = matrix.outerIndexPtr();
    view.i = matrix.innerIndexPtr();
    view.x = matrix.valuePtr();
    view.stype = 0;
    view.itype = CHOLMOD_LONG;
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    view.sorted = 1;
    view.packed = 1;
  }
  SpqrInput(const SpqrInput&) = delete;
  SpqrInput& operator=(const SpqrInput&) = delete;
};

// The smallest |R_kk| over the live columns of a factorisation, read where SuiteSparseQR keeps R
// before it assembles it (spqr_rconvert of SuiteSparse 5.12 reads the same layout): the column
// singletons' rows R1 (each row's singleton is live, its pivot the row's first entry: no
// earlier column reaches a later singleton's row; an empty column counts as a singleton column
// without a row, so rows and columns need not pair up by index), then each front's block,
// column by column, every column holding as many entries as the front has live pivot rows so
// far, a live pivotal column's own pivot last. Empty if the live pivots counted there disagree
// with the factorisation's rank (a layout this code does not know).
std::optional<double> smallest_live_pivot(const SuiteSparseQR_factorization<double>& qr) {
  double smallest = std::numeric_limits<double>::infinity();
  SuiteSparse_long live = 0;
  for (SuiteSparse_long row = 0; row < qr.n1rows; ++row)
    if (qr.R1p[row] < qr.R1p[row + 1]) {
      smallest = std::min(smallest, std::abs(qr.R1x[qr.R1p[row]]));
      ++live;
    }
  const spqr_symbolic* symbolic = qr.QRsym;
  const spqr_numeric<double>* numeric = qr.QRnum;
  if (symbolic != nullptr && numeric != nullptr) {
    for (SuiteSparse_long f = 0; f < symbolic->nf; ++f) {
      const double* block = numeric->Rblock[f];
      const SuiteSparse_long first = symbolic->Super[f];
      const SuiteSparse_long pivots = symbolic->Super[f + 1] - first;
      const SuiteSparse_long columns = symbolic->Rp[f + 1] - symbolic->Rp[f];
      SuiteSparse_long rows = 0;
      for (SuiteSparse_long k = 0; k < columns; ++k) {
        if (k < pivots && (numeric->Rdead == nullptr || numeric->Rdead[first + k] == 0)) {
          ++rows;
          smallest = std::min(smallest, std::abs(block[rows - 1]));
          ++live;
        }
        block += rows;
      }
    }
  }
  if (live != qr.rank) return std::nullopt;
  return smallest;
}

}  // namespace

struct SparseQr::Factor {
  cholmod_common common{};
  cholmod_sparse* r = nullptr;
  SuiteSparse_long* permutation = nullptr;
  Eigen::Index cols = 0;

  Factor() { cholmod_l_start(&common); }
  ~Factor() {
    if (r != nullptr) cholmod_l_free_sparse(&r, &common);
    if (permutation != nullptr)
      cholmod_l_free(static_cast<std::size_t>(cols), sizeof(SuiteSparse_long), permutation, &common);
    cholmod_l_finish(&common);
  }
  Factor(const Factor&) = delete;
  Factor& operator=(const Factor&) = delete;
};

SparseQr::SparseQr(const Eigen::SparseMatrix<double>& a, double threshold)
    : factor_(std::make_unique<Factor>()), rows_(a.rows()), cols_(a.cols()) {
  factor(a, threshold, {});
}

SparseQr::SparseQr(const Eigen::SparseMatrix<double>& a, double threshold, const std::vector<Eigen::Index>& column_order)
    : factor_(std::make_unique<Factor>()), rows_(a.rows()), cols_(a.cols()) {
  if (static_cast<Eigen::Index>(column_order.size()) != cols_)
    throw std::invalid_argument("SparseQr: the column order must list every column once");
  factor(a, threshold, column_order);
}

void SparseQr::factor(const Eigen::SparseMatrix<double>& a, double threshold, const std::vector<Eigen::Index>& column_order) {
  pin_blas_threads();
  factor_->cols = cols_;
  if (rows_ == 0 || cols_ == 0) {
    for (Eigen::Index j = 0; j < cols_; ++j) permutation_.push_back(j);
    return;
  }
  const bool given = !column_order.empty();
  SpqrInput input(a, column_order);
  cholmod_common& cc = factor_->common;
  // econ = 0: R has exactly rank rows. Nested dissection by METIS keeps the fill of R near
  // that of a Cholesky factor of AᵀA on lattice-like frameworks; a given order is kept
  // (SPQR_ORDERING_NATURAL: singletons first, then the columns as given, etree-postordered).
  const SuiteSparse_long rank = SuiteSparseQR<double>(given ? SPQR_ORDERING_NATURAL : SPQR_ORDERING_METIS, threshold, 0,
                                                      &input.view, &factor_->r, &factor_->permutation, &cc);
  if (cc.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  if (cc.status < CHOLMOD_OK || rank < 0 || factor_->r == nullptr)
    throw std::runtime_error("SuiteSparseQR failed (status " + std::to_string(cc.status) + ")");
  rank_ = static_cast<Eigen::Index>(rank);
  peak_memory_ = cc.memory_usage;
  permutation_.resize(static_cast<std::size_t>(cols_));
  for (Eigen::Index j = 0; j < cols_; ++j) {
    const Eigen::Index column = factor_->permutation != nullptr ? static_cast<Eigen::Index>(factor_->permutation[j]) : j;
    permutation_[static_cast<std::size_t>(j)] = given ? column_order[static_cast<std::size_t>(column)] : column;
  }
}

SparseRankCount sparse_qr_rank(const Eigen::SparseMatrix<double>& a, double threshold, const std::vector<Eigen::Index>& column_order) {
  if (!column_order.empty() && static_cast<Eigen::Index>(column_order.size()) != a.cols())
    throw std::invalid_argument("SparseQr: the column order must list every column once");
  SparseRankCount count;
  if (a.rows() == 0 || a.cols() == 0) return count;
  pin_blas_threads();
  SpqrInput input(a, column_order);
  cholmod_common cc{};
  cholmod_l_start(&cc);
  // keepH = false: the Householder vectors are discarded front by front, as SuiteSparseQR does
  // when Q is not asked for; the same factorisation, so the same rank and pivots.
  SuiteSparseQR_factorization<double>* qr =
      spqr_1factor<double>(column_order.empty() ? SPQR_ORDERING_METIS : SPQR_ORDERING_NATURAL, threshold, 0, 0,
                           &input.view, 0, nullptr, nullptr, nullptr, &cc);
  const int status = cc.status;
  if (qr == nullptr || status < CHOLMOD_OK) {
    if (qr != nullptr) spqr_freefac<double>(&qr, &cc);
    cholmod_l_finish(&cc);
    if (status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    throw std::runtime_error("SuiteSparseQR failed (status " + std::to_string(status) + ")");
  }
  count.rank = static_cast<Eigen::Index>(qr->rank);
  count.peak_memory = cc.memory_usage;
  const std::optional<double> smallest = smallest_live_pivot(*qr);
  spqr_freefac<double>(&qr, &cc);
  cholmod_l_finish(&cc);
  if (!smallest) throw std::logic_error("sparse_qr_rank: SuiteSparseQR's frontal R blocks do not match its rank");
  count.smallest_pivot = count.rank > 0 ? *smallest : 0.0;
  return count;
}

SparseQr::~SparseQr() = default;
SparseQr::SparseQr(SparseQr&&) noexcept = default;
SparseQr& SparseQr::operator=(SparseQr&&) noexcept = default;

SparseFactorView SparseQr::r() const {
  const cholmod_sparse* r = factor_->r;
  if (r == nullptr) return {0, cols_, 0, nullptr, nullptr, nullptr};
  return {static_cast<Eigen::Index>(r->nrow),
          static_cast<Eigen::Index>(r->ncol),
          static_cast<Eigen::Index>(static_cast<const std::int64_t*>(r->p)[r->ncol]),
          static_cast<const std::int64_t*>(r->p),
          static_cast<const std::int64_t*>(r->i),
          static_cast<const double*>(r->x)};
}

double SparseQr::smallest_pivot() const {
  if (rank_ == 0) return 0.0;
  const SparseFactorView r = this->r();
  double smallest = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < rank_; ++k) smallest = std::min(smallest, std::abs(r.coeff(k, k)));
  return smallest;
}

std::pair<std::vector<Eigen::Index>, std::vector<Eigen::Index>> SparseQr::live_and_dead_columns() const {
  std::vector<Eigen::Index> live(permutation_.begin(), permutation_.begin() + rank_);
  std::vector<Eigen::Index> dead(permutation_.begin() + rank_, permutation_.end());
  std::sort(live.begin(), live.end());
  std::sort(dead.begin(), dead.end());
  return {live, dead};
}

Eigen::MatrixXd SparseQr::null_vectors(Eigen::Index first, Eigen::Index count) const {
  const Eigen::Index dead = cols_ - rank_;
  first = std::clamp<Eigen::Index>(first, 0, dead);
  count = std::clamp<Eigen::Index>(count, 0, dead - first);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(cols_, count);
  if (count == 0) return result;
  const SparseFactorView r = this->r();
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for (Eigen::Index start = 0; start < count; start += kNullVectorBlock) {
    const Eigen::Index width = std::min(kNullVectorBlock, count - start);
    // y = −R12 e_k for each dead column k of the block, then R11 y = that, by columns of R11.
    Block y = Block::Zero(rank_, width);
    for (Eigen::Index c = 0; c < width; ++c)
      for (SparseFactorView::InnerIterator it(r, rank_ + first + start + c); it; ++it)
        if (it.row() < rank_) y(it.row(), c) = -it.value();
    for (Eigen::Index j = rank_ - 1; j >= 0; --j) {
      double diagonal = 0.0;
      for (SparseFactorView::InnerIterator it(r, j); it; ++it)
        if (it.row() == j) diagonal = it.value();
      y.row(j) /= diagonal;
      for (SparseFactorView::InnerIterator it(r, j); it; ++it)
        if (it.row() < j) y.row(it.row()) -= it.value() * y.row(j);
    }
    for (Eigen::Index c = 0; c < width; ++c) {
      auto column = result.col(start + c);
      for (Eigen::Index k = 0; k < rank_; ++k) column(permutation_[static_cast<std::size_t>(k)]) = y(k, c);
      column(permutation_[static_cast<std::size_t>(rank_ + first + start + c)]) = 1.0;
    }
  }
  return result;
}

void SparseQr::solve_transposed_live(Eigen::VectorXd& w) const {
  const SparseFactorView r = this->r();
  for (Eigen::Index j = 0; j < rank_; ++j) {  // column j of R is row j of R11ᵀ
    double sum = w(j), diagonal = 0.0;
    for (SparseFactorView::InnerIterator it(r, j); it; ++it) {
      if (it.row() < j) sum -= it.value() * w(it.row());
      else if (it.row() == j) diagonal = it.value();
    }
    w(j) = sum / diagonal;
  }
}

void SparseQr::solve_live(Eigen::VectorXd& w) const {
  const SparseFactorView r = this->r();
  for (Eigen::Index j = rank_ - 1; j >= 0; --j) {
    double diagonal = 0.0;
    for (SparseFactorView::InnerIterator it(r, j); it; ++it)
      if (it.row() == j) diagonal = it.value();
    w(j) /= diagonal;
    for (SparseFactorView::InnerIterator it(r, j); it; ++it)
      if (it.row() < j) w(it.row()) -= it.value() * w(j);
  }
}

double SparseQr::smallest_singular_estimate() const {
  if (rank_ == 0) return 0.0;
  // A fixed start of entries of varying size and sign (a quasi-random sequence of the index):
  // deterministic, and orthogonal to no singular vector in practice.
  Eigen::VectorXd x(rank_);
  for (Eigen::Index k = 0; k < rank_; ++k) x(k) = std::sin(1.0 + static_cast<double>(k) * 0.7548776662466927);
  x.normalize();
  double estimate = std::numeric_limits<double>::infinity();
  for (int step = 0; step < kSigmaMinSteps; ++step) {
    solve_transposed_live(x);
    solve_live(x);
    const double growth = x.norm();  // ‖(R11ᵀR11)⁻¹ x‖ for a unit x: at most 1/σ_min²
    if (!std::isfinite(growth) || growth <= 0.0) return 0.0;  // R11 singular in floating point
    const double next = 1.0 / std::sqrt(growth);
    const bool settled = std::abs(next - estimate) <= kSigmaMinSettled * next;
    estimate = std::min(estimate, next);
    if (settled) break;
    x /= growth;
  }
  return estimate;
}

Eigen::VectorXd SparseQr::least_squares_residual(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& g) const {
  if (rank_ == 0) return g;
  // x over the live columns (in the order of P) from R11ᵀ R11 x = (A_live)ᵀ b.
  auto solve = [&](const Eigen::VectorXd& b) {
    const Eigen::VectorXd atb = a.transpose() * b;
    Eigen::VectorXd w(rank_);
    for (Eigen::Index j = 0; j < rank_; ++j) w(j) = atb(permutation_[static_cast<std::size_t>(j)]);
    solve_transposed_live(w);
    solve_live(w);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(cols_);
    for (Eigen::Index k = 0; k < rank_; ++k) x(permutation_[static_cast<std::size_t>(k)]) = w(k);
    return x;
  };
  Eigen::VectorXd residual = g - a * solve(g);
  residual -= a * solve(residual);  // the correction step
  return residual;
}

}  // namespace kinestat::linalg
