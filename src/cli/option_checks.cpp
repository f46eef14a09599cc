// SPDX-License-Identifier: BSD-3-Clause
#include "cli/option_checks.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "kinestat/error.hpp"
#include "kinestat/io/input_error.hpp"

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

// ELEMENT=VALUE split at the last '=' (element names may hold one); none without an '='.
std::optional<std::pair<std::string, std::string>> split_named(const std::string& text) {
  const std::size_t equals = text.rfind('=');
  if (equals == std::string::npos) return std::nullopt;
  return std::pair{text.substr(0, equals), text.substr(equals + 1)};
}

}  // namespace

CLI::Option* add_misfit_option(CLI::App& command, std::vector<std::string>& texts, const std::string& about) {
  const CLI::Validator format(
      [](std::string& text) -> std::string {
        const auto named = split_named(text);
        if (!named) return positive_finite_number()(text);  // the plain VALUE, as before
        if (named->first.empty()) return fmt::format("'{}' names no element: expected ELEMENT=VALUE such as d1=0.01", text);
        const auto value = parse_double(named->second);
        if (!value || !std::isfinite(*value) || *value < 0)
          return fmt::format("'{}' is not a length zero or more: expected ELEMENT=VALUE such as d1=0.01", named->second);
        return {};
      },
      "");  // the type name below says what is expected
  return command
      .add_option("--misfit", texts,
                  about + ". VALUE: every element's misfit; ELEMENT=VALUE (repeat --misfit for each element): that element's, "
                          "the others then the plain VALUE if given, else none (docs/stiffness.md)")
      ->check(format)
      ->type_name("VALUE|ELEMENT=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

std::optional<framework::MisfitTolerance> misfit_tolerance(const std::vector<std::string>& texts) {
  if (texts.empty()) return std::nullopt;
  framework::MisfitTolerance tolerance;
  for (const std::string& text : texts) {
    if (const auto named = split_named(text)) {
      if (!tolerance.per_element.emplace(named->first, *parse_double(named->second)).second)
        throw Error(fmt::format("--misfit: element '{}' is given twice; give each element once", named->first));
    } else {
      if (tolerance.value) throw Error("--misfit: the plain VALUE (every element's misfit) is given twice; give it once");
      tolerance.value = *parse_double(text);
    }
  }
  return tolerance;
}

void check_misfit_elements(const framework::FrameworkModel& model, const std::optional<framework::MisfitTolerance>& tolerance,
                           const std::string& path) {
  if (!tolerance) return;
  if (const std::optional<std::string> unknown = framework::unknown_misfit_element(model, *tolerance))
    throw io::InputError({path, 1, 1}, fmt::format("--misfit: the model has no element named '{}'", *unknown));
}

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
