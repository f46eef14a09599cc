#include "kinestat/io/input_error.hpp"

#include <fmt/format.h>

namespace kinestat::io {

namespace {
std::string format_message(const SourceLocation& where, const std::string& problem) {
  // Keep the message on one line even if a caller passes a multi-line problem text.
  std::string flat = problem;
  for (char& ch : flat) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  const std::string file = where.file.empty() ? "<input>" : where.file;
  if (where.line <= 0) return fmt::format("{}: error: {}", file, flat);
  return fmt::format("{}:{}:{}: error: {}", file, where.line, where.column, flat);
}
}  // namespace

InputError::InputError(SourceLocation where, const std::string& problem)
    : std::runtime_error(format_message(where, problem)), where_(std::move(where)), problem_(problem) {}

}  // namespace kinestat::io
