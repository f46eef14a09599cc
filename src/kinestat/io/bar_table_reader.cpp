// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/bar_table_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "kinestat/io/input_error.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::io {

namespace {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::ElementType;
using framework::FrameworkModel;

// Shortest line of a node (one digit and a separator a coordinate) or a bar ("0 1"): the
// counts given are trusted for reserving memory only up to the lines the text can hold.
constexpr std::size_t kShortestEntryLine = 4;

// Longest piece of a token quoted back in an error message.
constexpr std::size_t kQuotedToken = 40;

class BarTableParser {
 public:
  BarTableParser(const std::string& path, std::string_view text) : path_(path), text_(text) {}

  FrameworkModel parse() {
    FrameworkModel model;
    model.name = "bar table";
    expect_line("the header 'kinestat bars 1' (a bar table: docs/formats.md)");
    if (token() != "kinestat" || token() != "bars" || token() != "1") fail(1, "expected the header 'kinestat bars 1'");
    end_of_line("the header 'kinestat bars 1'");

    expect_line("'dimension 2' or 'dimension 3'");
    keyword("dimension");
    const std::size_t dimension = count("the dimension, 2 or 3");
    if (dimension != 2 && dimension != 3) fail(token_column_, "expected the dimension 2 or 3");
    model.dimension = static_cast<int>(dimension);
    end_of_line("'dimension 2' or 'dimension 3'");

    read_nodes(model);
    read_bars(model);
    if (next_line()) {
      keyword("supports");
      read_supports(model);
    }
    if (next_line()) fail(1, "expected the end of the bar table after its supports");
    return model;
  }

 private:
  void read_nodes(FrameworkModel& model) {
    expect_line("'nodes N' (the number of nodes)");
    keyword("nodes");
    const std::size_t nodes = count("the number of nodes");
    // As a YAML framework (io/framework_reader): a model of no node is a mistake, not a structure.
    if (nodes == 0) fail(token_column_, "expected at least one node: a framework needs one");
    end_of_line("'nodes N'");
    model.nodes.reserve(std::min(nodes, text_.size() / kShortestEntryLine));
    const auto d = static_cast<Eigen::Index>(model.dimension);
    const char* coordinates = d == 2 ? "x y" : "x y z";
    for (std::size_t i = 0; i < nodes; ++i) {
      expect_line(fmt::format("the coordinates ({}) of node {} of {}", coordinates, i, nodes));
      framework::Node node;
      node.name = std::to_string(i);
      for (Eigen::Index k = 0; k < d; ++k) node.position(k) = number(fmt::format("the coordinates ({}) of node {}", coordinates, i));
      end_of_line(fmt::format("the {} coordinates ({}) of node {}", d, coordinates, i));
      model.nodes.push_back(std::move(node));
    }
    length_ = framework::characteristic_length(model);
  }

  void read_bars(FrameworkModel& model) {
    expect_line("'bars M' (the number of bars)");
    keyword("bars");
    const std::size_t bars = count("the number of bars");
    end_of_line("'bars M'");
    model.elements.reserve(std::min(bars, text_.size() / kShortestEntryLine));
    for (std::size_t k = 0; k < bars; ++k) {
      expect_line(fmt::format("bar {} of {}: the indices of its two nodes", k + 1, bars));
      framework::Element bar;
      bar.name = std::to_string(k + 1);
      bar.type = ElementType::truss;
      const std::size_t p = node_index(model, fmt::format("the first node of bar {}", k + 1));
      const int p_column = token_column_;
      const std::size_t q = node_index(model, fmt::format("the second node of bar {}", k + 1));
      const int q_column = token_column_;
      end_of_line(fmt::format("the two node indices of bar {}", k + 1));
      if (p == q) fail(q_column, fmt::format("bar {} joins node {} to itself", k + 1, p));
      const double length = (model.nodes[q].position - model.nodes[p].position).norm();
      if (!(length > kCoincident * length_))
        fail(p_column, fmt::format("zero-length bar {}: nodes {} and {} coincide", k + 1, p, q));
      bar.nodes = {p, q};
      bar.roles.assign(framework::deformation_count(model.dimension, bar), DeformationRole::fixed);
      model.elements.push_back(std::move(bar));
    }
  }

  void read_supports(FrameworkModel& model) {
    const std::size_t supports = count("the number of supports");
    end_of_line("'supports K'");
    const char* axes = model.dimension == 2 ? "x, y or xy" : "letters of xyz";
    std::vector<bool> supported(model.nodes.size(), false);
    for (std::size_t s = 0; s < supports; ++s) {
      expect_line(fmt::format("support {} of {}: a node index and the translations it holds ({})", s + 1, supports, axes));
      const std::size_t n = node_index(model, fmt::format("the node of support {}", s + 1));
      if (supported[n]) fail(token_column_, fmt::format("node {} is supported twice", n));
      supported[n] = true;
      const std::string_view held = token();
      if (held.empty()) fail(token_column_, fmt::format("expected the translations node {} holds ({})", n, axes));
      for (std::size_t i = 0; i < held.size(); ++i) {
        const auto slot = static_cast<int>(std::string_view("xyz").find(held[i]));
        if (slot < 0 || slot >= model.dimension)
          fail(token_column_ + static_cast<int>(i), fmt::format("expected the translations node {} holds ({})", n, axes));
        auto& role = model.nodes[n].roles[static_cast<std::size_t>(slot)];
        if (role == CoordinateRole::fixed)
          fail(token_column_ + static_cast<int>(i), fmt::format("translation {} of node {} is held twice", held[i], n));
        role = CoordinateRole::fixed;
      }
      end_of_line(fmt::format("support {}: a node index and its translations", s + 1));
    }
  }

