#include "kinestat/io/yaml_support.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace kinestat::io {

namespace {

// yaml-cpp parses recursively; bound the nesting so hostile input cannot overflow the stack.
constexpr int kMaxFlowNesting = 64;
// Block nesting shows as indentation and "- - -" runs at the start of a line.
constexpr std::size_t kMaxLeadingIndicators = 512;
constexpr std::size_t kMaxInputBytes = std::size_t{64} << 20;  // 64 MiB
// Aliases let a small file stand for an enormous tree ("billion laughs"); readers walk the
// tree, so its expanded size is bounded.
constexpr std::size_t kMaxExpandedNodes = std::size_t{4} << 20;

// Where the first character a model file may not contain stands (1-based line and column,
// columns counted in characters, and its byte offset), or line 0: bytes that are not
// well-formed UTF-8 (overlong forms, surrogates and code points above U+10FFFF rejected, as in
// RFC 3629), and C0 control characters other than tab, line feed and carriage return, and DEL,
// which YAML does not allow either. yaml-cpp passes both through into names (it even turns a
// NUL and the next character into a lone byte 0xA0), and a name must be printable in every
// report, JSON included.
struct TextPosition {
  int line = 0, column = 0;
  std::size_t offset = 0;
  bool control = false;  ///< a control character, not a UTF-8 error
};
TextPosition first_unreadable_character(const std::string& text) {
  int line = 1, column = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
    if (byte < 0x80) length = 1;
    else if (byte >= 0xC2 && byte <= 0xDF) length = 2;
    else if (byte == 0xE0) length = 3, low = 0xA0;
    else if ((byte >= 0xE1 && byte <= 0xEC) || byte == 0xEE || byte == 0xEF) length = 3;
    else if (byte == 0xED) length = 3, high = 0x9F;
    else if (byte == 0xF0) length = 4, low = 0x90;
    else if (byte >= 0xF1 && byte <= 0xF3) length = 4;
    else if (byte == 0xF4) length = 4, high = 0x8F;
    else return {line, column, i, false};
    if (i + length > text.size()) return {line, column, i, false};
    for (std::size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF)) return {line, column, i, false};
    }
    if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r') || byte == 0x7F) return {line, column, i, true};
    if (byte == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    i += length;
  }
  return {};
}

// The first line whose run of leading spaces and block indicators is longer than the limit.
int excessive_block_nesting(const std::string& text) {
  int line = 1;
  std::size_t run = 0;
  bool at_start = true;
  for (char ch : text) {
    if (ch == '\n') {
      ++line;
      run = 0;
      at_start = true;
      continue;
    }
    if (!at_start) continue;
    if (ch == ' ' || ch == '-' || ch == '?' || ch == ':' || ch == '\t') {
      if (++run > kMaxLeadingIndicators) return line;
    } else {
      at_start = false;
    }
  }
  return 0;
}

// Counts the nodes of the tree as readers would see it (aliases expanded), up to the limit.
bool expands_beyond_limit(const YAML::Node& root) {
  std::vector<YAML::Node> stack{root};
  std::size_t count = 0;
  while (!stack.empty()) {
    const YAML::Node node = stack.back();
    stack.pop_back();
    if (++count > kMaxExpandedNodes) return true;
    if (node.IsSequence()) {
      for (const auto& item : node) stack.push_back(item);
    } else if (node.IsMap()) {
      for (const auto& entry : node) {
        stack.push_back(entry.first);
        stack.push_back(entry.second);
      }
    }
  }
  return false;
}

// Finds the first place where "[" / "{" nesting exceeds the limit, outside quoted strings
// and comments. Returns {line, column} (1-based) or {0, 0}.
std::pair<int, int> excessive_flow_nesting(const std::string& text) {
  int depth = 0, line = 1, column = 0;
  char quote = 0;
  bool comment = false;
  for (char ch : text) {
    ++column;
    if (ch == '\n') {
      ++line;
      column = 0;
      comment = false;
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (ch == quote) quote = 0;
      continue;
    }
    if (ch == '"' || ch == '\'') {
      quote = ch;
    } else if (ch == '#') {
      comment = true;
    } else if (ch == '[' || ch == '{') {
      if (++depth > kMaxFlowNesting) return {line, column};
    } else if (ch == ']' || ch == '}') {
      depth = std::max(0, depth - 1);
    }
  }
  return {0, 0};
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return fmt::format("'{}'", node.Scalar());
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    default: return "nothing";
  }
}

}  // namespace

