// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/yaml_support.hpp"

#include "kinestat/io/printable_text.hpp"
#include "kinestat/io/read_only_file.hpp"
#include "kinestat/io/text_file.hpp"

#include <fmt/format.h>
#include <yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <iostream>
#include <istream>
#include <new>
#include <set>
#include <unordered_map>

namespace kinestat::io {

namespace {

// Where the first character a model file may not contain stands (1-based line and column,
// columns counted in characters, and its byte offset), or line 0: bytes that are not
// well-formed UTF-8 (overlong forms, surrogates and code points above U+10FFFF rejected, as in
// RFC 3629), and C0 control characters other than tab, line feed and carriage return, DEL and
// the C1 controls U+0080-U+009F, which YAML does not allow either (U+0085 is a line end in
// YAML 1.1, which libyaml implements). A name must be printable in every report, JSON
// included. In the raw text, the line and paragraph separators U+2028 / U+2029 (more YAML 1.1
// line ends, which would shift every line number after them) and the noncharacters U+FFFE /
// U+FFFF are refused too. With `unescaped`, the text is an unescaped string, where carriage
// returns are not allowed but the separators are (written as escapes).
struct TextPosition {
  enum class Problem : std::uint8_t { none, utf8, control, separator, noncharacter };
  int line = 0, column = 0;
  std::size_t offset = 0;
  Problem problem = Problem::none;
};
TextPosition first_unreadable_character(std::string_view text, bool unescaped = false) {
  using Problem = TextPosition::Problem;
  int line = 1, column = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7F) {  // printable ASCII: the common case, one test
      ++column;
      ++i;
      continue;
    }
    const std::size_t length = utf8_character_length(text, i);
    if (length == 0) return {line, column, i, Problem::utf8};
    const bool allowed_control = byte == '\t' || byte == '\n' || (byte == '\r' && !unescaped);
    if ((byte < 0x20 && !allowed_control) || byte == 0x7F) return {line, column, i, Problem::control};
    // C1 controls (U+0080-U+009F) reach a terminal as escape sequences too.
    if (byte == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) return {line, column, i, Problem::control};
    if (!unescaped && byte == 0xE2 && text[i + 1] == '\x80' && (text[i + 2] == '\xA8' || text[i + 2] == '\xA9'))
      return {line, column, i, Problem::separator};
    if (!unescaped && byte == 0xEF && text[i + 1] == '\xBF' && (text[i + 2] == '\xBE' || text[i + 2] == '\xBF'))
      return {line, column, i, Problem::noncharacter};
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

// The first carriage return that is not followed by a line feed (line ends of classic Mac
// OS), refused by name: YAML parsers disagree on them (yaml-cpp took none, libyaml takes them
// as line ends) and so would the line numbers of every message. {line, column} 1-based, or
// line 0.
std::pair<int, int> lone_carriage_return(std::string_view text) {
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    } else if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) {
      return {line, static_cast<int>(i - line_start) + 1};
    }
  }
  return {0, 0};
}

// Block nesting shows as indentation and "- - -" runs at the start of a line; this cheap scan
// refuses absurd runs before the parser sees them (the parser's own nesting limit follows).
constexpr std::size_t kMaxLeadingIndicators = 512;

