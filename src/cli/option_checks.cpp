// SPDX-License-Identifier: BSD-3-Clause
#include "cli/option_checks.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace kinestat::cli {

namespace {

// Parses all of `text` as a double; empty on anything else.
std::optional<double> parse_double(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  if (errno == ERANGE && std::isfinite(value) && value != 0) errno = 0;  // subnormal: fine
  if (errno == ERANGE) return value == 0 ? 0.0 : HUGE_VAL;
  return value;
}

}  // namespace

CLI::Validator positive_finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = parse_double(text);
        if (!value) return fmt::format("'{}' is not a number: expected a positive number such as 1e-9", text);
        if (!std::isfinite(*value))
          return fmt::format("'{}' is not finite: expected a positive number such as 1e-9", text);
        if (*value <= 0) return fmt::format("'{}' is not positive: expected a positive number such as 1e-9", text);
        return {};
      },
      "POSITIVE");
}

CLI::Validator non_negative_whole_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        bool digits = !text.empty();
        for (char c : text) digits = digits && std::isdigit(static_cast<unsigned char>(c));
        if (!digits) return fmt::format("'{}' is not a whole number >= 0", text);
        if (text.size() > 18) return fmt::format("'{}' is too large", text.substr(0, 20) + (text.size() > 20 ? "…" : ""));
        return {};
      },
      "COUNT");
}

void add_fail_unless_option(CLI::App& command, std::string& condition) {
  command
      .add_option("--fail-unless", condition,
                  "Exit with status 1 (after the report) unless the verdict is this: exactly-constrained (for design "
                  "checks in CI; 0 then means exactly constrained, 2 bad input)")
      ->check(CLI::IsMember({"exactly-constrained"}));
}

int verdict_exit_code(const std::string& condition, const design::Verdict& verdict) {
  if (condition == "exactly-constrained" && !verdict.exactly_constrained) return kExitVerdictNotAsRequired;
  return 0;
}

}  // namespace kinestat::cli
