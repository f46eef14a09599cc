// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/markup_escape.hpp"

#include "kinestat/io/printable_text.hpp"

namespace kinestat::report {

std::string markup_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const std::size_t length = io::utf8_character_length(text, i);
    const auto byte = static_cast<unsigned char>(c);
    // XML 1.0 has no way to write C0 control characters (other than tab and line ends) and a
    // terminal would act on them and on C1 controls; a byte that is not UTF-8 would make the
    // document malformed: U+FFFD stands in for all of them.
    const bool c1 = length == 2 && byte == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    if (length == 0 || (byte < 0x20 && c != '\t' && c != '\n' && c != '\r') || byte == 0x7F || c1) {
      out += "\xEF\xBF\xBD";
      i += length == 0 ? 1 : length;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out.append(text, i, length);
    }
    i += length;
  }
  return out;
}

}  // namespace kinestat::report