// The first line whose run of leading spaces and block indicators is longer than the limit.
int excessive_block_nesting(std::string_view text) {
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

// What a scan of the raw text finds before the parser runs: where flow nesting first passes the
// limit, and where the flow entries (separating commas) first pass the node limit. Both are cheap
// (one pass over the bytes) so that a file built to exhaust the parser is refused in a fraction
// of a second instead of after the parser has built tens of millions of nodes.
struct FlowScan {
  std::pair<int, int> too_deep{0, 0};     ///< line, column; 0, 0: within the limit
  std::pair<int, int> too_many{0, 0};     ///< line, column of the entry past the node limit
};

// Quoted scalars and comments are skipped. A comma inside a flow list or map separates two
// entries (plain scalars cannot contain one in flow context), and a line that starts with
// content holds at least one node, so commas plus content lines estimate the nodes from below;
// only the lines of a block scalar or a multi-line plain scalar count where no node starts, and
// 2^24 of those in a 64 MiB file is no model.
FlowScan scan_flow(std::string_view text, int max_depth, std::size_t max_nodes) {
  FlowScan scan;
  int depth = 0, line = 1, column = 0;
  std::size_t entries = 0;
  char quote = 0;
  bool comment = false, line_start = true;
  for (char ch : text) {
    ++column;
    if (ch == '\n') {
      ++line;
      column = 0;
      comment = false;
      line_start = true;
      continue;
    }
    if (comment) continue;
    if (line_start && !quote && ch != ' ' && ch != '\t' && ch != '\r') {
      line_start = false;
      if (ch != '#' && ch != ']' && ch != '}' && ch != ',' && ++entries > max_nodes && scan.too_many.first == 0)
        scan.too_many = {line, column};
    }
    if (quote) {
      if (ch == quote) quote = 0;
      continue;
    }
    if (ch == '"' || ch == '\'') {
      quote = ch;
    } else if (ch == '#') {
      comment = true;
    } else if (ch == '[' || ch == '{') {
      if (++depth > max_depth && scan.too_deep.first == 0) scan.too_deep = {line, column};
    } else if (ch == ']' || ch == '}') {
      depth = std::max(0, depth - 1);
    } else if (ch == ',' && depth > 0) {
      if (++entries > max_nodes && scan.too_many.first == 0) scan.too_many = {line, column};
    }
    if (scan.too_deep.first != 0 || scan.too_many.first != 0) break;
  }
  return scan;
}

// The tree is reserved for one node per this many bytes of text before it is built: model
// files have fewer (a generated lattice one per 6.7 bytes; flow lists of one-digit numbers, the
// densest, one per 2, then the tree grows as it would without the reservation).
constexpr std::size_t kBytesPerReservedNode = 4;

std::string nesting_message(bool flow, int limit) {
  return fmt::format("{} nesting deeper than {} levels, the nesting limit (lists and maps inside each other)",
                     flow ? "flow" : "block", limit);
}

// "U+HHHH" for the well-formed UTF-8 character at `offset` of `text`.
std::string code_point_text(std::string_view text, std::size_t offset) {
  const std::size_t length = std::max<std::size_t>(1, utf8_character_length(text, offset));
  auto code = static_cast<std::uint32_t>(static_cast<unsigned char>(text[offset]));
  if (length > 1) code &= 0x7Fu >> length;  // the payload bits of the lead byte
  for (std::size_t k = 1; k < length; ++k) code = (code << 6) | (static_cast<unsigned char>(text[offset + k]) & 0x3Fu);
  return fmt::format("U+{:04X}", code);
}

// The message for the first character of the raw text that a model file may not contain.
std::string unreadable_message(std::string_view text, const TextPosition& bad) {
  const auto byte = static_cast<unsigned char>(text[bad.offset]);
  switch (bad.problem) {
    case TextPosition::Problem::utf8:
      return fmt::format("byte 0x{:02X} is not UTF-8: model files are UTF-8 text (save UTF-16 or Latin-1 files as "
                         "UTF-8)",
                         byte);
    case TextPosition::Problem::separator:
      return fmt::format("the line separator {} is not allowed in a model file (YAML 1.1 takes it as a line end); "
                         "inside a double-quoted string, write it as the escape \\u{}",
                         code_point_text(text, bad.offset), code_point_text(text, bad.offset).substr(2));
    case TextPosition::Problem::noncharacter:
      return fmt::format("the noncharacter {} is not allowed in a model file", code_point_text(text, bad.offset));
    default: return fmt::format("control character {} is not allowed in a model file", code_point_text(text, bad.offset));
  }
}

// libyaml's event parser reading `text` in place (no copy), and the event it produced last.
class EventParser {
 public:
  explicit EventParser(std::string_view text) {
    if (yaml_parser_initialize(&parser_) == 0) throw std::bad_alloc();
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()), text.size());
  }
  EventParser(const EventParser&) = delete;
  EventParser& operator=(const EventParser&) = delete;
  ~EventParser() {
    release();
    yaml_parser_delete(&parser_);
  }
  /// The next event, or nullptr when the text is not well-formed YAML (see state()).
  const yaml_event_t* next() {
    release();
    if (yaml_parser_parse(&parser_, &event_) == 0) return nullptr;
    holding_ = true;
    return &event_;
  }
  const yaml_parser_t& state() const { return parser_; }

 private:
  void release() {
    if (holding_) yaml_event_delete(&event_);
    holding_ = false;
  }
  yaml_parser_t parser_{};
  yaml_event_t event_{};
  bool holding_ = false;
};

// 1-based line and column (in characters) of byte `offset` of `text`.
std::pair<int, int> position_of_offset(std::string_view text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') {
      ++line;
      column = 1;
    } else if ((byte & 0xC0) != 0x80) {
      ++column;
    }
  }
  return {line, column};
}

