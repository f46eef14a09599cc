// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/flint_elimination.hpp"

#include <stdexcept>

#ifdef KINESTAT_HAVE_FLINT
#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>

#include <cstdlib>
#include <mutex>
#include <new>
#endif

namespace kinestat::linalg {

#ifdef KINESTAT_HAVE_FLINT

namespace {

// FLINT's own allocation functions abort() when memory runs out; these throw std::bad_alloc
// instead, as GMP's do in the command (gmp_allocation.cpp), so a model too large for the machine
// ends as a clean error (install_throwing_flint_allocation). FLINT's temporaries of the failing
// operation leak on the way out.
void* flint_allocate(std::size_t size) {
  void* block = std::malloc(size);
  if (block == nullptr && size > 0) throw std::bad_alloc();
  return block;
}

void* flint_allocate_zeroed(std::size_t count, std::size_t size) {
  void* block = std::calloc(count, size);
  if (block == nullptr && count > 0 && size > 0) throw std::bad_alloc();
  return block;
}

void* flint_reallocate(void* block, std::size_t size) {
  void* moved = std::realloc(block, size);
  if (moved == nullptr && size > 0) throw std::bad_alloc();
  return moved;
}

void flint_release(void* block) { std::free(block); }

// An fmpq_mat_t that clears itself.
class FlintRationalMatrix {
 public:
  FlintRationalMatrix(Eigen::Index rows, Eigen::Index cols) {
    fmpq_mat_init(matrix_, static_cast<slong>(rows), static_cast<slong>(cols));
  }
  FlintRationalMatrix(const FlintRationalMatrix&) = delete;
  FlintRationalMatrix& operator=(const FlintRationalMatrix&) = delete;
  ~FlintRationalMatrix() { fmpq_mat_clear(matrix_); }

  fmpq* entry(Eigen::Index r, Eigen::Index c) const {
    return fmpq_mat_entry(matrix_, static_cast<slong>(r), static_cast<slong>(c));
  }
  fmpq_mat_struct* get() { return matrix_; }
  const fmpq_mat_struct* get() const { return matrix_; }

