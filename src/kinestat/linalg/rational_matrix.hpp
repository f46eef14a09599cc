// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A dense matrix of exact rationals (GMP). Eigen is not used here because mpq_class is not an
// Eigen scalar out of the box and the algorithms we need (elimination) are simple.

#include <gmpxx.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace kinestat::linalg {

using Rational = mpq_class;

/// Row-major dense matrix of rationals.
class RationalMatrix {
 public:
  RationalMatrix() = default;
  RationalMatrix(Eigen::Index rows, Eigen::Index cols) : rows_(rows), cols_(cols), data_(size(rows, cols)) {}

  Eigen::Index rows() const { return rows_; }
  Eigen::Index cols() const { return cols_; }
  Rational& operator()(Eigen::Index r, Eigen::Index c) { return data_[index(r, c)]; }
  const Rational& operator()(Eigen::Index r, Eigen::Index c) const { return data_[index(r, c)]; }

  RationalMatrix transpose() const;
  RationalMatrix operator*(const RationalMatrix& other) const;
  RationalMatrix operator+(const RationalMatrix& other) const;
  RationalMatrix operator-(const RationalMatrix& other) const;
  /// Copy of the rows x cols block starting at (row, col).
  RationalMatrix block(Eigen::Index row, Eigen::Index col, Eigen::Index rows, Eigen::Index cols) const;
  /// Copies `source` into this matrix with its top-left corner at (row, col).
  void set_block(Eigen::Index row, Eigen::Index col, const RationalMatrix& source);
  /// [this other]: the columns of `other` appended.
  RationalMatrix append_columns(const RationalMatrix& other) const;
  bool operator==(const RationalMatrix& other) const;
  bool is_zero() const;
  /// Nearest doubles.
  Eigen::MatrixXd to_double() const;

 private:
  static std::size_t size(Eigen::Index rows, Eigen::Index cols) {
    return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  }
  std::size_t index(Eigen::Index r, Eigen::Index c) const {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) + static_cast<std::size_t>(c);
  }
  Eigen::Index rows_ = 0;
  Eigen::Index cols_ = 0;
  std::vector<Rational> data_;
};

/// Exact rank by elimination.
Eigen::Index exact_rank(const RationalMatrix& m);
/// Exact conversion of a double (every finite double is a rational).
RationalMatrix to_rational(const Eigen::MatrixXi& m);

/// Exact text of a rational: "3", "-1/2".
std::string to_string(const Rational& value);

}  // namespace kinestat::linalg