int significant_digits(std::string_view literal) {
  std::string digits;
  for (char ch : literal) {
    if (ch == 'e' || ch == 'E') break;
    if (std::isdigit(static_cast<unsigned char>(ch))) digits += ch;
  }
  const auto first = digits.find_first_not_of('0');
  return first == std::string::npos ? 1 : static_cast<int>(digits.size() - first);
}

std::optional<mpq_class> parse_exact_decimal(std::string_view literal) {
  std::size_t i = 0;
  bool negative = false;
  if (i < literal.size() && (literal[i] == '+' || literal[i] == '-')) negative = literal[i++] == '-';
  std::string digits;
  long long exponent = 0;
  bool any_digit = false;
  for (; i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i])); ++i) {
    digits += literal[i];
    any_digit = true;
  }
  if (i < literal.size() && literal[i] == '.') {
    ++i;
    for (; i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i])); ++i) {
      digits += literal[i];
      --exponent;
      any_digit = true;
    }
  }
  if (!any_digit) return std::nullopt;
  if (i < literal.size() && (literal[i] == 'e' || literal[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < literal.size() && (literal[i] == '+' || literal[i] == '-')) exp_negative = literal[i++] == '-';
    long long e = 0;
    bool exp_digit = false;
    for (; i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i])); ++i) {
      e = e * 10 + (literal[i] - '0');
      exp_digit = true;
      if (e > 4000) return std::nullopt;  // beyond double range: not a sensible length
    }
    if (!exp_digit) return std::nullopt;
    exponent += exp_negative ? -e : e;
  }
  if (i != literal.size()) return std::nullopt;
  // Strip leading zeros so huge zero-padded literals cost nothing.
  const auto first = digits.find_first_not_of('0');
  digits = first == std::string::npos ? "0" : digits.substr(first);
  if (digits.size() > 4000) return std::nullopt;
  mpz_class numerator(digits, 10);
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  mpq_class value = exponent < 0 ? mpq_class(numerator, power) : mpq_class(numerator * power);
  value.canonicalize();
  return negative ? mpq_class(-value) : value;
}

YamlFile YamlFile::parse(std::string path, const std::string& text) {
  if (text.size() > kMaxInputBytes) {
    throw InputError({path, 1, 1}, fmt::format("file is larger than the {} MiB limit", kMaxInputBytes >> 20));
  }
  if (const TextPosition bad = first_unreadable_character(text); bad.line > 0) {
    const auto byte = static_cast<unsigned char>(text[bad.offset]);
    throw InputError({path, bad.line, bad.column},
                     bad.control ? fmt::format("control character U+{:04X} is not allowed in a model file", byte)
                                 : fmt::format("byte 0x{:02X} is not UTF-8: model files are UTF-8 text (save UTF-16 "
                                               "or Latin-1 files as UTF-8)",
                                               byte));
  }
  if (auto [line, column] = excessive_flow_nesting(text); line > 0) {
    throw InputError({path, line, column}, fmt::format("nesting deeper than {} levels", kMaxFlowNesting));
  }
  if (const int line = excessive_block_nesting(text); line > 0) {
    throw InputError({path, line, 1}, fmt::format("indentation or block nesting deeper than {} levels", kMaxLeadingIndicators));
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw InputError({path, error.mark.line + 1, error.mark.column + 1},
                     fmt::format("malformed YAML: {}", error.msg));
  }
  if (!root.IsDefined() || root.IsNull()) throw InputError({path, 1, 1}, "empty model file: expected a map");
  if (expands_beyond_limit(root)) {
    throw InputError({path, 1, 1}, fmt::format("the document expands to more than {} nodes (through aliases?)", kMaxExpandedNodes));
  }
  YamlFile file(std::move(path), root);
  file.expect_map(root, "the model file");
  return file;
}

YamlFile YamlFile::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError({path, 0, 0}, "cannot read file");
  return parse(path, buffer.str());
}

SourceLocation YamlFile::where(const YAML::Node& node) const {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {path_, 0, 0};
  return {path_, mark.line + 1, mark.column + 1};
}

void YamlFile::fail(const YAML::Node& node, const std::string& problem) const { throw InputError(where(node), problem); }