 private:
  fmpq_mat_t matrix_;
};

// The entries of `a` in FLINT: transposed or not, the resulting columns reversed or not.
void copy_into(const RationalMatrix& a, bool transposed, bool reversed_columns, FlintRationalMatrix& target) {
  const Eigen::Index target_cols = transposed ? a.rows() : a.cols();
  for (Eigen::Index r = 0; r < a.rows(); ++r) {
    for (Eigen::Index c = 0; c < a.cols(); ++c) {
      if (sgn(a(r, c)) == 0) continue;  // fmpq_mat_init gives zeros
      Eigen::Index tr = transposed ? c : r, tc = transposed ? r : c;
      if (reversed_columns) tc = target_cols - 1 - tc;
      fmpq_set_mpq(target.entry(tr, tc), a(r, c).get_mpq_t());
    }
  }
}

Rational rational_of(const fmpq* value) {
  Rational result;
  fmpq_get_mpq(result.get_mpq_t(), value);
  return result;
}

// Pivot column of each of the first `rank` rows of a matrix in reduced row echelon form.
std::vector<Eigen::Index> echelon_pivots(const FlintRationalMatrix& echelon, Eigen::Index rank, Eigen::Index cols) {
  std::vector<Eigen::Index> pivots;
  pivots.reserve(static_cast<std::size_t>(rank));
  Eigen::Index c = 0;
  for (Eigen::Index r = 0; r < rank; ++r) {
    while (c < cols && fmpq_is_zero(echelon.entry(r, c))) ++c;
    pivots.push_back(c++);
  }
  return pivots;
}

}  // namespace

void install_throwing_flint_allocation() {
  static std::once_flag once;
  std::call_once(once, [] {
    __flint_set_memory_functions(flint_allocate, flint_allocate_zeroed, flint_reallocate, flint_release);
  });
}

bool flint_available() { return true; }

Eigen::Index flint_rank(const RationalMatrix& a) {
  if (a.rows() == 0 || a.cols() == 0) return 0;
  FlintRationalMatrix rational(a.rows(), a.cols());
  copy_into(a, false, false, rational);
  fmpz_mat_t integer;
  fmpz_mat_init(integer, static_cast<slong>(a.rows()), static_cast<slong>(a.cols()));
  fmpz* row_denominators = _fmpz_vec_init(static_cast<slong>(a.rows()));
  fmpq_mat_get_fmpz_mat_rowwise(integer, row_denominators, rational.get());
  const slong rank = fmpz_mat_rank(integer);
  _fmpz_vec_clear(row_denominators, static_cast<slong>(a.rows()));
  fmpz_mat_clear(integer);
  return static_cast<Eigen::Index>(rank);
}

RightPivotNullSpace flint_right_pivot_null_space(const RationalMatrix& a) {
  const Eigen::Index rows = a.rows(), cols = a.cols();
  RightPivotNullSpace result;
  if (rows > 0 && cols > 0) {
    FlintRationalMatrix reversed(rows, cols), echelon(rows, cols);
    copy_into(a, false, true, reversed);
    result.rank = static_cast<Eigen::Index>(fmpq_mat_rref(echelon.get(), reversed.get()));
    // Column j of the reversed matrix is column cols − 1 − j of `a`: the leftmost pivots found
    // there are the rightmost of `a`, in the order the backwards search of `a` finds them.
    const std::vector<Eigen::Index> reversed_pivots = echelon_pivots(echelon, result.rank, cols);
    std::vector<bool> is_pivot(static_cast<std::size_t>(cols), false);
    for (Eigen::Index p : reversed_pivots) {
      result.pivot_columns.push_back(cols - 1 - p);
      is_pivot[static_cast<std::size_t>(cols - 1 - p)] = true;
    }
    for (Eigen::Index c = 0; c < cols; ++c)
      if (!is_pivot[static_cast<std::size_t>(c)]) result.free_variables.push_back(c);
    const auto nullity = static_cast<Eigen::Index>(result.free_variables.size());
    result.null_basis = RationalMatrix(cols, nullity);
    for (Eigen::Index j = 0; j < nullity; ++j) {
      const Eigen::Index f = result.free_variables[static_cast<std::size_t>(j)];
      result.null_basis(f, j) = 1;
      for (Eigen::Index r = 0; r < result.rank; ++r) {
        const fmpq* entry = echelon.entry(r, cols - 1 - f);
        if (!fmpq_is_zero(entry)) result.null_basis(result.pivot_columns[static_cast<std::size_t>(r)], j) = -rational_of(entry);
      }
    }
    return result;
  }
  for (Eigen::Index c = 0; c < cols; ++c) result.free_variables.push_back(c);
  result.null_basis = RationalMatrix(cols, cols);
  for (Eigen::Index c = 0; c < cols; ++c) result.null_basis(c, c) = 1;
  return result;
}

std::vector<Eigen::Index> flint_redundant_rows(const RationalMatrix& a) {
  const Eigen::Index rows = a.rows(), cols = a.cols();
  std::vector<Eigen::Index> redundant;
  if (rows == 0) return redundant;
  if (cols == 0) {  // every row is zero: each depends on (is) nothing
    for (Eigen::Index r = 0; r < rows; ++r) redundant.push_back(r);
    return redundant;
  }
  // Column j of the reversed transpose is row rows − 1 − j of `a`: its pivot columns are the
  // rows kept from the bottom up.
  FlintRationalMatrix reversed(cols, rows), echelon(cols, rows);
  copy_into(a, true, true, reversed);
  const auto rank = static_cast<Eigen::Index>(fmpq_mat_rref(echelon.get(), reversed.get()));
  std::vector<bool> kept(static_cast<std::size_t>(rows), false);
  for (Eigen::Index p : echelon_pivots(echelon, rank, rows)) kept[static_cast<std::size_t>(rows - 1 - p)] = true;
  for (Eigen::Index r = 0; r < rows; ++r)
    if (!kept[static_cast<std::size_t>(r)]) redundant.push_back(r);
  return redundant;
}

std::optional<RationalMatrix> flint_inverse(const RationalMatrix& a) {
  if (a.rows() != a.cols()) throw std::invalid_argument("flint_inverse: the matrix is not square");
  const Eigen::Index n = a.rows();
  if (n == 0) return RationalMatrix(0, 0);
  FlintRationalMatrix source(n, n), inverse(n, n);
  copy_into(a, false, false, source);
  if (fmpq_mat_inv(inverse.get(), source.get()) == 0) return std::nullopt;
  RationalMatrix result(n, n);
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index c = 0; c < n; ++c)
      if (!fmpq_is_zero(inverse.entry(r, c))) result(r, c) = rational_of(inverse.entry(r, c));
  return result;
}

#else

namespace {
[[noreturn]] void flint_missing() {
  throw std::logic_error("kinestat was built without FLINT (CMake option KINESTAT_FLINT)");
}
}  // namespace

void install_throwing_flint_allocation() {}  // no FLINT, nothing to install
bool flint_available() { return false; }
Eigen::Index flint_rank(const RationalMatrix&) { flint_missing(); }
RightPivotNullSpace flint_right_pivot_null_space(const RationalMatrix&) { flint_missing(); }
std::vector<Eigen::Index> flint_redundant_rows(const RationalMatrix&) { flint_missing(); }
std::optional<RationalMatrix> flint_inverse(const RationalMatrix&) { flint_missing(); }

#endif

}  // namespace kinestat::linalg
