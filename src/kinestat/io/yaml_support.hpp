#pragma once
// Shared helpers for reading kinestat model files with yaml-cpp: positions for error
// messages, strict maps (unknown and duplicate keys are errors) and exact numbers.
// Used by every model reader in io/; nothing outside io/ includes yaml-cpp.

#include <gmpxx.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kinestat/io/input_error.hpp"

namespace kinestat::io {

/// A number read from a model file: its double value, and its exact rational value when the
/// literal is an integer, a decimal or a decimal in scientific notation (e.g. "0.01", "1e-3").
struct ExactNumber {
  double value = 0.0;
  std::optional<mpq_class> exact;  ///< empty only for literals that are not rational
};

/// The file being read, so that every helper can say where a problem is.
class YamlFile {
 public:
  /// Parses `text` (YAML or JSON) that came from `path`. Throws InputError for malformed YAML,
  /// an empty document, or input over the size and nesting limits.
  static YamlFile parse(std::string path, const std::string& text);
  /// Reads and parses the file at `path`. Throws InputError if it cannot be read.
  static YamlFile load(const std::string& path);

  const YAML::Node& root() const { return root_; }
  const std::string& path() const { return path_; }

  /// Location of `node` (1-based line and column).
  SourceLocation where(const YAML::Node& node) const;
  /// Throws InputError at `node` with `problem`.
  [[noreturn]] void fail(const YAML::Node& node, const std::string& problem) const;

  /// A map whose keys must all be in `allowed`; duplicate keys are errors.
  void check_keys(const YAML::Node& map, std::string_view what,
                  std::initializer_list<std::string_view> allowed) const;
  void check_keys(const YAML::Node& map, std::string_view what, const std::vector<std::string>& allowed) const;
  /// `map[key]`, or InputError naming the map and the key if it is missing.
  YAML::Node required(const YAML::Node& map, std::string_view key, std::string_view what) const;
  /// `map[key]` if present, otherwise an undefined node.
  YAML::Node optional(const YAML::Node& map, std::string_view key) const;

  /// Reads a finite number; NaN, infinities and non-numbers are errors.
  ExactNumber number(const YAML::Node& node, std::string_view what) const;
  /// Reads an integer (no fraction part).
  long long integer(const YAML::Node& node, std::string_view what) const;
  /// Reads a non-empty scalar string.
  std::string string(const YAML::Node& node, std::string_view what) const;
  /// Reads a sequence of numbers whose length is one of `lengths`.
  std::vector<ExactNumber> numbers(const YAML::Node& node, std::string_view what,
                                   std::initializer_list<std::size_t> lengths) const;
  /// Reads a sequence node (errors if `node` is not a sequence).
  void expect_sequence(const YAML::Node& node, std::string_view what) const;
  void expect_map(const YAML::Node& node, std::string_view what) const;

 private:
  YamlFile(std::string path, YAML::Node root) : path_(std::move(path)), root_(std::move(root)) {}
  std::string path_;
  YAML::Node root_;
};

/// Significant digits of a decimal literal ("0.8660254" -> 7, "-1.50e3" -> 3, "0" -> 1).
int significant_digits(std::string_view literal);

/// Parses a decimal literal exactly ("-1.25e-3" -> -1/800). Empty if it is not one.
std::optional<mpq_class> parse_exact_decimal(std::string_view literal);

/// The `kind:` of a model document ("network" when absent). Checks `kinestat: 1`.
std::string model_kind(const YamlFile& file);

}  // namespace kinestat::io
