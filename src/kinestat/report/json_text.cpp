#include "kinestat/report/json_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "kinestat/tolerances.hpp"

namespace kinestat::report {

std::string json_text(const nlohmann::ordered_json& value, int indent) {
  std::string text = value.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  if (indent >= 0) text += '\n';
  return text;
}

nlohmann::ordered_json json_object(std::size_t keys) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  object.get_ref<nlohmann::ordered_json::object_t&>().reserve(keys);
  return object;
}

double rounded_for_report(double value) {
  if (!std::isfinite(value)) return value;
  if (std::abs(value) < kPrintedZero) return 0.0;
  const double r = std::stod(fmt::format("{:.10g}", value));
  return r == 0.0 ? 0.0 : r;
}

}  // namespace kinestat::report
