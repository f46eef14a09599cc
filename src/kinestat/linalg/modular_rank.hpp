// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact ranks by arithmetic modulo a prime. The rank of a rational matrix reduced modulo p is
// never above its rank over the rationals (a minor that vanishes over Q vanishes mod p), and it
// equals it unless p divides one of the nonzero maximal minors — unlikely for a large prime.
// So a modular rank is a certain lower bound, found in machine integers at the cost of one
// elimination, where GMP elimination grows its numbers with every step.

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

#include "kinestat/linalg/rational_matrix.hpp"

namespace kinestat::linalg {

/// The primes kinestat reduces modulo: 2^61 − 1 and 2^31 − 1 (both Mersenne primes). Fixed,
/// not drawn at run time, so the same input gives the same report.
inline constexpr std::uint64_t kModularPrimes[] = {2305843009213693951ULL, 2147483647ULL};

/// A dense matrix over GF(p), row-major, entries in [0, p).
struct ModularMatrix {
  Eigen::Index rows = 0, cols = 0;
  std::uint64_t prime = kModularPrimes[0];
  std::vector<std::uint64_t> entries;

  ModularMatrix() = default;
  ModularMatrix(Eigen::Index r, Eigen::Index c, std::uint64_t p)
      : rows(r), cols(c), prime(p), entries(static_cast<std::size_t>(r * c), 0) {}
  std::uint64_t& operator()(Eigen::Index r, Eigen::Index c) { return entries[static_cast<std::size_t>(r * cols + c)]; }
};

/// `value` modulo `prime`, or nothing when its denominator is a multiple of the prime.
std::optional<std::uint64_t> reduce(const Rational& value, std::uint64_t prime);

/// The rational matrix modulo `prime`, or nothing when a denominator is a multiple of it.
std::optional<ModularMatrix> reduce(const RationalMatrix& m, std::uint64_t prime);

/// Rank over GF(p) by Gaussian elimination (destroys nothing: works on a copy).
Eigen::Index modular_rank(ModularMatrix m);

/// Outcome of a modular rank: the largest rank over the primes tried (a certain lower bound
/// of the rank over the rationals) and how many primes agreed on it.
struct ModularRank {
  Eigen::Index rank = 0;
  int primes = 0;        ///< primes that could be used (denominators not multiples of them)
  int agreeing = 0;      ///< primes that gave `rank`
};

/// Rank of a rational matrix modulo every prime of kModularPrimes.
ModularRank modular_rank(const RationalMatrix& m);

}  // namespace kinestat::linalg
