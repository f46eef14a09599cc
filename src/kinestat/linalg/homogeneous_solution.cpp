// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/homogeneous_solution.hpp"

#include "kinestat/linalg/blas_kernels.hpp"
#include "kinestat/linalg/flint_elimination.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>

namespace kinestat::linalg {

namespace {

using Row = std::vector<Rational>;

// Candidates projected together in greedy_independent_rows.
constexpr Eigen::Index kGreedyBlock = 48;

// Keeps a set of rows in reduced echelon form so that a new row can be tested for
// dependence in one pass. Pivot column of basis row i is pivots[i]; basis rows are zero in
// every other basis row's pivot column and one in their own.
class ExactRowBasis {
 public:
  explicit ExactRowBasis(Eigen::Index cols) : cols_(cols) {}

  // Reduces `row` against the basis; if something is left, adds it and returns true.
  bool add(Row row) {
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      const Rational factor = row[static_cast<std::size_t>(pivots_[i])];
      if (sgn(factor) == 0) continue;
      for (Eigen::Index c = 0; c < cols_; ++c) {
        const auto cu = static_cast<std::size_t>(c);
        if (sgn(rows_[i][cu]) != 0) row[cu] -= factor * rows_[i][cu];
      }
    }
    Eigen::Index pivot = -1;
    for (Eigen::Index c = 0; c < cols_ && pivot < 0; ++c)
      if (sgn(row[static_cast<std::size_t>(c)]) != 0) pivot = c;
    if (pivot < 0) return false;
    const Rational scale = row[static_cast<std::size_t>(pivot)];
    for (Rational& value : row) value /= scale;
    for (auto& other : rows_) {
      const Rational factor = other[static_cast<std::size_t>(pivot)];
      if (sgn(factor) == 0) continue;
      for (Eigen::Index c = 0; c < cols_; ++c) {
        const auto cu = static_cast<std::size_t>(c);
        if (sgn(row[cu]) != 0) other[cu] -= factor * row[cu];
      }
    }
    rows_.push_back(std::move(row));
    pivots_.push_back(pivot);
    return true;
  }

 private:
  Eigen::Index cols_;
  std::vector<Row> rows_;
  std::vector<Eigen::Index> pivots_;
};

Row row_of(const RationalMatrix& a, Eigen::Index r) {
  Row row(static_cast<std::size_t>(a.cols()));
  for (Eigen::Index c = 0; c < a.cols(); ++c) row[static_cast<std::size_t>(c)] = a(r, c);
  return row;
}

// Exact inverse by Gauss-Jordan; returns false if singular.
bool invert(RationalMatrix m, RationalMatrix& inverse) {
  const Eigen::Index n = m.rows();
  inverse = RationalMatrix(n, n);
  for (Eigen::Index i = 0; i < n; ++i) inverse(i, i) = 1;
  for (Eigen::Index c = 0; c < n; ++c) {
    Eigen::Index pivot = c;
    while (pivot < n && sgn(m(pivot, c)) == 0) ++pivot;
    if (pivot == n) return false;
    for (Eigen::Index k = 0; k < n; ++k) {
      std::swap(m(c, k), m(pivot, k));
      std::swap(inverse(c, k), inverse(pivot, k));
    }
    const Rational scale = m(c, c);
    for (Eigen::Index k = 0; k < n; ++k) {
      m(c, k) /= scale;
      inverse(c, k) /= scale;
    }
    for (Eigen::Index r = 0; r < n; ++r) {
      if (r == c || sgn(m(r, c)) == 0) continue;
      const Rational factor = m(r, c);
      for (Eigen::Index k = 0; k < n; ++k) {
        m(r, k) -= factor * m(c, k);
        inverse(r, k) -= factor * inverse(c, k);
      }
    }
  }
  return true;
}

void clean_small(Eigen::MatrixXd& m) {
  const double largest = m.size() > 0 ? m.cwiseAbs().maxCoeff() : 0.0;
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (std::abs(m.data()[i]) <= kCoefficientZero * largest) m.data()[i] = 0.0;
}

// Greedy choice, in the given order, of vectors (rows of `vectors`) that are independent of
// the ones chosen before, by Gram-Schmidt with an absolute residual threshold.
std::vector<Eigen::Index> greedy_independent_rows(const Eigen::MatrixXd& vectors,
                                                  const std::vector<Eigen::Index>& order, double threshold,
                                                  Eigen::Index wanted) {
  std::vector<Eigen::Index> chosen;
  // Preallocated: at most `wanted` basis vectors; the first `kept` columns are in use.
  Eigen::MatrixXd basis(vectors.cols(), std::max<Eigen::Index>(wanted, 0));
  Eigen::Index kept = 0;
  // Blocked: the candidates of one block are projected against the basis found before it in
  // one matrix product (twice, which is enough), then taken one by one against the vectors the
  // block itself adds. Same choices as one row at a time, at matrix-product speed.
  const auto candidates = static_cast<Eigen::Index>(order.size());
  for (Eigen::Index start = 0; start < candidates && kept < wanted; start += kGreedyBlock) {
    const Eigen::Index width = std::min(kGreedyBlock, candidates - start);
    Eigen::MatrixXd block(vectors.cols(), width);
    for (Eigen::Index c = 0; c < width; ++c) block.col(c) = vectors.row(order[static_cast<std::size_t>(start + c)]).transpose();
    for (int pass = 0; pass < 2; ++pass) blas_subtract_projection(basis, kept, block);
    const Eigen::Index block_start = kept;
    for (Eigen::Index c = 0; c < width && kept < wanted; ++c) {
      Eigen::VectorXd residual = block.col(c);
      const auto fresh = basis.middleCols(block_start, kept - block_start);
      for (int pass = 0; pass < 2; ++pass) residual -= fresh * (fresh.transpose() * residual);
      const double norm = residual.norm();
      if (norm > threshold) {
        basis.col(kept++) = residual / norm;
        chosen.push_back(order[static_cast<std::size_t>(start + c)]);
      }
    }
  }
  return chosen;
}

}  // namespace

