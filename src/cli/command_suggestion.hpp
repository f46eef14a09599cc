// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An unknown subcommand names the nearest one (`kinestat analyse` -> "did you mean 'analyze'?"),
// where CLI11 alone would say only that a subcommand is required.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kinestat::cli {

/// The edit distance between `a` and `b` (insertions, deletions, substitutions and swaps of
/// neighbouring characters, one each: optimal string alignment).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name in `names` nearest to `word`, when it is near enough to be a misspelling of it (at
/// most 2 edits, and fewer than half the word's length); nothing otherwise.
std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& names);

/// When the first argument is not an option and names no subcommand of `app`: the one-line
/// error for it ("kinestat: error: unknown command 'analyse'; did you mean 'analyze'?"), which
/// the command prints before exiting 2. Nothing otherwise.
std::optional<std::string> unknown_command_message(const CLI::App& app, int argc, const char* const* argv);

}  // namespace kinestat::cli
