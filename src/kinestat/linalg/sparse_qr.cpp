// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/sparse_qr.hpp"

#include "kinestat/linalg/cholmod_view.hpp"
#include "kinestat/linalg/factorisation_memory.hpp"

#include <SuiteSparseQR.hpp>

// SuiteSparseQR's factorisation without the conversion of R to a sparse matrix, and its release
// (exported by libspqr, declared in its internal header spqr.hpp, which defines macros of its own).
template <typename Entry>
SuiteSparseQR_factorization<Entry>* spqr_1factor(int ordering, double tol, SuiteSparse_long bncols, int keepH,
                                                 cholmod_sparse* A, SuiteSparse_long ldb, SuiteSparse_long* Bp,
                                                 SuiteSparse_long* Bi, Entry* Bx, cholmod_common* cc);
template <typename Entry>
void spqr_freefac(SuiteSparseQR_factorization<Entry>** QR_handle, cholmod_common* cc);
// The two phases spqr_1factor runs when there are no column singletons, and its mapping of the
// squeezed R (same origin).
spqr_symbolic* spqr_analyze(cholmod_sparse* A, int ordering, SuiteSparse_long* Quser, int do_rank_detection, int keepH,
                            cholmod_common* cc);
template <typename Entry>
spqr_numeric<Entry>* spqr_factorize(cholmod_sparse** Ahandle, SuiteSparse_long freeA, double tol, SuiteSparse_long ntol,
                                    spqr_symbolic* QRsym, cholmod_common* cc);
template <typename Entry>
int spqr_rmap(SuiteSparseQR_factorization<Entry>* QR, cholmod_common* cc);

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <cstdint>
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
  CholmodMatrix matrix;
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
    view = cholmod_view(matrix);
  }
  SpqrInput(const SpqrInput&) = delete;
  SpqrInput& operator=(const SpqrInput&) = delete;
};

// SuiteSparseQR's factorisation of a matrix (spqr_1factor: singletons, the fill-reducing order,
// the multifrontal QR with Heath's rank rule), Householder vectors discarded front by front as
// SuiteSparseQR does when Q is not asked for, so the same factorisation, rank and R.
class FrontalFactorisation {
 public:
  // The factorisation, the threshold asked for after the METIS order and the symbolic analysis
  // where they do not depend on it: with every column holding two or more
  // entries spqr_1factor finds no column singletons, whatever the threshold, and factors A
  // itself in the order of spqr_1colamd, which is METIS on the pattern of Aᵀ, postordered. The
  // calls below are spqr_1factor's and spqr_1colamd's in that case, in their order, with their
  // arguments (SuiteSparse 5.12, SPQR/Source/spqr_1factor.cpp and spqr_1colamd.cpp). Every
  // factorisation that can takes this way, whether or not its threshold is known, so that one
  // whose stack of fronts would exceed `memory_limit` is refused before any numeric work.
  FrontalFactorisation(SpqrInput& input, bool given_order, const std::function<double()>& threshold,
                       MemoryLimit memory_limit)
      : memory_limit_(memory_limit.resolved()) {
    start();
    if (given_order || !every_column_has_two_entries(input.view)) {
      factor_whole(input, given_order, ask(threshold));
      return;
    }
    cholmod_sparse* a = &input.view;
    const auto n = static_cast<SuiteSparse_long>(a->ncol);
    qr_ = static_cast<SuiteSparseQR_factorization<double>*>(
        cholmod_l_malloc(1, sizeof(SuiteSparseQR_factorization<double>), &cc_));
    check(qr_ != nullptr);
    *qr_ = SuiteSparseQR_factorization<double>{};  // every pointer null, no singletons, no B
    qr_->narows = static_cast<SuiteSparse_long>(a->nrow);
    qr_->nacols = n;
    qr_->Q1fill = static_cast<SuiteSparse_long*>(cholmod_l_malloc(static_cast<std::size_t>(n), sizeof(SuiteSparse_long), &cc_));
    check(qr_->Q1fill != nullptr);
    cholmod_sparse* pattern_transposed = cholmod_l_transpose(a, 0, &cc_);
    check(pattern_transposed != nullptr);
    const int postorder = cc_.postorder;
    cc_.postorder = 1;
    cholmod_l_metis(pattern_transposed, nullptr, 0, /*postorder*/ 1, qr_->Q1fill, &cc_);
    cc_.postorder = postorder;
    cholmod_l_free_sparse(&pattern_transposed, &cc_);
    check(true);
    qr_->QRsym = spqr_analyze(a, SPQR_ORDERING_GIVEN, qr_->Q1fill, /*do_rank_detection*/ 1, /*keepH*/ 0, &cc_);
    check(qr_->QRsym != nullptr);
    // spqr_factorize allocates this stack of doubles (the fronts, and R in place of each) at once.
    const double stack_bytes = static_cast<double>(sizeof(double)) * static_cast<double>(qr_->QRsym->maxstack);
    if (const auto limit = static_cast<double>(memory_limit_); stack_bytes > limit) {
      const double flops = cc_.SPQR_flopcount_bound;
      release();
      throw FactorisationTooLarge(stack_bytes, /*at_least*/ false, flops, limit);
    }
    const double tol = ask(threshold);
    if (!(tol >= 0.0)) {  // spqr_1factor would skip the rank rule, which the analysis above assumed
      release();
      throw std::invalid_argument("SparseQr: a threshold asked for after the analysis must be a number >= 0");
    }
    qr_->tol = tol;
    qr_->allow_tol = 1;
    qr_->QRnum = spqr_factorize<double>(&a, /*freeA*/ 0, tol, n, qr_->QRsym, &cc_);
    check(qr_->QRnum != nullptr);
    qr_->rank = qr_->QRnum->rank1;
    if (qr_->rank < n) check(spqr_rmap<double>(qr_, &cc_) != 0);
  }
  ~FrontalFactorisation() { release(); }
  FrontalFactorisation(const FrontalFactorisation&) = delete;
  FrontalFactorisation& operator=(const FrontalFactorisation&) = delete;

