#include "kinestat/report/markup_escape.hpp"

namespace kinestat::report {

std::string markup_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: {
        // XML 1.0 has no way to write C0 control characters (other than tab and line ends)
        // and a terminal would act on them: U+FFFD stands in for them.
        const auto byte = static_cast<unsigned char>(c);
        if ((byte < 0x20 && c != '\t' && c != '\n' && c != '\r') || byte == 0x7F) out += "\xEF\xBF\xBD";
        else out += c;
      }
    }
  }
  return out;
}

}  // namespace kinestat::report