// The InputError for a text that libyaml refused: its problem at its position, and what it
// was reading (libyaml's context, or else the innermost open list or map, `open`) with where
// that starts. libyaml counts lines and columns from 0.
struct OpenCollection {
  bool defined = false, map = false, flow = false;
  std::uint32_t line = 0, column = 0;  ///< 1-based
};
InputError malformed(const std::string& path, std::string_view text, const yaml_parser_t& parser, const OpenCollection& open) {
  if (parser.error == YAML_MEMORY_ERROR) return InputError({path, 0, 0}, "out of memory while parsing the model file");
  std::string problem = parser.problem != nullptr ? parser.problem : "unknown problem";
  // The one escape error the reader names: a \u or \U escape of a UTF-16 surrogate (or past U+10FFFF).
  if (problem == "found invalid Unicode character escape code") {
    problem = "invalid unicode escape: a \\u or \\U escape of a UTF-16 surrogate (U+D800-U+DFFF) or above U+10FFFF";
  }
  if (parser.error == YAML_READER_ERROR) {
    const auto [line, column] = position_of_offset(text, parser.problem_offset);
    return InputError({path, line, column}, fmt::format("malformed YAML: {}", problem));
  }
  const yaml_mark_t& mark = parser.problem_mark;
  std::string context;
  const bool own_context = parser.context != nullptr && (parser.context_mark.line != mark.line ||
                                                        parser.context_mark.column != mark.column);
  if (own_context) {
    context = fmt::format(" ({} that starts at line {}, column {})", parser.context, parser.context_mark.line + 1,
                          parser.context_mark.column + 1);
  } else if (open.defined) {
    context = fmt::format(" (in the {} {} that starts at line {}, column {})", open.flow ? "flow" : "block",
                          open.map ? "map" : "list", open.line, open.column);
  }
  return InputError({path, static_cast<int>(mark.line + 1), static_cast<int>(mark.column + 1)},
                    fmt::format("malformed YAML: {}{}", problem, context));
}

std::string_view event_text(const yaml_char_t* text) {
  return text == nullptr ? std::string_view() : std::string_view(reinterpret_cast<const char*>(text));
}

// Builds the ModelTree from libyaml's events, enforcing the limits as nodes arrive.
class TreeBuilder {
 public:
  TreeBuilder(const std::string& path, const ReadingLimits& limits, ModelTree& tree)
      : path_(path), limits_(limits), tree_(tree) {}

  bool has_root() const { return root_set_; }
  /// The innermost list or map not closed yet (for messages).
  OpenCollection innermost_open() const {
    OpenCollection open;
    if (stack_.empty()) return open;
    const Open& last = stack_.back();
    const TreeNode node = tree_.node(last.node);
    open.defined = true;
    open.map = last.map;
    open.flow = last.flow;
    open.line = static_cast<std::uint32_t>(node.line());
    open.column = static_cast<std::uint32_t>(node.column());
    return open;
  }

  /// Adds what `event` says to the tree.
  void handle(const yaml_event_t& event) {
    const yaml_mark_t& mark = event.start_mark;
    switch (event.type) {
      case YAML_DOCUMENT_START_EVENT:
        if (++documents_ > 1) {
          throw InputError(at(mark), "a second YAML document starts here ('---'): a model file holds exactly one "
                                     "model; put each model in a file of its own");
        }
        break;
      case YAML_ALIAS_EVENT: on_alias(mark, event_text(event.data.alias.anchor)); break;
      case YAML_SCALAR_EVENT: on_scalar(event); break;
      case YAML_SEQUENCE_START_EVENT:
        open(mark, TreeNode::Kind::sequence, event_text(event.data.sequence_start.anchor),
             event.data.sequence_start.style == YAML_FLOW_SEQUENCE_STYLE);
        break;
      case YAML_MAPPING_START_EVENT:
        open(mark, TreeNode::Kind::map, event_text(event.data.mapping_start.anchor),
             event.data.mapping_start.style == YAML_FLOW_MAPPING_STYLE);
        break;
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT: close(); break;
      default: break;  // stream start and end, document end
    }
  }

 private:
  struct Anchor {
    std::uint32_t node = 0;
    std::uint64_t expanded = 0;  ///< nodes the anchored node stands for
    std::string name;
    bool open = false;
  };
  struct Open {
    std::uint32_t node = 0;
    std::uint64_t expanded_at_start = 0;
    std::uint32_t anchor = 0;  ///< 1 + index into anchors_, 0 for none
    bool map = false, flow = false;
    std::vector<std::uint32_t> children;
  };

  void on_alias(const yaml_mark_t& mark, std::string_view name) {
    const auto found = anchor_index_.find(std::string(name));
    if (found == anchor_index_.end()) {
      throw InputError(at(mark), fmt::format("the alias '*{}' refers to an anchor that is not defined before it "
                                             "('&{}')",
                                             name, name));
    }
    const Anchor& target = anchors_[found->second];
    if (target.open) {
      throw InputError(at(mark), fmt::format("the alias '*{}' refers to the list or map that contains it (a "
                                             "self-referencing alias would expand without end)",
                                             target.name));
    }
    count(target.expanded, mark);
    attach(target.node);
  }