  const SuiteSparseQR_factorization<double>& factor() const { return *qr_; }
  /// SuiteSparse's own count of its peak memory, in bytes.
  std::size_t peak_memory() const { return cc_.memory_usage; }

  /// Visits R where SuiteSparseQR keeps it before assembling it (the layout spqr_rconvert of
  /// SuiteSparse 5.12 reads). Columns are numbered in the factorisation's order (column singletons
  /// first, then the fill order), rows are R's (squeezed: the k-th live column's pivot is row
  /// k). First the column singletons' rows R1: each row's singleton is live and its pivot is the
  /// row's first entry (no earlier column reaches a later singleton's row; an empty column counts
  /// as a singleton column without a row, so rows and columns need not pair up by index). Then
  /// each front's packed block, column by column, every column holding as many entries as the
  /// front has live pivot rows so far, a live pivotal column's own pivot last.
  /// live(column, pivot) is called for every live column in order; with `Entries`,
  /// entry(row, column, value) for every stored entry (exact zeros of the fronts skipped, as
  /// spqr_rconvert skips them), the rows of each column increasing. Throws std::logic_error if
  /// the live columns found disagree with the factorisation's rank (a layout this code does not
  /// know).
  template <bool Entries, typename Live, typename Entry>
  void visit_r(Live&& live, Entry&& entry) const {
    const SuiteSparseQR_factorization<double>& qr = *qr_;
    SuiteSparse_long found = 0;
    for (SuiteSparse_long row = 0; row < qr.n1rows; ++row) {
      const SuiteSparse_long begin = qr.R1p[row], end = qr.R1p[row + 1];
      if (begin < end) {
        live(qr.R1j[begin], qr.R1x[begin]);
        ++found;
      }
      if constexpr (Entries)
        for (SuiteSparse_long p = begin; p < end; ++p) entry(row, qr.R1j[p], qr.R1x[p]);
    }
    const spqr_symbolic* symbolic = qr.QRsym;
    const spqr_numeric<double>* numeric = qr.QRnum;
    if (symbolic != nullptr && numeric != nullptr) {
      SuiteSparse_long first_row = qr.n1rows;
      for (SuiteSparse_long f = 0; f < symbolic->nf; ++f) {
        const double* block = numeric->Rblock[f];
        const SuiteSparse_long first = symbolic->Super[f];
        const SuiteSparse_long pivots = symbolic->Super[f + 1] - first;
        const SuiteSparse_long* front_columns = symbolic->Rj + symbolic->Rp[f];
        const SuiteSparse_long columns = symbolic->Rp[f + 1] - symbolic->Rp[f];
        SuiteSparse_long rows = 0;
        for (SuiteSparse_long k = 0; k < columns; ++k) {
          const SuiteSparse_long column = qr.n1cols + front_columns[k];
          if (k < pivots && (numeric->Rdead == nullptr || numeric->Rdead[first + k] == 0)) {
            ++rows;
            live(column, block[rows - 1]);
            ++found;
          }
          if constexpr (Entries)
            for (SuiteSparse_long t = 0; t < rows; ++t)
              if (block[t] != 0.0) entry(first_row + t, column, block[t]);
          block += rows;
        }
        first_row += rows;
      }
    }
    if (found != qr.rank) throw std::logic_error("SparseQr: SuiteSparseQR's frontal R blocks do not match its rank");
  }

