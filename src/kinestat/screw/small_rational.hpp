// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An exact rational with 64-bit numerator and denominator, for building coupling bases without
// GMP when the geometry's numbers are short (integer or few-digit decimal coordinates). Every
// operation is exact or throws SmallRational::Overflow, so a caller can fall back to GMP; the
// value is then the same rational GMP would compute. The basis construction itself is written
// once for both scalars (coupling_basis.cpp, vector3.hpp): this class supplies the arithmetic,
// sgn, abs_less and exact_sqrt that it uses.

#include <cmath>
#include <cstdint>
#include <optional>

#include "kinestat/linalg/rational_matrix.hpp"

namespace kinestat::screw {

class SmallRational {
 public:
  /// Thrown when a numerator or denominator would leave the 64-bit range.
  struct Overflow {};

  SmallRational() = default;
  SmallRational(std::int64_t integer) : num_(integer) {}  // NOLINT(google-explicit-constructor): integers convert

  /// `value` exactly, or empty when its numerator or denominator does not fit in 64 bits.
  static std::optional<SmallRational> from(const linalg::Rational& value);

  std::int64_t num() const { return num_; }
  std::int64_t den() const { return den_; }
  int sign() const { return (num_ > 0) - (num_ < 0); }

  friend SmallRational operator+(const SmallRational& a, const SmallRational& b);
  friend SmallRational operator-(const SmallRational& a, const SmallRational& b) { return a + (-b); }
  friend SmallRational operator*(const SmallRational& a, const SmallRational& b);
  friend SmallRational operator/(const SmallRational& a, const SmallRational& b);
  SmallRational operator-() const;
  SmallRational& operator+=(const SmallRational& b) { return *this = *this + b; }
  SmallRational& operator-=(const SmallRational& b) { return *this = *this - b; }
  friend bool operator==(const SmallRational& a, const SmallRational& b) { return a.num_ == b.num_ && a.den_ == b.den_; }
  /// |a| < |b|, exactly.
  friend bool abs_less(const SmallRational& a, const SmallRational& b);

  /// The double nearest the value in the direction of zero (rounded toward zero), as
  /// GMP's mpq_get_d rounds, so both paths give the same bits. Never throws.
  double to_double() const;

  /// The exact square root when the value is the square of a rational, else empty (also for
  /// negative values).
  std::optional<SmallRational> exact_sqrt() const;

  /// -1, 0 or 1, as GMP's sgn.
  friend int sgn(const SmallRational& a) { return a.sign(); }
  /// As the member, for the scalar-generic vector operations (vector3.hpp).
  friend std::optional<SmallRational> exact_sqrt(const SmallRational& a) { return a.exact_sqrt(); }

 private:
  SmallRational(std::int64_t num, std::int64_t den, bool) : num_(num), den_(den) {}
  static SmallRational reduced(std::int64_t num, std::int64_t den);

  std::int64_t num_ = 0;
  std::int64_t den_ = 1;  // > 0, coprime with num_
};

}  // namespace kinestat::screw
