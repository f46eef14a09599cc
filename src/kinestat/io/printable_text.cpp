// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/printable_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

namespace kinestat::io {

namespace {

// The code point of the well-formed character of `length` bytes at text[i].
std::uint32_t code_point(std::string_view text, std::size_t i, std::size_t length) {
  static constexpr unsigned char kLeadMask[] = {0, 0x7F, 0x1F, 0x0F, 0x07};
  std::uint32_t code = static_cast<unsigned char>(text[i]) & kLeadMask[length];
  for (std::size_t k = 1; k < length; ++k) code = (code << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3Fu);
  return code;
}

bool acted_on(std::uint32_t code) {
  return (code >= 0x80 && code <= 0x9F) || code == 0x2028 || code == 0x2029 || (code >= 0x202A && code <= 0x202E) ||
         (code >= 0x2066 && code <= 0x2069);
}

}  // namespace

std::size_t utf8_character_length(std::string_view text, std::size_t i) {
  const auto byte = static_cast<unsigned char>(text[i]);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
  if (byte < 0x80) return 1;
  if (byte >= 0xC2 && byte <= 0xDF) length = 2;
  else if (byte == 0xE0) length = 3, low = 0xA0;
  else if ((byte >= 0xE1 && byte <= 0xEC) || byte == 0xEE || byte == 0xEF) length = 3;
  else if (byte == 0xED) length = 3, high = 0x9F;
  else if (byte == 0xF0) length = 4, low = 0x90;
  else if (byte >= 0xF1 && byte <= 0xF3) length = 4;
  else if (byte == 0xF4) length = 4, high = 0x8F;
  else return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    const auto next = static_cast<unsigned char>(text[i + k]);
    if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF)) return 0;
  }
  return length;
}

std::string printable_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t length = utf8_character_length(text, i);
    const auto byte = static_cast<unsigned char>(text[i]);
    if (length == 0 || (length == 1 && (byte < 0x20 || byte == 0x7F))) {
      out += fmt::format("\\x{:02X}", byte);
      ++i;
      continue;
    }
    const std::uint32_t code = code_point(text, i, length);
    if (acted_on(code)) out += fmt::format("\\u{{{:04X}}}", code);
    else out.append(text.substr(i, length));
    i += length;
  }
  return out;
}

std::string input_excerpt(std::string_view text) {
  const std::size_t line_end = std::min(text.find_first_of("\r\n"), text.size());
  std::size_t end = 0, characters = 0;
  while (end < line_end && characters < kExcerptCharacters) {
    const std::size_t length = utf8_character_length(text, end);
    end += length == 0 ? 1 : length;
    ++characters;
  }
  end = std::min(end, line_end);
  return printable_text(text.substr(0, end)) + (end < text.size() ? "\u2026" : "");
}

}  // namespace kinestat::io
