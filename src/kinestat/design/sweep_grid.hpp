// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The variants of a design sweep (docs/sweep.md): the values of each swept parameter, their
// Cartesian product numbered in row-major order, and the deterministic slice of it that one
// shard of a distributed run takes. Pure arithmetic: no model, no file.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kinestat::design {

/// Most variants one sweep may have (10¹²): far beyond any run, small enough that variant
/// numbers, products and shard counts never overflow.
inline constexpr std::uint64_t kMaxSweepVariants = 1'000'000'000'000ULL;
/// Most values one ranged parameter may take (steps + 1).
inline constexpr long long kMaxSweepSteps = 10'000'000;

/// Value k of `steps + 1` values from `from` to `to` in equal steps: (from·(steps − k) + to·k) /
/// steps, so value 0 is `from` and value `steps` is `to` exactly (in the model's units); where
/// that sum overflows a double (ends near ±1e308), from·((steps − k)/steps) + to·(k/steps),
/// which cannot. `steps` ≥ 1, 0 ≤ k ≤ steps, `from` and `to` finite: the value is finite.
double range_value(double from, double to, long long k, long long steps);
/// The `steps + 1` values range_value(from, to, k, steps), k = 0 … steps. `steps` ≥ 1 and
/// ≤ kMaxSweepSteps (else none), `from` and `to` finite.
std::vector<double> range_values(double from, double to, long long steps);

/// The number of variants of a grid whose parameters take `sizes[p]` values each (the product;
/// 1 for no parameter), or nothing when it exceeds kMaxSweepVariants or a size is 0.
std::optional<std::uint64_t> variant_count(const std::vector<std::size_t>& sizes);

/// The value index of every parameter for variant `variant` (0-based, < variant_count(sizes)):
/// row-major order, the first parameter varying slowest and the last fastest.
std::vector<std::size_t> variant_position(std::uint64_t variant, const std::vector<std::size_t>& sizes);

/// One of `count` shards of a sweep: it takes the variants v with v mod count == index
/// (round-robin, so variants whose cost grows along a parameter spread evenly).
struct SweepShard {
  std::uint64_t index = 0;  ///< 0-based, < count
  std::uint64_t count = 1;  ///< ≥ 1
};

/// `--shard I/N` as a shard: whole numbers without sign, 0 ≤ I < N ≤ kMaxSweepVariants;
/// nothing for anything else.
std::optional<SweepShard> parse_shard(std::string_view text);

/// Whether shard `shard` takes variant `variant`.
bool in_shard(std::uint64_t variant, const SweepShard& shard);

/// The variants of `shard` among `count` variants, ascending.
std::uint64_t shard_size(std::uint64_t count, const SweepShard& shard);

/// `value` as the shortest decimal literal that reads back as the same double ("0.3",
/// "30.000000000000004", "1e-07"); -0 is written "0". The literal a variant's model file gets.
std::string number_literal(double value);

}  // namespace kinestat::design
