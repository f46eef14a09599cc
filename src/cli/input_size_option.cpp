// SPDX-License-Identifier: BSD-3-Clause
#include "cli/input_size_option.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <string>
#include <utility>

#include "kinestat/io/text_file.hpp"

namespace kinestat::cli {

namespace {

constexpr std::uint64_t kLargestInputSize = std::uint64_t{1} << 40;  // 1 TiB: far beyond any machine's memory here

// The command's setting: the bytes --max-input-size gave, or nothing (the defaults).
std::optional<std::size_t>& input_size_setting() {
  static std::optional<std::size_t> bytes;
  return bytes;
}

}  // namespace

std::optional<std::size_t> parse_byte_size(std::string_view text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data() || value == 0) return std::nullopt;
  std::string unit(end, text.data() + text.size());
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  static constexpr std::array<std::pair<const char*, int>, 4> kUnits = {{{"K", 10}, {"M", 20}, {"G", 30}, {"T", 40}}};
  int shift = 0;
  if (!unit.empty() && unit != "B") {
    const auto found = std::find_if(kUnits.begin(), kUnits.end(), [&](const auto& u) {
      return unit == u.first || unit == std::string(u.first) + "IB" || unit == std::string(u.first) + "B";
    });
    if (found == kUnits.end()) return std::nullopt;
    shift = found->second;
  }
  if (value > (kLargestInputSize >> shift)) return std::nullopt;
  return static_cast<std::size_t>(value << shift);
}

void add_input_size_option(CLI::App& command) {
  command
      .add_option_function<std::string>(
          "--max-input-size",
          [](const std::string& text) {
            const std::optional<std::size_t> bytes = parse_byte_size(text);
            if (!bytes) throw CLI::ValidationError("--max-input-size", "expected a size such as 512MiB, 2GiB or 100000000 (bytes), up to 1TiB; got '" + text + "'");
            input_size_setting() = *bytes;
          },
          "Largest model file read (default 64MiB), e.g. 512MiB or 2GiB: for YAML models of more than about 10^6 bars; a "
          "bar table (.bars, docs/formats.md) is 3-4 times smaller")
      ->type_name("SIZE");
}

io::ReadingLimits model_reading_limits() {
  const std::optional<std::size_t>& bytes = input_size_setting();
  return bytes ? io::reading_limits_for(*bytes) : io::ReadingLimits{};
}

}  // namespace kinestat::cli
