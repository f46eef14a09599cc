#pragma once
// JSON reports as text, in one place so every report is printed the same way.

#include <nlohmann/json.hpp>

#include <string>

namespace kinestat::report {

/// `value` as text with `indent` spaces per level (-1: one line), and a final newline when
/// indented. Bytes that are not UTF-8 (model readers reject them, but names can also come
/// from elsewhere, such as the command line) become U+FFFD instead of an exception.
std::string json_text(const nlohmann::ordered_json& value, int indent = 2);

/// `value` to ten significant digits, as every report prints numbers: enough to read, and stable
/// against last-bit noise of the SVD; below kPrintedZero in magnitude, and -0, printed as 0.
double rounded_for_report(double value);

}  // namespace kinestat::report
