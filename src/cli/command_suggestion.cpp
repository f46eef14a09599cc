// SPDX-License-Identifier: BSD-3-Clause
#include "cli/command_suggestion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "kinestat/io/printable_text.hpp"

namespace kinestat::cli {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Rows i-2, i-1 and i of the dynamic programme over prefixes of a and b.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[b.size()];
}

std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& names) {
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const std::string& name : names) {
    const std::size_t distance = edit_distance(word, name);
    if (!best || distance < best_distance) {
      best = name;
      best_distance = distance;
    }
  }
  // Two edits catch the usual slips (analyse, strucure, raport); a short word is only a
  // misspelling when most of it survives.
  if (!best || best_distance > 2 || 2 * best_distance >= word.size()) return std::nullopt;
  return best;
}

std::optional<std::string> unknown_command_message(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2 || argv[1] == nullptr) return std::nullopt;
  const std::string_view word = argv[1];
  if (word.empty() || word.front() == '-') return std::nullopt;
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  if (std::find(names.begin(), names.end(), word) != names.end()) return std::nullopt;
  const std::string shown = io::input_excerpt(word);
  if (const auto nearest = nearest_name(word, names))
    return fmt::format("kinestat: error: unknown command '{}'; did you mean '{}'?", shown, *nearest);
  return fmt::format("kinestat: error: unknown command '{}'; the commands are {} (kinestat --help)", shown, fmt::join(names, ", "));
}

}  // namespace kinestat::cli