// In a build with FLINT (KINESTAT_FLINT) the exact functions below eliminate by FLINT
// (flint_elimination.hpp), several times faster; the GMP elimination is the fallback of a build
// without it. Both give
// the same answers: ranks, reduced echelon forms and inverses are unique.
Eigen::Index exact_rank(const RationalMatrix& m) {
  if (flint_available()) return flint_rank(m);
  ExactRowBasis basis(m.cols());
  Eigen::Index rank = 0;
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    if (basis.add(row_of(m, r))) ++rank;
  return rank;
}

std::vector<Eigen::Index> redundant_rows(const RationalMatrix& a) {
  if (flint_available()) return flint_redundant_rows(a);
  std::vector<Eigen::Index> redundant;
  ExactRowBasis basis(a.cols());
  for (Eigen::Index r = a.rows() - 1; r >= 0; --r)
    if (!basis.add(row_of(a, r))) redundant.push_back(r);
  std::sort(redundant.begin(), redundant.end());
  return redundant;
}

std::vector<Eigen::Index> redundant_rows(const Eigen::MatrixXd& a, Eigen::Index rank) {
  std::vector<Eigen::Index> redundant;
  if (a.cols() == 0) {
    // No unknown (every coupling rigid): every row is redundant. Eigen's row() of a matrix
    // without columns offsets a null pointer (undefined behaviour, found by fuzz_valid_models).
    for (Eigen::Index r = 0; r < a.rows(); ++r) redundant.push_back(r);
    return redundant;
  }
  Eigen::MatrixXd unit_rows = a;
  for (Eigen::Index r = 0; r < a.rows(); ++r) {
    const double norm = a.row(r).norm();
    if (norm > 0) unit_rows.row(r) /= norm;
  }
  std::vector<Eigen::Index> bottom_up(static_cast<std::size_t>(a.rows()));
  std::iota(bottom_up.rbegin(), bottom_up.rend(), Eigen::Index{0});
  std::vector<Eigen::Index> kept = greedy_independent_rows(unit_rows, bottom_up, kFreeVariableResidual, rank);
  if (static_cast<Eigen::Index>(kept.size()) != rank) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(unit_rows.transpose());
    kept.clear();
    for (Eigen::Index i = 0; i < rank; ++i) kept.push_back(qr.colsPermutation().indices()(i));
  }
  std::vector<bool> is_kept(static_cast<std::size_t>(a.rows()), false);
  for (Eigen::Index r : kept) is_kept[static_cast<std::size_t>(r)] = true;
  for (Eigen::Index r = 0; r < a.rows(); ++r)
    if (!is_kept[static_cast<std::size_t>(r)]) redundant.push_back(r);
  return redundant;
}

