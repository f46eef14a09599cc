// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A fixed-seed pseudo-random sequence (SplitMix64) for random realisations: the same on every
// platform and standard library (std:: distributions are not), so reports stay byte-identical.

#include <cstdint>

namespace kinestat::linalg {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}

  /// The next 64 random bits.
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// A whole number in [-bound, bound] (bound below 2^62).
  std::int64_t integer(std::int64_t bound) {
    const auto span = static_cast<std::uint64_t>(2 * bound + 1);
    return static_cast<std::int64_t>(next() % span) - bound;
  }
  /// A double in [-1, 1).
  double symmetric() { return static_cast<double>(next() >> 11) * 0x1.0p-52 - 1.0; }

 private:
  std::uint64_t state_;
};

}  // namespace kinestat::linalg
