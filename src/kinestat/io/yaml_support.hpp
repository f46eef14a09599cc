// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading kinestat model files (YAML, or JSON which is YAML too): the text is read through a
// bounded reader and parsed event by event into a ModelTree, with every limit (bytes, nesting,
// nodes with aliases expanded, one document) enforced while reading. The helpers give positions
// for error messages, strict maps (unknown and duplicate keys are errors) and exact numbers.
// The parser itself stays inside yaml_support.cpp.

#include <gmpxx.h>

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/model_tree.hpp"

namespace kinestat::io {

/// Limits on what a model file may be; each error message names the limit it hit.
struct ReadingLimits {
  std::size_t max_bytes = std::size_t{64} << 20;  ///< size of the file or stream (64 MiB)
  int max_nesting = 64;                           ///< lists and maps inside each other
  /// Nodes of the document with every alias counted as the nodes it stands for; bounds both
  /// memory (≈ 24 bytes a node) and the work of the readers that walk the tree.
  std::size_t max_nodes = std::size_t{1} << 24;
};

/// A number read from a model file: its double value, and its exact rational value when the
/// literal is an integer, a decimal or a decimal in scientific notation (e.g. "0.01", "1e-3").
struct ExactNumber {
  double value = 0.0;
  std::optional<mpq_class> exact;  ///< empty only for literals that are not rational
};

/// Reads at most `limits.max_bytes` bytes from the file at `path` (a regular file, a device,
/// a FIFO...): never reads an endless source to its end. Throws InputError if the path is a
/// folder, cannot be read, or holds more than the limit.
std::string read_model_text(const std::string& path, const ReadingLimits& limits = {});
/// The same for an open stream (standard input); `source` names it in messages.
std::string read_model_text(std::istream& in, const std::string& source, const ReadingLimits& limits = {});

/// The file being read, so that every helper can say where a problem is.
class YamlFile {
 public:
  /// Parses `text` (YAML or JSON) that came from `path`. Throws InputError for malformed YAML,
  /// an empty document, more than one document, a string with control characters (checked
  /// after unescaping), or input over the limits.
  static YamlFile parse(std::string path, const std::string& text, const ReadingLimits& limits = {});
  /// Reads (bounded) and parses the file at `path`; "-" is standard input (named "<stdin>" in
  /// messages). Throws InputError if it cannot be read.
  static YamlFile load(const std::string& path, const ReadingLimits& limits = {});

  TreeNode root() const { return tree_->root(); }
  const std::string& path() const { return path_; }
  /// Nodes stored (aliases stored once).
  std::size_t node_count() const { return tree_->node_count(); }

  /// Location of `node` (1-based line and column).
  SourceLocation where(const TreeNode& node) const;
  /// Throws InputError at `node` with `problem`.
  [[noreturn]] void fail(const TreeNode& node, const std::string& problem) const;
  /// A notice at `node` ("file:line:column: note: problem"): something read that the user
  /// should write differently, which does not change the model: kept in notices(), which the
  /// readers carry into io::ModelFile::notices and the caller shows (the command: on standard
  /// error and in the JSON report's `notices`).
  void notice(const TreeNode& node, const std::string& problem) const;
  /// The notices of this file kept so far (copies of a YamlFile share them).
  const std::vector<std::string>& notices() const { return *notices_; }

  /// A map whose keys must all be in `allowed`; duplicate keys are errors.
  void check_keys(const TreeNode& map, std::string_view what, std::initializer_list<std::string_view> allowed) const;
  void check_keys(const TreeNode& map, std::string_view what, const std::vector<std::string>& allowed) const;
  /// True exactly when check_keys(map, what, allowed) passes: `map` is a map of at most 16
  /// distinct scalar keys, each in `allowed`. Prepares no message (for a reader's success path:
  /// call check_keys when this is false, for the error).
  bool keys_allowed(const TreeNode& map, std::initializer_list<std::string_view> allowed) const;
  /// `map[key]`, or InputError naming the map and the key if it is missing.
  TreeNode required(const TreeNode& map, std::string_view key, std::string_view what) const;
  /// `map[key]` if present, otherwise an undefined node.
  TreeNode optional(const TreeNode& map, std::string_view key) const;

  /// Reads a finite number; NaN, infinities and non-numbers are errors.
  ExactNumber number(const TreeNode& node, std::string_view what) const;
  /// Reads an integer (no fraction part).
  long long integer(const TreeNode& node, std::string_view what) const;
  /// Reads a non-empty scalar string.
  std::string string(const TreeNode& node, std::string_view what) const;
  /// Reads a sequence of numbers whose length is one of `lengths`.
  std::vector<ExactNumber> numbers(const TreeNode& node, std::string_view what,
                                   std::initializer_list<std::size_t> lengths) const;
  /// Fills values[0, count) and returns true when `list` is a list of `count` scalars that
  /// decimal_toward_zero reads; numbers(list, what, {count}) then gives the same values. False
  /// otherwise (numbers() then gives the values or the error). Prepares no message.
  bool plain_numbers(const TreeNode& list, std::size_t count, double* values) const;
  /// Reads a sequence node (errors if `node` is not a sequence).
  void expect_sequence(const TreeNode& node, std::string_view what) const;
  void expect_map(const TreeNode& node, std::string_view what) const;

 private:
  YamlFile(std::string path, std::shared_ptr<const ModelTree> tree)
      : path_(std::move(path)), tree_(std::move(tree)), notices_(std::make_shared<std::vector<std::string>>()) {}
  std::string path_;
  std::shared_ptr<const ModelTree> tree_;
  std::shared_ptr<std::vector<std::string>> notices_;
};

/// read(file), with the notices `file` gave before an InputError carried by that error: an older
/// spelling read as format version 1 meant it often explains the error that follows, and the
/// command prints the notices before the error line.
template <class Read>
auto keeping_notices(const YamlFile& file, Read&& read) -> decltype(read(file)) {
  try {
    return read(file);
  } catch (InputError& error) {
    if (error.notices().empty()) error.set_notices(file.notices());
    throw;
  }
}

/// Significant digits of a decimal literal ("0.8660254" -> 7, "-1.50e3" -> 3, "0" -> 1).
int significant_digits(std::string_view literal);

/// Parses a decimal literal exactly ("-1.25e-3" -> -1/800). Empty if it is not one.
std::optional<mpq_class> parse_exact_decimal(std::string_view literal);

/// The double YamlFile::number gives for a decimal literal — its exact value rounded towards
/// zero, as GMP's mpq_get_d does — found with 64- and 128-bit integers instead of GMP. Empty
/// when the literal is not a decimal (see parse_exact_decimal), has more than 19 significant
/// digits, or its value is not a normal double between 1e-300 and 1e300 in magnitude (zero is
/// read): YamlFile::number decides those by exact arithmetic.
std::optional<double> decimal_toward_zero(std::string_view literal);

/// The `kind:` of a model document ("network" when absent). Checks `kinestat: 1`.
std::string model_kind(const YamlFile& file);

/// The key `"$schema"` that a model or sweep spec may carry at its root (the JSON Schema it
/// follows, for editors and validators); readers accept it and ignore its value.
inline constexpr std::string_view kSchemaKey = "$schema";

}  // namespace kinestat::io