HomogeneousSolution solve_homogeneous(const RationalMatrix& a) {
  const Eigen::Index rows = a.rows(), cols = a.cols();
  if (flint_available()) {
    RightPivotNullSpace reduced = flint_right_pivot_null_space(a);
    HomogeneousSolution solution;
    solution.rank.exact = true;
    solution.rank.rank = reduced.rank;
    solution.rank.rows = rows;
    solution.rank.cols = cols;
    solution.free_variables = std::move(reduced.free_variables);
    solution.coefficients = reduced.null_basis.to_double();
    solution.exact_coefficients = std::move(reduced.null_basis);
    solution.redundant_rows = redundant_rows(a);
    return solution;
  }
  std::vector<Row> m;
  m.reserve(static_cast<std::size_t>(rows));
  for (Eigen::Index r = 0; r < rows; ++r) m.push_back(row_of(a, r));

  // Reduced row echelon form with pivots sought from the last column backwards.
  std::vector<Eigen::Index> pivot_col_of_row;
  std::vector<bool> is_pivot(static_cast<std::size_t>(cols), false);
  std::size_t rank = 0;
  for (Eigen::Index c = cols - 1; c >= 0; --c) {
    const auto cu = static_cast<std::size_t>(c);
    std::size_t pivot = rank;
    while (pivot < m.size() && sgn(m[pivot][cu]) == 0) ++pivot;
    if (pivot == m.size()) continue;
    std::swap(m[rank], m[pivot]);
    const Rational scale = m[rank][cu];
    for (Rational& value : m[rank]) value /= scale;
    for (std::size_t r = 0; r < m.size(); ++r) {
      if (r == rank || sgn(m[r][cu]) == 0) continue;
      const Rational factor = m[r][cu];
      for (std::size_t k = 0; k < static_cast<std::size_t>(cols); ++k)
        if (sgn(m[rank][k]) != 0) m[r][k] -= factor * m[rank][k];
    }
    pivot_col_of_row.push_back(c);
    is_pivot[cu] = true;
    ++rank;
  }

  HomogeneousSolution solution;
  solution.rank.exact = true;
  solution.rank.rank = static_cast<Eigen::Index>(rank);
  solution.rank.rows = rows;
  solution.rank.cols = cols;
  for (Eigen::Index c = 0; c < cols; ++c)
    if (!is_pivot[static_cast<std::size_t>(c)]) solution.free_variables.push_back(c);

  RationalMatrix k(cols, solution.nullity());
  for (Eigen::Index j = 0; j < solution.nullity(); ++j) {
    const Eigen::Index f = solution.free_variables[static_cast<std::size_t>(j)];
    k(f, j) = 1;
    for (std::size_t r = 0; r < rank; ++r) k(pivot_col_of_row[r], j) = -m[r][static_cast<std::size_t>(f)];
  }
  solution.coefficients = k.to_double();
  solution.exact_coefficients = std::move(k);
  solution.redundant_rows = redundant_rows(a);
  return solution;
}

Eigen::MatrixXd echelon_null_basis(const Eigen::MatrixXd& null_basis, std::vector<Eigen::Index>& free_variables,
                                   double free_variable) {
  const Eigen::Index cols = null_basis.rows(), nullity = null_basis.cols();
  std::vector<Eigen::Index> top_down(static_cast<std::size_t>(cols));
  std::iota(top_down.begin(), top_down.end(), Eigen::Index{0});
  free_variables = greedy_independent_rows(null_basis, top_down, free_variable, nullity);
  std::sort(free_variables.begin(), free_variables.end());
  const auto found = static_cast<Eigen::Index>(free_variables.size());
  Eigen::MatrixXd at_free(found, nullity);
  for (Eigen::Index j = 0; j < found; ++j) at_free.row(j) = null_basis.row(free_variables[static_cast<std::size_t>(j)]);
  std::optional<Eigen::MatrixXd> divided;
  if (at_free.size() > 0 && found == nullity) divided = lapack_right_divide(null_basis, at_free);
  Eigen::MatrixXd coefficients = divided ? std::move(*divided) : Eigen::MatrixXd::Zero(cols, found);
  clean_small(coefficients);
  for (Eigen::Index j = 0; j < found; ++j)  // exactly one on the free variables themselves
    coefficients.row(free_variables[static_cast<std::size_t>(j)]) = Eigen::RowVectorXd::Unit(found, j);
  return coefficients;
}

HomogeneousSolution solve_homogeneous(const Eigen::MatrixXd& a, const RankTolerance& tolerance, double free_variable) {
  const Eigen::Index rows = a.rows(), cols = a.cols();
  HomogeneousSolution solution;
  Eigen::MatrixXd null_basis;
  if (rows == 0 || cols == 0) {
    null_basis = Eigen::MatrixXd::Identity(cols, cols);
  } else {
    const SvdAnalysis svd = analyse_svd(a, tolerance, SvdVectors::right_only);
    solution.singular_values = svd.singular_values;
    solution.rank = svd.rank;
    null_basis = svd.null_space();
  }
  solution.coefficients = echelon_null_basis(null_basis, solution.free_variables, free_variable);

  // Rows kept from the bottom up; redundant = the rest. Fall back to column-pivoted QR of A^T
  // if the greedy pass disagrees with the SVD rank (only possible near the tolerance).
  std::vector<Eigen::Index> bottom_up(static_cast<std::size_t>(rows));
  std::iota(bottom_up.rbegin(), bottom_up.rend(), Eigen::Index{0});
  std::vector<Eigen::Index> kept =
      greedy_independent_rows(a, bottom_up, std::max(solution.rank.threshold, 0.0), solution.rank.rank);
  if (static_cast<Eigen::Index>(kept.size()) != solution.rank.rank) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a.transpose());
    kept.clear();
    for (Eigen::Index i = 0; i < solution.rank.rank; ++i) kept.push_back(qr.colsPermutation().indices()(i));
  }
  std::vector<bool> is_kept(static_cast<std::size_t>(rows), false);
  for (Eigen::Index r : kept) is_kept[static_cast<std::size_t>(r)] = true;
  for (Eigen::Index r = 0; r < rows; ++r)
    if (!is_kept[static_cast<std::size_t>(r)]) solution.redundant_rows.push_back(r);
  return solution;
}

