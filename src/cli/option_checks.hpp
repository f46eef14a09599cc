// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Checks of numeric command-line options with messages that say what is expected. CLI11's
// own range checks let NaN through and print their bounds with all 309 digits of DBL_MAX.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "kinestat/network/network_result.hpp"

namespace kinestat::cli {

/// A finite number > 0 (rank tolerances): NaN, infinities, zero and negatives are refused.
CLI::Validator positive_finite_number();
/// A whole number >= 0 (counts and 1-based indices, 0 meaning "none").
CLI::Validator non_negative_whole_number();

/// The name of the first numeric result of a network analysis that is not finite (the values
/// given, or the model's geometry, overflowed a double), or nothing when all are finite.
std::optional<std::string> first_non_finite_result(const network::NetworkResult& result);

}  // namespace kinestat::cli
