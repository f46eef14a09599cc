// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/rational_matrix.hpp"

#include <cassert>

namespace kinestat::linalg {

RationalMatrix RationalMatrix::transpose() const {
  RationalMatrix t(cols_, rows_);
  for (Eigen::Index r = 0; r < rows_; ++r)
    for (Eigen::Index c = 0; c < cols_; ++c) t(c, r) = (*this)(r, c);
  return t;
}

RationalMatrix RationalMatrix::operator*(const RationalMatrix& other) const {
  assert(cols_ == other.rows_);
  RationalMatrix product(rows_, other.cols_);
  for (Eigen::Index r = 0; r < rows_; ++r) {
    for (Eigen::Index k = 0; k < cols_; ++k) {
      const Rational& a = (*this)(r, k);
      if (sgn(a) == 0) continue;  // the matrices we multiply are sparse
      for (Eigen::Index c = 0; c < other.cols_; ++c) {
        if (sgn(other(k, c)) != 0) product(r, c) += a * other(k, c);
      }
    }
  }
  return product;
}

RationalMatrix RationalMatrix::operator+(const RationalMatrix& other) const {
  assert(rows_ == other.rows_ && cols_ == other.cols_);
  RationalMatrix sum = *this;
  for (std::size_t i = 0; i < data_.size(); ++i) sum.data_[i] += other.data_[i];
  return sum;
}

RationalMatrix RationalMatrix::operator-(const RationalMatrix& other) const {
  assert(rows_ == other.rows_ && cols_ == other.cols_);
  RationalMatrix difference = *this;
  for (std::size_t i = 0; i < data_.size(); ++i) difference.data_[i] -= other.data_[i];
  return difference;
}

RationalMatrix RationalMatrix::block(Eigen::Index row, Eigen::Index col, Eigen::Index rows, Eigen::Index cols) const {
  assert(row + rows <= rows_ && col + cols <= cols_);
  RationalMatrix b(rows, cols);
  for (Eigen::Index r = 0; r < rows; ++r)
    for (Eigen::Index c = 0; c < cols; ++c) b(r, c) = (*this)(row + r, col + c);
  return b;
}

void RationalMatrix::set_block(Eigen::Index row, Eigen::Index col, const RationalMatrix& source) {
  assert(row + source.rows_ <= rows_ && col + source.cols_ <= cols_);
  for (Eigen::Index r = 0; r < source.rows_; ++r)
    for (Eigen::Index c = 0; c < source.cols_; ++c) (*this)(row + r, col + c) = source(r, c);
}

RationalMatrix RationalMatrix::append_columns(const RationalMatrix& other) const {
  assert(rows_ == other.rows_);
  RationalMatrix joined(rows_, cols_ + other.cols_);
  joined.set_block(0, 0, *this);
  joined.set_block(0, cols_, other);
  return joined;
}

bool RationalMatrix::operator==(const RationalMatrix& other) const {
  return rows_ == other.rows_ && cols_ == other.cols_ && data_ == other.data_;
}

bool RationalMatrix::is_zero() const {
  for (const Rational& value : data_)
    if (sgn(value) != 0) return false;
  return true;
}

Eigen::MatrixXd RationalMatrix::to_double() const {
  Eigen::MatrixXd m(rows_, cols_);
  for (Eigen::Index r = 0; r < rows_; ++r)
    for (Eigen::Index c = 0; c < cols_; ++c) m(r, c) = (*this)(r, c).get_d();
  return m;
}

std::string to_string(const Rational& value) { return value.get_str(); }

RationalMatrix to_rational(const Eigen::MatrixXi& m) {
  RationalMatrix r(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) r(i, j) = m(i, j);
  return r;
}

}  // namespace kinestat::linalg