 private:
  void factor_whole(SpqrInput& input, bool given_order, double threshold) {
    // Nested dissection by METIS keeps the fill of R near that of a Cholesky factor of AᵀA on
    // lattice-like frameworks; a given order is kept (SPQR_ORDERING_NATURAL: singletons first,
    // then the columns as given, etree-postordered).
    qr_ = spqr_1factor<double>(given_order ? SPQR_ORDERING_NATURAL : SPQR_ORDERING_METIS, threshold, 0, 0, &input.view, 0,
                               nullptr, nullptr, nullptr, &cc_);
    check(qr_ != nullptr);
  }
  // CHOLMOD prints its errors (an allocation that failed) to standard error by default; they
  // reach the caller as exceptions instead, so that a command's error stays one line.
  void start() {
    cholmod_l_start(&cc_);
    cc_.print = 0;
  }
  // The caller's threshold; what was made is released if asking throws.
  double ask(const std::function<double()>& threshold) {
    try {
      return threshold();
    } catch (...) {
      release();
      throw;
    }
  }
  static bool every_column_has_two_entries(const cholmod_sparse& a) {
    const auto* starts = static_cast<const SuiteSparse_long*>(a.p);
    for (std::size_t j = 0; j < a.ncol; ++j)
      if (starts[j + 1] - starts[j] < 2) return false;
    return true;
  }
  // Throws, releasing what was made, if SuiteSparse failed or `made` is false.
  void check(bool made) {
    const int status = cc_.status;
    if (made && status >= CHOLMOD_OK) return;
    // Out of memory after SuiteSparseQR's analysis (spqr_1factor allocates the stack of fronts at
    // once): its R alone, SPQR_istat[0] entries, is a lower bound on what was asked for, and
    // when that is a large part of the machine's memory, the fill is why.
    const double r_bytes = static_cast<double>(sizeof(double)) * static_cast<double>(cc_.SPQR_istat[0]);
    const double flops = cc_.SPQR_flopcount_bound;
    release();
    if (status == CHOLMOD_OUT_OF_MEMORY && r_bytes > static_cast<double>(memory_limit_) / 8)
      throw FactorisationTooLarge(r_bytes, /*at_least*/ true, flops, 0.0);
    if (status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    throw std::runtime_error("SuiteSparseQR failed (status " + std::to_string(status) + ")");
  }
  void release() {
    if (qr_ != nullptr) spqr_freefac<double>(&qr_, &cc_);
    cholmod_l_finish(&cc_);
  }
  cholmod_common cc_{};
  SuiteSparseQR_factorization<double>* qr_ = nullptr;
  std::uint64_t memory_limit_;  // bytes (MemoryLimit::resolved)
};

}  // namespace

// R (rank × n) in compressed columns, in the order of permutation(): the live columns first.
struct SparseQr::Factor {
  std::vector<std::int64_t> starts, rows;
  std::vector<double> values;
};

SparseQr::SparseQr(const Eigen::SparseMatrix<double>& a, double threshold, MemoryLimit memory_limit)
    : factor_(std::make_unique<Factor>()), rows_(a.rows()), cols_(a.cols()) {
  factor(a, [threshold] { return threshold; }, {}, memory_limit);
}

SparseQr::SparseQr(const Eigen::SparseMatrix<double>& a, const std::function<double()>& threshold,
                   MemoryLimit memory_limit)
    : factor_(std::make_unique<Factor>()), rows_(a.rows()), cols_(a.cols()) {
  factor(a, threshold, {}, memory_limit);
}

SparseQr::SparseQr(const Eigen::SparseMatrix<double>& a, double threshold, const std::vector<Eigen::Index>& column_order,
                   MemoryLimit memory_limit)
    : factor_(std::make_unique<Factor>()), rows_(a.rows()), cols_(a.cols()) {
  if (static_cast<Eigen::Index>(column_order.size()) != cols_)
    throw std::invalid_argument("SparseQr: the column order must list every column once");
  factor(a, [threshold] { return threshold; }, column_order, memory_limit);
}