  void on_scalar(const yaml_event_t& event) {
    const yaml_mark_t& mark = event.start_mark;
    const auto& scalar = event.data.scalar;
    const std::string_view value(reinterpret_cast<const char*>(scalar.value), scalar.length);
    if (const TextPosition bad = first_unreadable_character(value, true); bad.line > 0) {
      throw InputError(at(mark), bad.problem == TextPosition::Problem::control
                                     ? fmt::format("this string contains the control character {} (written as an "
                                                   "escape?); names and values must be printable text (tab and "
                                                   "newline allowed)",
                                                   code_point_text(value, bad.offset))
                                     : "this string is not valid UTF-8 after its escapes are resolved (a \\u escape "
                                       "of a lone surrogate?)");
    }
    // A plain scalar without a tag: '~', 'null' and an empty node are nulls, '<<' a merge key.
    const bool plain = scalar.style == YAML_PLAIN_SCALAR_STYLE && scalar.tag == nullptr;
    const std::string_view anchor = event_text(scalar.anchor);
    if (plain && (value.empty() || value == "~" || value == "null" || value == "Null" || value == "NULL")) {
      close_leaf(add(mark, TreeNode::Kind::null, 0, 0), anchor);
      return;
    }
    if (plain && value == "<<" && !stack_.empty() && stack_.back().map && stack_.back().children.size() % 2 == 0) {
      throw InputError(at(mark), "YAML merge keys ('<<: *anchor') are not supported: write the keys of the map out "
                                 "in full");
    }
    const std::uint32_t offset = tree_.add_text(value);
    close_leaf(add(mark, TreeNode::Kind::scalar, offset, static_cast<std::uint32_t>(value.size())), anchor);
  }

  SourceLocation at(const yaml_mark_t& mark) const {
    return {path_, static_cast<int>(mark.line + 1), static_cast<int>(mark.column + 1)};
  }

  void count(std::uint64_t nodes, const yaml_mark_t& mark) {
    expanded_ += nodes;
    if (expanded_ > limits_.max_nodes) {
      throw InputError(at(mark), fmt::format("the document expands to more than {} nodes, the node limit (each "
                                             "alias counts as the nodes it stands for)",
                                             limits_.max_nodes));
    }
  }

  std::uint32_t add(const yaml_mark_t& mark, TreeNode::Kind kind, std::uint32_t begin, std::uint32_t length) {
    count(1, mark);
    ModelTree::Record record;
    record.line = static_cast<std::uint32_t>(mark.line + 1);
    record.column = static_cast<std::uint32_t>(mark.column + 1);
    record.begin = begin;
    record.count = length;
    record.kind = kind;
    return tree_.add(record);
  }

  // Registers the anchor `name` ("" for none) as standing for `node`; a later anchor of the
  // same name replaces it for the aliases that follow. Returns 1 + its index, or 0.
  std::uint32_t define(std::string_view name, std::uint32_t node) {
    if (name.empty()) return 0;
    Anchor entry;
    entry.node = node;
    entry.name = std::string(name);
    anchors_.push_back(std::move(entry));
    const auto index = static_cast<std::uint32_t>(anchors_.size() - 1);
    anchor_index_[anchors_.back().name] = index;
    return index + 1;
  }

  void attach(std::uint32_t node) {
    if (stack_.empty()) {
      tree_.set_root(node);
      root_set_ = true;
    } else {
      stack_.back().children.push_back(node);
    }
  }

  void close_leaf(std::uint32_t node, std::string_view anchor) {
    if (const std::uint32_t id = define(anchor, node); id != 0) anchors_[id - 1].expanded = 1;
    attach(node);
  }

  void open(const yaml_mark_t& mark, TreeNode::Kind kind, std::string_view anchor, bool flow) {
    // Levels are counted below the top-level map of the model.
    if (static_cast<int>(stack_.size()) > limits_.max_nesting) {
      throw InputError(at(mark), nesting_message(flow, limits_.max_nesting));
    }
    const std::uint64_t start = expanded_;
    const std::uint32_t node = add(mark, kind, 0, 0);
    const std::uint32_t id = define(anchor, node);
    if (id != 0) anchors_[id - 1].open = true;
    // Reuse the child lists of closed containers at this depth: no allocation per container.
    if (spare_.size() <= stack_.size()) spare_.resize(stack_.size() + 1);
    Open entry;
    entry.node = node;
    entry.expanded_at_start = start;
    entry.anchor = id;
    entry.map = kind == TreeNode::Kind::map;
    entry.flow = flow;
    entry.children = std::move(spare_[stack_.size()]);
    entry.children.clear();
    stack_.push_back(std::move(entry));
  }

  void close() {
    Open done = std::move(stack_.back());
    stack_.pop_back();
    tree_.set_children(done.node, done.children, done.map);
    if (done.anchor != 0) {
      Anchor& entry = anchors_[done.anchor - 1];
      entry.open = false;
      entry.expanded = expanded_ - done.expanded_at_start;
    }
    spare_[stack_.size()] = std::move(done.children);
    attach(done.node);
  }

  const std::string& path_;
  const ReadingLimits& limits_;
  ModelTree& tree_;
  std::vector<Open> stack_;
  std::vector<std::vector<std::uint32_t>> spare_;
  std::vector<Anchor> anchors_;
  std::unordered_map<std::string, std::uint32_t> anchor_index_;
  std::uint64_t expanded_ = 0;
  int documents_ = 0;
  bool root_set_ = false;
};