void YamlFile::expect_map(const YAML::Node& node, std::string_view what) const {
  if (!node.IsMap()) fail(node, fmt::format("{} must be a map, found {}", what, describe(node)));
}

void YamlFile::expect_sequence(const YAML::Node& node, std::string_view what) const {
  if (!node.IsSequence()) fail(node, fmt::format("{} must be a list, found {}", what, describe(node)));
}

void YamlFile::check_keys(const YAML::Node& map, std::string_view what,
                          std::initializer_list<std::string_view> allowed) const {
  check_keys(map, what, std::vector<std::string>(allowed.begin(), allowed.end()));
}

void YamlFile::check_keys(const YAML::Node& map, std::string_view what, const std::vector<std::string>& allowed) const {
  expect_map(map, what);
  std::set<std::string> seen;
  for (const auto& entry : map) {
    if (!entry.first.IsScalar()) fail(entry.first, fmt::format("keys of {} must be names", what));
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (const auto& name : allowed) list += (list.empty() ? "" : ", ") + name;
      fail(entry.first, fmt::format("unknown key '{}' in {}; expected one of: {}", key, what, list));
    }
    if (!seen.insert(key).second) fail(entry.first, fmt::format("duplicate key '{}' in {}", key, what));
  }
}

YAML::Node YamlFile::required(const YAML::Node& map, std::string_view key, std::string_view what) const {
  YAML::Node value = optional(map, key);
  if (!value.IsDefined()) fail(map, fmt::format("{} is missing the key '{}'", what, key));
  return value;
}

YAML::Node YamlFile::optional(const YAML::Node& map, std::string_view key) const {
  for (const auto& entry : map) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) return entry.second;
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

ExactNumber YamlFile::number(const YAML::Node& node, std::string_view what) const {
  if (!node.IsScalar()) fail(node, fmt::format("{} must be a number, found {}", what, describe(node)));
  const std::string& text = node.Scalar();
  ExactNumber result;
  result.exact = parse_exact_decimal(text);
  if (result.exact) {
    result.value = result.exact->get_d();
    const bool underflow = result.value == 0.0 && sgn(*result.exact) != 0;
    if (!std::isfinite(result.value) || underflow) fail(node, fmt::format("{} is out of range: '{}'", what, text));
    return result;
  }
  fail(node, fmt::format("{} must be a finite number, found '{}'", what, text));
}

long long YamlFile::integer(const YAML::Node& node, std::string_view what) const {
  const ExactNumber n = number(node, what);
  if (!n.exact || n.exact->get_den() != 1 || std::abs(n.value) > 1e15) {
    fail(node, fmt::format("{} must be an integer, found '{}'", what, node.Scalar()));
  }
  return static_cast<long long>(n.value);
}

std::string YamlFile::string(const YAML::Node& node, std::string_view what) const {
  if (!node.IsScalar() || node.Scalar().empty()) {
    fail(node, fmt::format("{} must be a name, found {}", what, describe(node)));
  }
  return node.Scalar();
}

std::vector<ExactNumber> YamlFile::numbers(const YAML::Node& node, std::string_view what,
                                           std::initializer_list<std::size_t> lengths) const {
  expect_sequence(node, what);
  if (std::find(lengths.begin(), lengths.end(), node.size()) == lengths.end()) {
    std::string expected;
    for (std::size_t n : lengths) expected += (expected.empty() ? "" : " or ") + std::to_string(n);
    fail(node, fmt::format("{} must have {} numbers, found {}", what, expected, node.size()));
  }
  std::vector<ExactNumber> values;
  for (const auto& item : node) values.push_back(number(item, what));
  return values;
}

std::string model_kind(const YamlFile& file) {
  const YAML::Node& root = file.root();
  const YAML::Node version = file.required(root, "kinestat", "the model file");
  if (file.integer(version, "the format version 'kinestat'") != 1) {
    file.fail(version, "unsupported format version: expected 'kinestat: 1'");
  }
  const YAML::Node kind = file.optional(root, "kind");
  if (!kind.IsDefined()) return "network";
  const std::string name = file.string(kind, "'kind'");
  if (name != "network" && name != "framework" && name != "structure") {
    file.fail(kind, fmt::format("unknown kind '{}'; expected network, framework or structure", name));
  }
  return name;
}

}  // namespace kinestat::io
