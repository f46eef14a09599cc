// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An ordered set of body numbers in [0, n): a bitmap with a summary word per 64 words.
// The structural search inserts and erases a body once or twice each and lists the set in
// order only now and then; a balanced tree (std::set) made each insertion a cache miss and
// an allocation, a fifth of a 10^6-body decomposition. Listing costs O(n / 4096 + size).

#include <bit>
#include <cstdint>
#include <vector>

namespace kinestat::structure {

class BodySet {
 public:
  /// An empty set of numbers in [0, size).
  explicit BodySet(int size)
      : words_(static_cast<std::size_t>(size + 63) / 64, 0), summary_((words_.size() + 63) / 64, 0) {}

  void insert(int body) {
    const std::size_t w = static_cast<std::size_t>(body) / 64;
    const std::uint64_t bit = std::uint64_t{1} << (body % 64);
    if (words_[w] & bit) return;
    words_[w] |= bit;
    summary_[w / 64] |= std::uint64_t{1} << (w % 64);
    ++count_;
  }

  void erase(int body) {
    const std::size_t w = static_cast<std::size_t>(body) / 64;
    const std::uint64_t bit = std::uint64_t{1} << (body % 64);
    if (!(words_[w] & bit)) return;
    words_[w] &= ~bit;
    if (words_[w] == 0) summary_[w / 64] &= ~(std::uint64_t{1} << (w % 64));
    --count_;
  }

  int size() const { return count_; }

  /// The members in ascending order.
  std::vector<int> ascending() const {
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(count_));
    for (std::size_t s = 0; s < summary_.size(); ++s)
      for (std::uint64_t used = summary_[s]; used != 0; used &= used - 1) {
        const std::size_t w = s * 64 + static_cast<std::size_t>(std::countr_zero(used));
        for (std::uint64_t bits = words_[w]; bits != 0; bits &= bits - 1)
          out.push_back(static_cast<int>(w * 64) + std::countr_zero(bits));
      }
    return out;
  }

  /// The members in descending order.
  std::vector<int> descending() const {
    std::vector<int> out = ascending();
    return {out.rbegin(), out.rend()};
  }

 private:
  std::vector<std::uint64_t> words_;    // bit b % 64 of word b / 64: body b is a member
  std::vector<std::uint64_t> summary_;  // bit w % 64 of summary word w / 64: word w is not zero
  int count_ = 0;
};

}  // namespace kinestat::structure
