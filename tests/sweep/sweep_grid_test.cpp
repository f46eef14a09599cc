// SPDX-License-Identifier: BSD-3-Clause
// The arithmetic of design sweeps (design/sweep_grid.hpp). Expected values follow from the
// definitions in docs/sweep.md (row-major numbering, v mod N shards), worked out by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>

#include "kinestat/design/sweep_grid.hpp"

namespace {

using namespace kinestat::design;

TEST(SweepGrid, RangeHitsBothEndsAndTheMiddleExactly) {
  const auto values = range_values(-1.0, 1.0, 20);
  ASSERT_EQ(values.size(), 21u);
  EXPECT_EQ(values.front(), -1.0);
  EXPECT_EQ(values.back(), 1.0);
  EXPECT_EQ(values[10], 0.0);  // (−1·10 + 1·10) / 20, exact
  EXPECT_EQ(values[5], -0.5);  // (−1·15 + 1·5) / 20
  // 0.1 to 0.3: the naive from + (to − from) would end at 0.30000000000000004.
  EXPECT_EQ(range_values(0.1, 0.3, 7).back(), 0.3);
  EXPECT_TRUE(range_values(0, 1, 0).empty());
}

// −1e308 to 1e308 in 4 steps: −1e308·3 overflows, yet every value lies between the ends.
// By hand: −1e308·(3/4) + 1e308·(1/4) = −5e307, then 0, then 5e307 (each within an ulp).
TEST(SweepGrid, EndsNearTheLargestDoubleGiveFiniteValues) {
  const auto values = range_values(-1e308, 1e308, 4);
  ASSERT_EQ(values.size(), 5u);
  EXPECT_EQ(values.front(), -1e308);
  EXPECT_DOUBLE_EQ(values[1], -5e307);
  EXPECT_EQ(values[2], 0.0);
  EXPECT_DOUBLE_EQ(values[3], 5e307);
  EXPECT_EQ(values.back(), 1e308);
  EXPECT_EQ(range_value(-1e308, 1e308, 2, 4), 0.0);
  // Ends of one sign near the largest double: still finite, still between them.
  const double largest = std::numeric_limits<double>::max();
  for (long long k = 0; k <= 3; ++k) {
    const double v = range_value(largest, largest / 2, k, 3);
    EXPECT_TRUE(std::isfinite(v)) << k;
    EXPECT_LE(v, largest);
    EXPECT_GE(v, largest / 2);
  }
}

TEST(SweepGrid, VariantsAreNumberedRowMajorFirstParameterSlowest) {
  const std::vector<std::size_t> sizes{2, 3};
  ASSERT_EQ(*variant_count(sizes), 6u);
  EXPECT_EQ(variant_position(0, sizes), (std::vector<std::size_t>{0, 0}));
  EXPECT_EQ(variant_position(2, sizes), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(variant_position(3, sizes), (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(variant_position(5, sizes), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(*variant_count({}), 1u);
  EXPECT_FALSE(variant_count({1000000, 1000000, 2}));  // 2·10¹² > kMaxSweepVariants
  EXPECT_FALSE(variant_count({3, 0}));
}

TEST(SweepGrid, ShardsPartitionTheVariants) {
  for (std::uint64_t count : {0u, 1u, 7u, 1000u}) {
    for (std::uint64_t n : {1u, 3u, 4u, 9u}) {
      std::multiset<std::uint64_t> taken;
      std::uint64_t sizes = 0;
      for (std::uint64_t i = 0; i < n; ++i) {
        sizes += shard_size(count, {i, n});
        for (std::uint64_t v = 0; v < count; ++v)
          if (in_shard(v, {i, n})) taken.insert(v);
      }
      EXPECT_EQ(taken.size(), count);
      EXPECT_EQ(std::set<std::uint64_t>(taken.begin(), taken.end()).size(), count);
      EXPECT_EQ(sizes, count);
    }
  }
  EXPECT_EQ(shard_size(10, {1, 4}), 3u);  // 1, 5, 9
  EXPECT_EQ(shard_size(10, {3, 4}), 2u);  // 3, 7
}

TEST(SweepGrid, ShardOptionIsIndexSlashCount) {
  ASSERT_TRUE(parse_shard("0/4"));
  EXPECT_EQ(parse_shard("3/4")->index, 3u);
  EXPECT_EQ(parse_shard("3/4")->count, 4u);
  for (const char* bad : {"4/4", "1/0", "-1/4", "+1/4", "1/4x", "a/b", "1", "/4", "0/", " 0/4", "0/10000000000000"})
    EXPECT_FALSE(parse_shard(bad)) << bad;
}

TEST(SweepGrid, LiteralsReadBackAsTheSameDouble) {
  for (double value : {0.1, 28.01, 1e-7, -2.5e300, 30.000000000000004, 1.0 / 3.0}) {
    const std::string literal = number_literal(value);
    EXPECT_EQ(std::strtod(literal.c_str(), nullptr), value) << literal;
  }
  EXPECT_EQ(number_literal(-0.0), "0");
  EXPECT_EQ(number_literal(0.1), "0.1");
  EXPECT_EQ(number_literal(28), "28");
}

}  // namespace
