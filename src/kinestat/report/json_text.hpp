// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// JSON reports as text, in one place so every report is printed the same way.

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace kinestat::report {

/// The version of the JSON report formats (analyze, structure, move, sweep lines): their keys and
/// what they mean (docs/report.md, schemas/report-v1.schema.json). Raised when a key is removed
/// or changes its meaning; a new key does not raise it.
inline constexpr int kReportVersion = 1;

/// kinestat's version, e.g. "0.1.0" (the project version CMake was given).
std::string_view kinestat_version();

/// Appends `kinestat_version` and `report_version` (kReportVersion) to the top level of a JSON
/// report, after its other keys (the verdict stays first). Replaces them when present.
void add_versions(nlohmann::ordered_json& report);

/// `value` as text with `indent` spaces per level (-1: one line), and a final newline when
/// indented. Bytes that are not UTF-8 (model readers reject them, but names can also come
/// from elsewhere, such as the command line) become U+FFFD instead of an exception.
std::string json_text(const nlohmann::ordered_json& value, int indent = 2);

/// An empty JSON object with room for `keys` keys. nlohmann's ordered_map is a std::vector of
/// (const key, value) pairs whose move may throw, so each time an object grows, every value
/// already in it is copied: an object that received a large array before its other keys copied
/// that array again at each growth (a tenth of a report with all its vectors).
nlohmann::ordered_json json_object(std::size_t keys);

/// `value` to ten significant digits, as every report prints numbers: enough to read, and stable
/// against last-bit noise of the SVD; below kPrintedZero in magnitude, and -0, printed as 0.
double rounded_for_report(double value);

}  // namespace kinestat::report