HomogeneousSolution with_free_variables(const HomogeneousSolution& solution, std::vector<Eigen::Index> chosen,
                                        double free_variable) {
  const Eigen::Index nullity = solution.nullity();
  const Eigen::Index n = solution.coefficients.rows();
  if (static_cast<Eigen::Index>(chosen.size()) != nullity)
    throw DependentFreeVariable(-1, "the number of chosen free variables differs from the nullity");
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (chosen[i] < 0 || chosen[i] >= n) throw DependentFreeVariable(chosen[i], "variable index out of range");
    for (std::size_t j = 0; j < i; ++j)
      if (chosen[j] == chosen[i]) throw DependentFreeVariable(chosen[i], "variable chosen twice");
  }
  // Report the first chosen variable that depends on those before it.
  auto first_dependent = [&](const Eigen::MatrixXd& rows_of_k) {
    const double scale = std::max(1.0, rows_of_k.size() > 0 ? rows_of_k.cwiseAbs().maxCoeff() : 1.0);
    std::vector<Eigen::Index> order(chosen.size());
    std::iota(order.begin(), order.end(), Eigen::Index{0});
    const auto independent = greedy_independent_rows(rows_of_k, order, free_variable * scale, nullity);
    for (std::size_t i = 0; i < chosen.size(); ++i)
      if (std::find(independent.begin(), independent.end(), static_cast<Eigen::Index>(i)) == independent.end())
        return chosen[i];
    return chosen.front();
  };

  HomogeneousSolution result = solution;
  std::vector<Eigen::Index> sorted = chosen;
  std::sort(sorted.begin(), sorted.end());
  result.free_variables = sorted;
  if (solution.exact_coefficients) {
    const RationalMatrix& k = *solution.exact_coefficients;
    RationalMatrix at_chosen(nullity, nullity);
    for (Eigen::Index i = 0; i < nullity; ++i)
      for (Eigen::Index j = 0; j < nullity; ++j) at_chosen(i, j) = k(sorted[static_cast<std::size_t>(i)], j);
    RationalMatrix inverse;
    bool invertible = false;
    if (flint_available()) {
      std::optional<RationalMatrix> found = flint_inverse(at_chosen);
      invertible = found.has_value();
      if (found) inverse = std::move(*found);
    } else {
      invertible = invert(at_chosen, inverse);
    }
    if (!invertible) {
      Eigen::MatrixXd rows_in_request_order(nullity, nullity);
      for (Eigen::Index i = 0; i < nullity; ++i)
        rows_in_request_order.row(i) = solution.coefficients.row(chosen[static_cast<std::size_t>(i)]);
      throw DependentFreeVariable(first_dependent(rows_in_request_order), "chosen variables are not independent");
    }
    result.exact_coefficients = k * inverse;
    result.coefficients = result.exact_coefficients->to_double();
    return result;
  }
  Eigen::MatrixXd at_chosen(nullity, nullity), in_request_order(nullity, nullity);
  for (Eigen::Index i = 0; i < nullity; ++i) {
    at_chosen.row(i) = solution.coefficients.row(sorted[static_cast<std::size_t>(i)]);
    in_request_order.row(i) = solution.coefficients.row(chosen[static_cast<std::size_t>(i)]);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(at_chosen);
  const auto& sv = svd.singularValues();
  if (nullity > 0 && sv(nullity - 1) <= free_variable * std::max(1.0, sv(0)))
    throw DependentFreeVariable(first_dependent(in_request_order), "chosen variables are not independent");
  result.coefficients = solution.coefficients * at_chosen.inverse();
  clean_small(result.coefficients);
  for (Eigen::Index j = 0; j < nullity; ++j)
    result.coefficients.row(sorted[static_cast<std::size_t>(j)]) = Eigen::RowVectorXd::Unit(nullity, j);
  return result;
}

}  // namespace kinestat::linalg
