// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/sweep_line.hpp"

#include "kinestat/report/json_text.hpp"

namespace kinestat::report {

namespace {

nlohmann::ordered_json identity(const SweepVariant& variant) {
  nlohmann::ordered_json line;
  line["variant"] = variant.index;
  line["of"] = variant.count;
  if (variant.file.empty()) line["parameters"] = variant.parameters;
  else line["file"] = variant.file;
  return line;
}

}  // namespace

const std::vector<std::string>& sweep_report_keys() {
  static const std::vector<std::string> keys{"kind",        "verdict",     "rows",           "cols",    "rank",
                                             "mechanisms",  "self_stresses", "FN",            "CN",      "rank_motion",
                                             "rank_action", "classification", "generic",       "rank_decision", "rank_evidence"};
  return keys;
}

nlohmann::ordered_json sweep_line(const SweepVariant& variant, const nlohmann::ordered_json& report, bool full) {
  nlohmann::ordered_json line = identity(variant);
  if (full) {
    for (const auto& [key, value] : report.items()) line[key] = value;
  } else {
    for (const std::string& key : sweep_report_keys())
      if (const auto it = report.find(key); it != report.end()) line[key] = *it;
  }
  add_versions(line);
  return line;
}

nlohmann::ordered_json sweep_error_line(const SweepVariant& variant, const std::string& error) {
  nlohmann::ordered_json line = identity(variant);
  line["error"] = error;
  add_versions(line);
  return line;
}

std::string sweep_line_text(const nlohmann::ordered_json& line) { return json_text(line, -1) + "\n"; }

}  // namespace kinestat::report
