// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/screw/small_rational.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace kinestat::screw {

namespace {

using Int = std::int64_t;
constexpr Int kMin = std::numeric_limits<Int>::min();
constexpr Int kExactDouble = Int{1} << 53;

Int checked_mul(Int a, Int b) {
  Int product = 0;
  if (__builtin_mul_overflow(a, b, &product) || product == kMin) throw SmallRational::Overflow{};
  return product;
}

Int checked_add(Int a, Int b) {
  Int sum = 0;
  if (__builtin_add_overflow(a, b, &sum) || sum == kMin) throw SmallRational::Overflow{};
  return sum;
}

Int magnitude(Int a) { return a < 0 ? -a : a; }  // a != kMin by construction

// floor(sqrt(x)) for x >= 0 if x is a perfect square, else -1.
Int perfect_square_root(Int x) {
  auto root = static_cast<Int>(std::sqrt(static_cast<double>(x)));
  for (Int r = root > 0 ? root - 1 : 0; r <= root + 1; ++r) {
    Int square = 0;
    if (__builtin_mul_overflow(r, r, &square)) break;
    if (square == x) return r;
  }
  return -1;
}

}  // namespace

std::optional<SmallRational> SmallRational::from(const linalg::Rational& value) {
  const mpz_srcptr num = mpq_numref(value.get_mpq_t());
  const mpz_srcptr den = mpq_denref(value.get_mpq_t());
  if (!mpz_fits_slong_p(num) || !mpz_fits_slong_p(den)) return std::nullopt;
  const long n = mpz_get_si(num), d = mpz_get_si(den);
  if (n == std::numeric_limits<long>::min()) return std::nullopt;
  return SmallRational(static_cast<Int>(n), static_cast<Int>(d), true);  // GMP keeps it canonical
}

SmallRational SmallRational::reduced(Int num, Int den) {
  if (den == 0) throw Overflow{};  // division by zero: not a value this class represents
  if (den < 0) {
    num = -num;
    den = -den;
  }
  const Int g = std::gcd(magnitude(num), den);
  return {num / g, den / g, true};
}

SmallRational SmallRational::operator-() const { return {-num_, den_, true}; }

SmallRational operator+(const SmallRational& a, const SmallRational& b) {
  if (a.num_ == 0) return b;
  if (b.num_ == 0) return a;
  if (a.den_ == 1 && b.den_ == 1) return {checked_add(a.num_, b.num_), 1, true};  // integers: no gcd needed
  const Int g = std::gcd(a.den_, b.den_);
  const Int num = checked_add(checked_mul(a.num_, b.den_ / g), checked_mul(b.num_, a.den_ / g));
  return SmallRational::reduced(num, checked_mul(a.den_, b.den_ / g));
}

SmallRational operator*(const SmallRational& a, const SmallRational& b) {
  if (a.num_ == 0 || b.num_ == 0) return {};
  if (a.den_ == 1 && b.den_ == 1) return {checked_mul(a.num_, b.num_), 1, true};
  const Int g1 = std::gcd(magnitude(a.num_), b.den_), g2 = std::gcd(magnitude(b.num_), a.den_);
  return {checked_mul(a.num_ / g1, b.num_ / g2), checked_mul(a.den_ / g2, b.den_ / g1), true};
}

SmallRational operator/(const SmallRational& a, const SmallRational& b) {
  if (b.num_ == 0) throw SmallRational::Overflow{};
  const SmallRational inverse = b.num_ < 0 ? SmallRational(-b.den_, -b.num_, true) : SmallRational(b.den_, b.num_, true);
  return a * inverse;
}

bool abs_less(const SmallRational& a, const SmallRational& b) {
  return checked_mul(magnitude(a.num_), b.den_) < checked_mul(magnitude(b.num_), a.den_);
}

namespace {

// n / d rounded toward zero to a double, for 0 < n, d < 2^63: the quotient's leading 53 bits by
// long division, the fraction and lower bits dropped (what mpq_get_d computes). Numbers from
// numpy carry 17 digits, beyond the 2^53 that the division in doubles below handles.
double truncated_quotient(std::uint64_t n, std::uint64_t d) {
  std::uint64_t whole = n / d, rest = n % d, mantissa = 0;
  int exponent = 0;
  constexpr std::uint64_t kTop = std::uint64_t{1} << 52;
  if (whole >= 2 * kTop) {
    exponent = std::bit_width(whole) - 53;
    mantissa = whole >> exponent;
  } else {
    mantissa = whole;
    while (mantissa < kTop) {  // the next bit of the fraction
      rest <<= 1;  // rest < d < 2^63: no overflow
      const bool bit = rest >= d;
      if (bit) rest -= d;
      mantissa = (mantissa << 1) | static_cast<std::uint64_t>(bit);
      --exponent;
    }
  }
  return std::ldexp(static_cast<double>(mantissa), exponent);  // exact: mantissa < 2^53
}

}  // namespace

double SmallRational::to_double() const {
  if (num_ == 0) return 0.0;
  if (magnitude(num_) > kExactDouble || den_ > kExactDouble) {
    const double q = truncated_quotient(static_cast<std::uint64_t>(magnitude(num_)), static_cast<std::uint64_t>(den_));
    return num_ < 0 ? -q : q;
  }
  const auto n = static_cast<double>(num_), d = static_cast<double>(den_);
  double q = n / d;  // rounded to nearest
  // n − q d is exact in one fused operation; its sign says whether the rounding went away from
  // zero, and then the neighbour toward zero is the truncated quotient.
  const double remainder = std::fma(-q, d, n);
  if ((n > 0 && remainder < 0) || (n < 0 && remainder > 0)) q = std::nextafter(q, 0.0);
  return q;
}

std::optional<SmallRational> SmallRational::exact_sqrt() const {
  if (num_ < 0) return std::nullopt;
  const Int n = perfect_square_root(num_), d = perfect_square_root(den_);
  if (n < 0 || d < 0) return std::nullopt;
  return SmallRational(n, d, true);
}

}  // namespace kinestat::screw