std::string describe(const TreeNode& node) {
  switch (node.kind()) {
    case TreeNode::Kind::scalar: return fmt::format("'{}'", input_excerpt(node.scalar()));
    case TreeNode::Kind::sequence: return "a list";
    case TreeNode::Kind::map: return "a map";
    default: return "nothing";
  }
}

[[noreturn]] void too_large(const std::string& source, const ReadingLimits& limits) {
  throw InputError({source, 0, 0}, fmt::format("the input is larger than the {} limit on model files (stopped "
                                               "reading there): the command's --max-input-size SIZE raises it "
                                               "(e.g. 1GiB); a large framework reads faster as a bar table "
                                               "(.bars, docs/formats.md)",
                                               size_text(limits.max_bytes)));
}

}  // namespace

std::string read_model_text(const std::string& path, const ReadingLimits& limits) {
  ReadOnlyFile file(path, "this is a folder, not a model file: give the path of a .yaml or .json model");
  const auto size = file.regular_size();
  if (size && *size > limits.max_bytes) too_large(path, limits);
  // Devices, FIFOs and pipes have no size: read in blocks and stop one byte past the limit.
  std::string text;
  if (size) text.reserve(*size);
  char block[1 << 16];
  while (const std::size_t got = file.read_some(block, sizeof block)) {
    text.append(block, got);
    if (text.size() > limits.max_bytes) too_large(path, limits);
  }
  return text;
}

std::string read_model_text(std::istream& in, const std::string& source, const ReadingLimits& limits) {
  std::string text;
  char block[1 << 16];
  while (in) {
    in.read(block, sizeof block);
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limits.max_bytes) too_large(source, limits);
  }
  if (in.bad()) throw InputError({source, 0, 0}, "cannot read the input");
  return text;
}

int significant_digits(std::string_view literal) {
  std::string digits;
  for (char ch : literal) {
    if (ch == 'e' || ch == 'E') break;
    if (std::isdigit(static_cast<unsigned char>(ch))) digits += ch;
  }
  const auto first = digits.find_first_not_of('0');
  return first == std::string::npos ? 1 : static_cast<int>(digits.size() - first);
}

