#include "kinestat/report/json_text.hpp"

namespace kinestat::report {

std::string json_text(const nlohmann::ordered_json& value, int indent) {
  std::string text = value.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  if (indent >= 0) text += '\n';
  return text;
}

}  // namespace kinestat::report
