// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One line of a design sweep's output (docs/sweep.md): which variant, what it is, and the keys
// of its `kinestat analyze --json` report that a sweep compares (or the whole report), as one
// line of JSON. Deterministic: the same variant gives the same bytes, whatever the shard.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace kinestat::report {

/// The keys of the analysis report a line carries, in this order where the report has them:
/// `kind`, `verdict`, framework counts (`rows`, `cols`, `rank`, `mechanisms`,
/// `self_stresses`), network counts (`FN`, `CN`, `rank_motion`, `rank_action`), `classification`,
/// `generic`, and the rank evidence (`rank_decision` of frameworks, with its `status`;
/// `rank_evidence` of networks).
const std::vector<std::string>& sweep_report_keys();

/// What a variant is: its parameters' values ({"h": 28.01}, in the model's units) or the file it
/// was read from.
struct SweepVariant {
  std::uint64_t index = 0;  ///< 0-based, in the spec's order
  std::uint64_t count = 0;  ///< variants in the sweep
  nlohmann::ordered_json parameters;  ///< an object, or null for a variant file
  std::string file;                   ///< the variant file as the spec writes it, or empty
};

/// `{"variant": i, "of": n, "parameters": {...} | "file": ..., <sweep_report_keys() of report>}`;
/// with `full`, every key of `report` instead.
nlohmann::ordered_json sweep_line(const SweepVariant& variant, const nlohmann::ordered_json& report, bool full);

/// The line of a variant that could not be analysed: `{"variant", "of", "parameters" | "file",
/// "error": message}` (the message `kinestat analyze` would print for that variant's file).
nlohmann::ordered_json sweep_error_line(const SweepVariant& variant, const std::string& error);

/// `line` as one line of text (no spaces, ending with a newline).
std::string sweep_line_text(const nlohmann::ordered_json& line);

}  // namespace kinestat::report
