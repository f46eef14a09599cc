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

}  // namespace kinestat::linalg
