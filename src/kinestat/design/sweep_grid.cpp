// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/sweep_grid.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>

namespace kinestat::design {

double range_value(double from, double to, long long k, long long steps) {
  if (k <= 0) return from;
  if (k >= steps) return to;
  const auto s = static_cast<double>(steps), t = static_cast<double>(k);
  // The weighted form is exact at both ends, unlike from + (to − from)·k/steps; its products
  // overflow only for ends near the largest double, where weights of at most 1 cannot.
  const double weighted = (from * (s - t) + to * t) / s;
  return std::isfinite(weighted) ? weighted : from * ((s - t) / s) + to * (t / s);
}

std::vector<double> range_values(double from, double to, long long steps) {
  std::vector<double> values;
  if (steps < 1 || steps > kMaxSweepSteps) return values;
  values.reserve(static_cast<std::size_t>(steps) + 1);
  for (long long k = 0; k <= steps; ++k) values.push_back(range_value(from, to, k, steps));
  return values;
}

std::optional<std::uint64_t> variant_count(const std::vector<std::size_t>& sizes) {
  std::uint64_t count = 1;
  for (const std::size_t size : sizes) {
    if (size == 0 || size > kMaxSweepVariants / count) return std::nullopt;
    count *= size;
  }
  return count;
}

std::vector<std::size_t> variant_position(std::uint64_t variant, const std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> position(sizes.size(), 0);
  for (std::size_t p = sizes.size(); p-- > 0;) {
    position[p] = static_cast<std::size_t>(variant % sizes[p]);
    variant /= sizes[p];
  }
  return position;
}

namespace {
std::optional<std::uint64_t> whole_number(std::string_view text) {
  if (text.empty() || text.size() > 13) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}
}  // namespace

std::optional<SweepShard> parse_shard(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const auto index = whole_number(text.substr(0, slash)), count = whole_number(text.substr(slash + 1));
  if (!index || !count || *count < 1 || *count > kMaxSweepVariants || *index >= *count) return std::nullopt;
  return SweepShard{*index, *count};
}

bool in_shard(std::uint64_t variant, const SweepShard& shard) { return variant % shard.count == shard.index; }

std::uint64_t shard_size(std::uint64_t count, const SweepShard& shard) {
  return count / shard.count + (shard.index < count % shard.count ? 1 : 0);
}

std::string number_literal(double value) {
  if (value == 0.0) return "0";
  return fmt::format("{}", value);
}

}  // namespace kinestat::design