  // The next line with content (not blank, not a '#' comment) becomes the current line; false
  // at the end of the text.
  bool next_line() {
    while (position_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', position_), text_.size());
      line_ = text_.substr(position_, end - position_);
      if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
      position_ = end + 1;
      ++line_number_;
      cursor_ = 0;
      const std::size_t first = line_.find_first_not_of(" \t");
      if (first != std::string_view::npos && line_[first] != '#') return true;
    }
    line_ = {};
    cursor_ = 0;
    return false;
  }

  void expect_line(const std::string& what) {
    if (!next_line()) {
      at_end_ = true;
      fail(1, "expected " + what + ", found the end of the file");
    }
  }

  // The next whitespace-separated token of the current line ("" at its end); its column in
  // token_column_.
  std::string_view token() {
    while (cursor_ < line_.size() && (line_[cursor_] == ' ' || line_[cursor_] == '\t')) ++cursor_;
    const std::size_t start = cursor_;
    while (cursor_ < line_.size() && line_[cursor_] != ' ' && line_[cursor_] != '\t') ++cursor_;
    token_column_ = static_cast<int>(start) + 1;
    return line_.substr(start, cursor_ - start);
  }

  void keyword(std::string_view word) {
    const std::string_view found = token();
    if (found != word) fail(token_column_, fmt::format("expected '{}', found {}", word, quoted(found)));
  }

  std::size_t count(const std::string& what) {
    const std::string_view found = token();
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(found.data(), found.data() + found.size(), value);
    if (found.empty() || error != std::errc() || end != found.data() + found.size() ||
        value > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      fail(token_column_, fmt::format("expected {} (a whole number up to {}), found {}", what,
                                      std::numeric_limits<int>::max(), quoted(found)));
    return static_cast<std::size_t>(value);
  }

  std::size_t node_index(const FrameworkModel& model, const std::string& what) {
    const std::string_view found = token();
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(found.data(), found.data() + found.size(), value);
    if (found.empty() || error != std::errc() || end != found.data() + found.size() || value >= model.nodes.size())
      fail(token_column_, fmt::format("expected {} (a node index from 0 to {}), found {}", what,
                                      static_cast<long long>(model.nodes.size()) - 1, quoted(found)));
    return static_cast<std::size_t>(value);
  }

  double number(const std::string& what) {
    const std::string_view found = token();
    double value = 0.0;
    const char* first = found.data();
    const char* last = found.data() + found.size();
    if (first != last && *first == '+') ++first;  // from_chars reads no '+'
    const auto [end, error] = std::from_chars(first, last, value);
    if (found.empty() || error != std::errc() || end != last || !std::isfinite(value))
      fail(token_column_, fmt::format("expected {} (finite numbers), found {}", what, quoted(found)));
    return value;
  }

  void end_of_line(const std::string& what) {
    const std::string_view extra = token();
    if (!extra.empty()) fail(token_column_, fmt::format("expected the end of the line after {}, found {}", what, quoted(extra)));
  }

  static std::string quoted(std::string_view found) {
    if (found.empty()) return "the end of the line";
    std::string shown(found.substr(0, kQuotedToken));
    for (char& c : shown)
      if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    return fmt::format("'{}'{}", shown, found.size() > kQuotedToken ? "..." : "");
  }

  [[noreturn]] void fail(int column, const std::string& problem) const {
    throw InputError({path_, at_end_ ? line_number_ + 1 : line_number_, at_end_ ? 1 : column}, problem);
  }

  const std::string& path_;
  std::string_view text_;
  std::size_t position_ = 0;   ///< start of the next line in text_
  std::string_view line_;      ///< the current line, without its newline
  int line_number_ = 0;        ///< 1-based number of the current line
  std::size_t cursor_ = 0;     ///< next character of line_ to read
  int token_column_ = 1;       ///< 1-based column of the last token read
  bool at_end_ = false;        ///< the problem is the end of the file (placed after the last line)
  double length_ = 1.0;        ///< characteristic length of the nodes, for coincident bar ends
};

}  // namespace

bool is_bar_table_path(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find_first_of("/\\", dot) != std::string::npos) return false;
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == "bars";
}

framework::FrameworkModel parse_bar_table(const std::string& path, std::string_view text) {
  return BarTableParser(path, text).parse();
}

}  // namespace kinestat::io
