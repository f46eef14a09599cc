// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/linalg/modular_rank.hpp"

#include <algorithm>

namespace kinestat::linalg {

namespace {

using u64 = std::uint64_t;
__extension__ using u128 = unsigned __int128;  // GCC and Clang; -Wpedantic wants the marker

constexpr u64 kMersenne61 = (u64{1} << 61) - 1;

// a * b mod p; the Mersenne prime 2^61 - 1 reduces with a shift and a mask instead of a
// 128-bit division, and products of residues below 2^32 fit in 64 bits.
u64 multiply(u64 a, u64 b, u64 p) {
  if (p == kMersenne61) {
    const u128 x = static_cast<u128>(a) * b;
    const u64 r = static_cast<u64>(x & kMersenne61) + static_cast<u64>(x >> 61);
    return r >= kMersenne61 ? r - kMersenne61 : r;
  }
  if (p < (u64{1} << 32)) return (a * b) % p;
  return static_cast<u64>((static_cast<u128>(a) * b) % p);
}

u64 power(u64 base, u64 exponent, u64 p) {
  u64 result = 1;
  for (; exponent > 0; exponent >>= 1, base = multiply(base, base, p))
    if (exponent & 1U) result = multiply(result, base, p);
  return result;
}

// Inverse by Fermat's little theorem (p is prime, a is not a multiple of it).
u64 inverse(u64 a, u64 p) { return power(a, p - 2, p); }

u64 residue(const mpz_class& z, u64 p) {
  // mpz_fdiv_ui takes an unsigned long, 64 bits on the platforms kinestat builds for.
  static_assert(sizeof(unsigned long) == sizeof(u64));
  return mpz_fdiv_ui(z.get_mpz_t(), static_cast<unsigned long>(p));
}

}  // namespace

std::optional<std::uint64_t> reduce(const Rational& value, std::uint64_t prime) {
  const u64 denominator = residue(value.get_den(), prime);
  if (denominator == 0) return std::nullopt;
  return multiply(residue(value.get_num(), prime), inverse(denominator, prime), prime);
}

std::optional<ModularMatrix> reduce(const RationalMatrix& m, std::uint64_t prime) {
  ModularMatrix out(m.rows(), m.cols(), prime);
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) {
      if (sgn(m(r, c)) == 0) continue;
      const auto value = reduce(m(r, c), prime);
      if (!value) return std::nullopt;
      out(r, c) = *value;
    }
  return out;
}

Eigen::Index modular_rank(ModularMatrix m) {
  const u64 p = m.prime;
  Eigen::Index rank = 0;
  for (Eigen::Index c = 0; c < m.cols && rank < m.rows; ++c) {
    Eigen::Index pivot = rank;
    while (pivot < m.rows && m(pivot, c) == 0) ++pivot;
    if (pivot == m.rows) continue;
    if (pivot != rank)
      for (Eigen::Index k = c; k < m.cols; ++k) std::swap(m(pivot, k), m(rank, k));
    const u64 scale = inverse(m(rank, c), p);
    for (Eigen::Index k = c; k < m.cols; ++k) m(rank, k) = multiply(m(rank, k), scale, p);
    for (Eigen::Index r = rank + 1; r < m.rows; ++r) {
      const u64 factor = m(r, c);
      if (factor == 0) continue;
      for (Eigen::Index k = c; k < m.cols; ++k) {
        const u64 subtract = multiply(factor, m(rank, k), p);
        m(r, k) = m(r, k) >= subtract ? m(r, k) - subtract : m(r, k) + (p - subtract);
      }
    }
    ++rank;
  }
  return rank;
}

ModularRank modular_rank(const RationalMatrix& m) {
  ModularRank result;
  std::vector<Eigen::Index> ranks;
  for (u64 p : kModularPrimes) {
    const auto reduced = reduce(m, p);
    if (!reduced) continue;
    ranks.push_back(modular_rank(*reduced));
  }
  result.primes = static_cast<int>(ranks.size());
  if (ranks.empty()) return result;
  result.rank = *std::max_element(ranks.begin(), ranks.end());
  result.agreeing = static_cast<int>(std::count(ranks.begin(), ranks.end(), result.rank));
  return result;
}

}  // namespace kinestat::linalg