namespace {

// Literals beyond these are refused: a double keeps 17 digits, and exact arithmetic on longer
// numbers only costs time.
constexpr std::size_t kMaxLiteralDigits = 4000;
constexpr long long kMaxDecimalExponent = 4000;

// Why a literal is not a decimal number, for the error message ("" if it is one).
enum class LiteralProblem { none, not_decimal, too_many_digits, exponent_too_large };

LiteralProblem parse_decimal(std::string_view literal, std::optional<mpq_class>* out) {
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
  if (!any_digit) return LiteralProblem::not_decimal;
  bool huge_exponent = false;
  if (i < literal.size() && (literal[i] == 'e' || literal[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < literal.size() && (literal[i] == '+' || literal[i] == '-')) exp_negative = literal[i++] == '-';
    long long e = 0;
    bool exp_digit = false;
    for (; i < literal.size() && std::isdigit(static_cast<unsigned char>(literal[i])); ++i) {
      if (e <= kMaxDecimalExponent) e = e * 10 + (literal[i] - '0');
      exp_digit = true;
    }
    if (!exp_digit) return LiteralProblem::not_decimal;
    huge_exponent = e > kMaxDecimalExponent;
    exponent += exp_negative ? -e : e;
  }
  if (i != literal.size()) return LiteralProblem::not_decimal;
  // Strip leading zeros so huge zero-padded literals cost nothing.
  const auto first = digits.find_first_not_of('0');
  digits = first == std::string::npos ? "0" : digits.substr(first);
  if (digits.size() > kMaxLiteralDigits) return LiteralProblem::too_many_digits;
  if (huge_exponent || std::abs(exponent) > 2 * kMaxDecimalExponent) return LiteralProblem::exponent_too_large;
  mpz_class numerator(digits, 10);
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  mpq_class value = exponent < 0 ? mpq_class(numerator, power) : mpq_class(numerator * power);
  value.canonicalize();
  *out = negative ? mpq_class(-value) : value;
  return LiteralProblem::none;
}

bool starts_with_prefix(std::string_view text, std::string_view prefix) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  if (text.size() <= prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  return true;
}

}  // namespace

std::optional<mpq_class> parse_exact_decimal(std::string_view literal) {
  std::optional<mpq_class> value;
  (void)parse_decimal(literal, &value);
  return value;
}

namespace {

__extension__ typedef unsigned __int128 DecimalWide;

// 10^k as a 128-bit integer (k ≤ 38).
DecimalWide decimal_power(int k) {
  DecimalWide power = 1;
  while (k-- > 0) power *= 10;
  return power;
}

// a × b into `out`, unless it passes 128 bits.
bool decimal_product_fits(DecimalWide a, DecimalWide b, DecimalWide& out) {
  if (a != 0 && b > ~DecimalWide{0} / a) return false;
  out = a * b;
  return true;
}

// a × 2^shift into `out`, unless it passes 128 bits.
bool decimal_shift_fits(DecimalWide a, int shift, DecimalWide& out) {
  if (a != 0 && (shift >= 128 || (shift > 0 && (a >> (128 - shift)) != 0))) return false;
  out = a == 0 ? a : a << shift;
  return true;
}

// Literals decimal_toward_zero reads: 10^19 < 2^64, and |value| within these bounds.
constexpr int kFastDecimalDigits = 19;
constexpr double kFastDecimalSmallest = 1e-300;
constexpr double kFastDecimalLargest = 1e300;

}  // namespace

std::optional<double> decimal_toward_zero(std::string_view literal) {
  // The grammar of parse_decimal: [+-] digits [. digits] [(e|E) [+-] digits], a digit somewhere
  // before the exponent; value n × 10^exponent.
  const std::size_t size = literal.size();
  std::size_t i = 0;
  bool negative = false;
  if (i < size && (literal[i] == '+' || literal[i] == '-')) negative = literal[i++] == '-';
  const auto is_digit = [](char ch) { return ch >= '0' && ch <= '9'; };
  std::uint64_t n = 0;
  int digits = 0;
  long long exponent = 0;
  bool any_digit = false;
  const auto take = [&](char ch) {
    any_digit = true;
    if (n == 0 && ch == '0') return true;  // leading zeros are not significant
    if (++digits > kFastDecimalDigits) return false;
    n = n * 10 + static_cast<std::uint64_t>(ch - '0');
    return true;
  };
  for (; i < size && is_digit(literal[i]); ++i)
    if (!take(literal[i])) return std::nullopt;
  if (i < size && literal[i] == '.') {
    for (++i; i < size && is_digit(literal[i]); ++i) {
      if (!take(literal[i])) return std::nullopt;
      --exponent;
    }
  }
  if (!any_digit) return std::nullopt;
  if (i < size && (literal[i] == 'e' || literal[i] == 'E')) {
    ++i;
    bool exponent_negative = false;
    if (i < size && (literal[i] == '+' || literal[i] == '-')) exponent_negative = literal[i++] == '-';
    long long e = 0;
    bool exponent_digit = false;
    for (; i < size && is_digit(literal[i]); ++i) {
      exponent_digit = true;
      if (e < 100000) e = e * 10 + (literal[i] - '0');
    }
    if (!exponent_digit) return std::nullopt;
    exponent += exponent_negative ? -e : e;
  }
  if (i != size) return std::nullopt;
  if (n == 0) return 0.0;  // GMP's zero has no sign: "-0" reads as +0
  // 10^|exponent| must fit in 128 bits for the comparison below.
  if (exponent > 38 || exponent < -38) return std::nullopt;
  // r: the double nearest to n × 10^exponent. One IEEE operation on exact operands when n and
  // the power of ten are exact doubles, otherwise from_chars (correctly rounded).
  double r = 0.0;
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (n <= (std::uint64_t{1} << 53) && exponent >= -22 && exponent <= 22) {
    const auto exact = static_cast<double>(n);
    r = exponent >= 0 ? exact * kPowers[exponent] : exact / kPowers[-exponent];
  } else {
    char buffer[64];
    char* end = std::to_chars(buffer, buffer + 32, n).ptr;
    *end++ = 'e';
    end = std::to_chars(end, buffer + sizeof buffer, exponent).ptr;
    const auto [stop, error] = std::from_chars(buffer, end, r);
    if (error != std::errc() || stop != end) return std::nullopt;
  }
  if (!(r >= kFastDecimalSmallest && r <= kFastDecimalLargest)) return std::nullopt;
  // r = mantissa × 2^binary exactly; compare it with n × 10^exponent in integers, both sides
  // multiplied by 10^−exponent and 2^−binary where those are negative.
  int scale = 0;
  const double fraction = std::frexp(r, &scale);
  const auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  const int binary = scale - 53;
  DecimalWide left = mantissa, right = n;
  if (exponent < 0 ? !decimal_product_fits(left, decimal_power(static_cast<int>(-exponent)), left)
                   : !decimal_product_fits(right, decimal_power(static_cast<int>(exponent)), right))
    return std::nullopt;
  if (binary > 0 ? !decimal_shift_fits(left, binary, left) : !decimal_shift_fits(right, -binary, right))
    return std::nullopt;
  // Rounded away from zero: the double below is the truncated value.
  if (left > right) r = std::nextafter(r, 0.0);
  return negative ? -r : r;
}

YamlFile YamlFile::parse(std::string path, const std::string& text, const ReadingLimits& limits) {
  if (text.size() > limits.max_bytes) too_large(path, limits);
  if (const TextPosition bad = first_unreadable_character(text); bad.line > 0) {
    throw InputError({path, bad.line, bad.column}, unreadable_message(text, bad));
  }
  if (const auto [line, column] = lone_carriage_return(text); line > 0) {
    throw InputError({path, line, column}, "a line ends with a lone carriage return (classic Mac line ends): save the "
                                           "file with LF or CR LF line ends");
  }
  const FlowScan flow = scan_flow(text, limits.max_nesting, limits.max_nodes);
  if (const auto [line, column] = flow.too_deep; line > 0) {
    throw InputError({path, line, column}, nesting_message(true, limits.max_nesting));
  }
  if (const auto [line, column] = flow.too_many; line > 0) {
    throw InputError({path, line, column},
                     fmt::format("the document has more than {} entries (lines and items of flow lists), past the "
                                 "node limit ({} nodes)",
                                 limits.max_nodes, limits.max_nodes));
  }
  if (const int line = excessive_block_nesting(text); line > 0) {
    throw InputError({path, line, 1}, fmt::format("indentation or block nesting deeper than {} levels", kMaxLeadingIndicators));
  }
  auto tree = std::make_shared<ModelTree>();
  // Every node but the root is one child entry; the scalars' text is never longer than the file.
  tree->reserve(std::min(text.size() / kBytesPerReservedNode + 1, limits.max_nodes + 1), text.size());
  TreeBuilder builder(path, limits, *tree);
  EventParser parser(text);
  while (true) {
    const yaml_event_t* event = parser.next();
    if (event == nullptr) throw malformed(path, text, parser.state(), builder.innermost_open());
    if (event->type == YAML_STREAM_END_EVENT) break;
    builder.handle(*event);
  }
  if (!builder.has_root() || tree->root().is_null()) throw InputError({path, 1, 1}, "empty model file: expected a map");
  YamlFile file(std::move(path), std::move(tree));
  file.expect_map(file.root(), "the model file");
  return file;
}

YamlFile YamlFile::load(const std::string& path, const ReadingLimits& limits) {
  if (path == "-") return parse("<stdin>", read_model_text(std::cin, "<stdin>", limits), limits);
  return parse(path, read_model_text(path, limits), limits);
}

void YamlFile::notice(const TreeNode& node, const std::string& problem) const {
  const SourceLocation at = where(node);
  const std::string line = fmt::format("{}:{}:{}: note: {}", printable_text(at.file), at.line, at.column, problem);
  notices_->push_back(line);
}

SourceLocation YamlFile::where(const TreeNode& node) const {
  if (!node.defined()) return {path_, 0, 0};
  return {path_, node.line(), node.column()};
}

void YamlFile::fail(const TreeNode& node, const std::string& problem) const { throw InputError(where(node), problem); }

void YamlFile::expect_map(const TreeNode& node, std::string_view what) const {
  if (!node.is_map()) fail(node, fmt::format("{} must be a map, found {}", what, describe(node)));
}

void YamlFile::expect_sequence(const TreeNode& node, std::string_view what) const {
  if (!node.is_sequence()) fail(node, fmt::format("{} must be a list, found {}", what, describe(node)));
}

namespace {

// The keys of `map` must be names from `allowed` (strings or string views), none twice. The
// first key that is not reported, in file order; earlier keys are compared directly (maps of a
// model have a few keys each), a large map through a set.
template <typename Names>
void check_map_keys(const YamlFile& file, const TreeNode& map, std::string_view what, const Names& allowed) {
  file.expect_map(map, what);
  constexpr std::size_t kCompareDirectly = 16;
  const std::size_t size = map.size();
  std::set<std::string_view> seen;
  for (std::size_t i = 0; i < size; ++i) {
    const TreeNode key_node = map.key(i);
    if (!key_node.is_scalar()) file.fail(key_node, fmt::format("keys of {} must be names", what));
    const std::string_view key = key_node.scalar();
    if (std::find_if(allowed.begin(), allowed.end(), [&](const auto& name) { return std::string_view(name) == key; }) ==
        allowed.end()) {
      std::string list;
      for (const auto& name : allowed) list += fmt::format("{}{}", list.empty() ? "" : ", ", std::string_view(name));
      file.fail(key_node, fmt::format("unknown key '{}' in {}; expected one of: {}", input_excerpt(key), what, list));
    }
    bool duplicate = false;
    if (size <= kCompareDirectly) {
      for (std::size_t j = 0; j < i && !duplicate; ++j) duplicate = map.key(j).scalar() == key;
    } else {
      duplicate = !seen.insert(key).second;
    }
    if (duplicate) file.fail(key_node, fmt::format("duplicate key '{}' in {}", input_excerpt(key), what));
  }
}

}  // namespace

void YamlFile::check_keys(const TreeNode& map, std::string_view what, std::initializer_list<std::string_view> allowed) const {
  check_map_keys(*this, map, what, allowed);
}

void YamlFile::check_keys(const TreeNode& map, std::string_view what, const std::vector<std::string>& allowed) const {
  check_map_keys(*this, map, what, allowed);
}

bool YamlFile::keys_allowed(const TreeNode& map, std::initializer_list<std::string_view> allowed) const {
  // check_map_keys compares at most this many keys directly; larger maps take the full check.
  constexpr std::size_t kKeysCompared = 16;
  if (!map.is_map() || map.size() > kKeysCompared) return false;
  const std::size_t size = map.size();
  for (std::size_t i = 0; i < size; ++i) {
    const TreeNode key_node = map.key(i);
    if (!key_node.is_scalar()) return false;
    const std::string_view key = key_node.scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (map.key(j).scalar() == key) return false;
  }
  return true;
}

TreeNode YamlFile::required(const TreeNode& map, std::string_view key, std::string_view what) const {
  TreeNode value = optional(map, key);
  if (!value.defined()) fail(map, fmt::format("{} is missing the key '{}'", what, key));
  return value;
}

TreeNode YamlFile::optional(const TreeNode& map, std::string_view key) const { return map[key]; }

ExactNumber YamlFile::number(const TreeNode& node, std::string_view what) const {
  if (!node.is_scalar()) fail(node, fmt::format("{} must be a number, found {}", what, describe(node)));
  const std::string_view text = node.scalar();
  ExactNumber result;
  switch (parse_decimal(text, &result.exact)) {
    case LiteralProblem::none: {
      result.value = result.exact->get_d();
      const bool underflow = result.value == 0.0 && sgn(*result.exact) != 0;
      if (!std::isfinite(result.value) || underflow) {
        fail(node, fmt::format("{} is out of range: '{}' is beyond what a double holds (about 1e-308 to 1e308)",
                               what, input_excerpt(text)));
      }
      return result;
    }
    case LiteralProblem::too_many_digits:
      fail(node, fmt::format("{} has more than {} significant digits; write it with fewer (a double keeps 17)", what,
                             kMaxLiteralDigits));
    case LiteralProblem::exponent_too_large:
      fail(node, fmt::format("{} is out of range: '{}' is beyond what a double holds (about 1e-308 to 1e308)", what,
                             input_excerpt(text)));
    case LiteralProblem::not_decimal: break;
  }
  if (starts_with_prefix(text, "0x")) fail(node, fmt::format("{} is written in hexadecimal ('{}'): write it as a decimal number", what, input_excerpt(text)));
  if (starts_with_prefix(text, "0o")) fail(node, fmt::format("{} is written in octal ('{}'): write it as a decimal number", what, input_excerpt(text)));
  if (starts_with_prefix(text, "0b")) fail(node, fmt::format("{} is written in binary ('{}'): write it as a decimal number", what, input_excerpt(text)));
  fail(node, fmt::format("{} must be a finite number, found '{}'", what, input_excerpt(text)));
}

long long YamlFile::integer(const TreeNode& node, std::string_view what) const {
  const ExactNumber n = number(node, what);
  if (!n.exact || n.exact->get_den() != 1 || std::abs(n.value) > 1e15) {
    fail(node, fmt::format("{} must be an integer, found '{}'", what, input_excerpt(node.scalar())));
  }
  return static_cast<long long>(n.value);
}

std::string YamlFile::string(const TreeNode& node, std::string_view what) const {
  if (!node.is_scalar() || node.scalar().empty()) {
    fail(node, fmt::format("{} must be a name, found {}", what, describe(node)));
  }
  return std::string(node.scalar());
}

std::vector<ExactNumber> YamlFile::numbers(const TreeNode& node, std::string_view what,
                                           std::initializer_list<std::size_t> lengths) const {
  expect_sequence(node, what);
  if (std::find(lengths.begin(), lengths.end(), node.size()) == lengths.end()) {
    std::string expected;
    for (std::size_t n : lengths) expected += (expected.empty() ? "" : " or ") + std::to_string(n);
    fail(node, fmt::format("{} must have {} numbers, found {}", what, expected, node.size()));
  }
  std::vector<ExactNumber> values;
  values.reserve(node.size());
  for (const TreeNode& item : node.items()) values.push_back(number(item, what));
  return values;
}

bool YamlFile::plain_numbers(const TreeNode& list, std::size_t count, double* values) const {
  if (!list.is_sequence() || list.size() != count) return false;
  for (std::size_t i = 0; i < count; ++i) {
    const TreeNode item = list[i];
    if (!item.is_scalar()) return false;
    const std::optional<double> value = decimal_toward_zero(item.scalar());
    if (!value) return false;
    values[i] = *value;
  }
  return true;
}

std::string model_kind(const YamlFile& file) {
  const TreeNode root = file.root();
  const TreeNode version = file.required(root, "kinestat", "the model file");
  if (file.integer(version, "the format version 'kinestat'") != 1) {
    file.fail(version, "unsupported format version: expected 'kinestat: 1'");
  }
  const TreeNode kind = file.optional(root, "kind");
  if (!kind.defined()) return "network";
  const std::string name = file.string(kind, "'kind'");
  if (name != "network" && name != "framework" && name != "structure") {
    file.fail(kind, fmt::format("unknown kind '{}'; expected network, framework or structure", input_excerpt(name)));
  }
  return name;
}

}  // namespace kinestat::io
