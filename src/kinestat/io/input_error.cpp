// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/input_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "kinestat/io/printable_text.hpp"

namespace kinestat::io {

namespace {

// Words (runs without spaces) longer than this are shortened, and the whole problem text too,
// so that echoing a 70,000-character name still gives a readable one-line message.
constexpr std::size_t kMaxWordBytes = 120;
constexpr std::size_t kKeptWordBytes = 60;
constexpr std::size_t kMaxProblemBytes = 400;

// The longest prefix of `text` of at most `bytes` bytes that ends on a UTF-8 character boundary.
std::size_t utf8_prefix(std::string_view text, std::size_t bytes) {
  if (bytes >= text.size()) return text.size();
  while (bytes > 0 && (static_cast<unsigned char>(text[bytes]) & 0xC0) == 0x80) --bytes;
  return bytes;
}

std::string shortened(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    const std::string_view word(text.data() + i, end - i);
    if (word.size() > kMaxWordBytes) {
      out += word.substr(0, utf8_prefix(word, kKeptWordBytes));
      out += fmt::format("\u2026 ({} bytes)", word.size());
    } else {
      out += word;
    }
    if (end < text.size()) out += ' ';
    i = end + 1;
  }
  if (out.size() > kMaxProblemBytes) out = out.substr(0, utf8_prefix(out, kMaxProblemBytes)) + "\u2026";
  return out;
}

std::string format_message(const SourceLocation& where, const std::string& problem) {
  // Keep the message on one line even if a caller passes a multi-line problem text, and show
  // any other control character a name brings along as an escape.
  std::string flat = problem;
  for (char& ch : flat) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  flat = shortened(printable_text(flat));
  const std::string file = where.file.empty() ? "<input>" : printable_text(where.file);
  if (where.line <= 0) return fmt::format("{}: error: {}", file, flat);
  return fmt::format("{}:{}:{}: error: {}", file, where.line, where.column, flat);
}
}  // namespace

InputError::InputError(SourceLocation where, const std::string& problem)
    : Error(format_message(where, problem), where), problem_(problem) {}  // not moved: read first

}  // namespace kinestat::io
