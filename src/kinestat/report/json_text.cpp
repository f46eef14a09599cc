// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/json_text.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "kinestat/tolerances.hpp"

namespace kinestat::report {

std::string json_text(const nlohmann::ordered_json& value, int indent) {
  std::string text = value.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  if (indent >= 0) text += '\n';
  return text;
}

std::string_view kinestat_version() { return KINESTAT_PROJECT_VERSION; }

void add_versions(nlohmann::ordered_json& report) {
  if (!report.is_object()) return;
  report.erase("kinestat_version");  // a report copied into another (sweep --full) keeps one pair, last
  report.erase("report_version");
  report["kinestat_version"] = kinestat_version();
  report["report_version"] = kReportVersion;
}

nlohmann::ordered_json json_object(std::size_t keys) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  object.get_ref<nlohmann::ordered_json::object_t&>().reserve(keys);
  return object;
}

double rounded_for_report(double value) {
  if (!std::isfinite(value)) return value;
  if (std::abs(value) < kPrintedZero) return 0.0;
  // Ten significant digits and back, both correctly rounded (to_chars / from_chars: the same
  // digits as "{:.10g}" and strtod, without a string allocation for each of 10^5-10^6 numbers).
  char digits[32];
  const auto written = std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, 10);
  double r = 0.0;
  std::from_chars(digits, written.ptr, r);
  return r == 0.0 ? 0.0 : r;
}

}  // namespace kinestat::report