void SparseQr::factor(const Eigen::SparseMatrix<double>& a, const std::function<double()>& threshold,
                      const std::vector<Eigen::Index>& column_order, MemoryLimit memory_limit) {
  if (rows_ == 0 || cols_ == 0) {
    threshold();  // asked for in every case, so that a caller's promise is always collected
    for (Eigen::Index j = 0; j < cols_; ++j) permutation_.push_back(j);
    factor_->starts.assign(static_cast<std::size_t>(cols_) + 1, 0);
    return;
  }
  const bool given = !column_order.empty();
  SpqrInput input(a, column_order);
  const FrontalFactorisation qr(input, given, threshold, memory_limit);
  rank_ = static_cast<Eigen::Index>(qr.factor().rank);
  // R assembled once, straight into trapezoidal form: the live columns first, each group in
  // the factorisation's order, every entry in its row of the squeezed R. SuiteSparseQR makes
  // the same matrix in two copies (spqr_rconvert, then spqr_trapezoidal), with the same entries
  // in the same order.
  const auto n = static_cast<std::size_t>(cols_);
  std::vector<std::int64_t> position(n, -1), count(n, 0);
  std::int64_t live = 0;
  qr.visit_r<true>([&](SuiteSparse_long column, double) { position[static_cast<std::size_t>(column)] = live++; },
                   [&](SuiteSparse_long, SuiteSparse_long column, double) { ++count[static_cast<std::size_t>(column)]; });
  std::int64_t dead = live;
  for (std::int64_t& p : position)
    if (p < 0) p = dead++;
  std::vector<std::int64_t>& starts = factor_->starts;
  starts.assign(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k) starts[static_cast<std::size_t>(position[k]) + 1] = count[k];
  for (std::size_t k = 0; k < n; ++k) starts[k + 1] += starts[k];
  factor_->rows.resize(static_cast<std::size_t>(starts[n]));
  factor_->values.resize(static_cast<std::size_t>(starts[n]));
  std::vector<std::int64_t> next(starts.begin(), starts.end() - 1);
  qr.visit_r<true>([](SuiteSparse_long, double) {},
                   [&](SuiteSparse_long row, SuiteSparse_long column, double value) {
                     const auto at = static_cast<std::size_t>(next[static_cast<std::size_t>(position[static_cast<std::size_t>(column)])]++);
                     factor_->rows[at] = row;
                     factor_->values[at] = value;
                   });
  peak_memory_ = qr.peak_memory() + factor_->rows.size() * (sizeof(std::int64_t) + sizeof(double));
  permutation_.resize(n);
  const SuiteSparse_long* fill = qr.factor().Q1fill;
  for (std::size_t k = 0; k < n; ++k) {
    const auto column = static_cast<std::size_t>(fill != nullptr ? fill[k] : static_cast<SuiteSparse_long>(k));
    permutation_[static_cast<std::size_t>(position[k])] = given ? column_order[column] : static_cast<Eigen::Index>(column);
  }
}

SparseRankCount sparse_qr_rank(const Eigen::SparseMatrix<double>& a, double threshold, const std::vector<Eigen::Index>& column_order,
                               MemoryLimit memory_limit) {
  if (!column_order.empty() && static_cast<Eigen::Index>(column_order.size()) != a.cols())
    throw std::invalid_argument("SparseQr: the column order must list every column once");
  SparseRankCount count;
  if (a.rows() == 0 || a.cols() == 0) return count;
  SpqrInput input(a, column_order);
  const FrontalFactorisation qr(input, !column_order.empty(), [threshold] { return threshold; }, memory_limit);
  count.rank = static_cast<Eigen::Index>(qr.factor().rank);
  count.peak_memory = qr.peak_memory();
  double smallest = std::numeric_limits<double>::infinity();
  qr.visit_r<false>([&](SuiteSparse_long, double pivot) { smallest = std::min(smallest, std::abs(pivot)); },
                    [](SuiteSparse_long, SuiteSparse_long, double) {});
  count.smallest_pivot = count.rank > 0 ? smallest : 0.0;
  return count;
}

SparseQr::~SparseQr() = default;
SparseQr::SparseQr(SparseQr&&) noexcept = default;
SparseQr& SparseQr::operator=(SparseQr&&) noexcept = default;

SparseFactorView SparseQr::r() const {
  const Factor& f = *factor_;
  return {rank_, cols_, static_cast<Eigen::Index>(f.rows.size()), f.starts.data(), f.rows.data(), f.values.data()};
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
