// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/sweep_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "kinestat/io/model_file.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

namespace {

bool whole_index(const std::string& step) {
  return !step.empty() && step.size() <= 9 && std::all_of(step.begin(), step.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool literal_character(char c) { return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'; }

// Byte offset of each line start of `text` (lines 1-based: line L starts at starts[L - 1]).
std::vector<std::size_t> line_starts(const std::string& text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts.push_back(i + 1);
  return starts;
}

// Byte offset of the `column`-th character (1-based, UTF-8) of the line starting at `start`.
std::size_t column_offset(const std::string& text, std::size_t start, int column) {
  std::size_t i = start;
  for (int c = 1; c < column && i < text.size() && text[i] != '\n'; ++c) {
    ++i;
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  }
  return i;
}

class SlotFinder {
 public:
  SlotFinder(const YamlFile& model, const std::string& text) : model_(model), text_(text), starts_(line_starts(text)) {}

  NumberSlot find(const SweepParameter& p) const {
    TreeNode node = model_.root();
    std::string reached = "the model";
    for (const std::string& step : p.path) {
      TreeNode next;
      if (node.is_map()) {
        next = node[step];
      } else if (node.is_sequence() && whole_index(step)) {
        next = node[static_cast<std::size_t>(std::stoul(step))];
      } else if (node.is_sequence()) {
        for (const TreeNode item : node.items())
          if (item.is_map() && item["name"].is_scalar() && item["name"].scalar() == step) next = item;
      }
      if (!next.defined()) fail(p, fmt::format("{} has no '{}'{}", reached, step, hint(node, step)));
      reached = fmt::format("'{}' (at {}:{}:{})", step, model_.path(), next.line(), next.column());
      node = next;
    }
    if (!node.is_scalar() || !parse_exact_decimal(node.scalar()))
      fail(p, fmt::format("{} is not a number of the model", reached));
    // The node's text in the file: a plain literal starts at the node's position.
    const auto line = static_cast<std::size_t>(node.line());
    if (line == 0 || line > starts_.size()) fail(p, fmt::format("{} cannot be found in the model's text", reached));
    // Columns count characters; should the parser count bytes, the byte column is tried too.
    const std::size_t start = starts_[line - 1];
    for (const std::size_t offset : {column_offset(text_, start, node.column()), start + static_cast<std::size_t>(node.column() - 1)}) {
      if (offset >= text_.size()) continue;
      std::size_t end = offset;
      while (end < text_.size() && literal_character(text_[end])) ++end;
      if (end > offset && text_.compare(offset, end - offset, node.scalar()) == 0) return {offset, end - offset};
    }
    fail(p, fmt::format("{} is not written as a plain number (quoted, or in another form): write it as a plain decimal "
                        "number so that a sweep can replace it",
                        reached));
  }

 private:
  static std::string hint(const TreeNode& node, const std::string& step) {
    if (node.is_sequence() && whole_index(step)) return fmt::format(" (it has {} items, numbered from 0)", node.size());
    if (node.is_sequence()) return " (no item of the list has that 'name')";
    if (!node.is_map()) return " (it is a single value)";
    return {};
  }

  [[noreturn]] void fail(const SweepParameter& p, const std::string& problem) const {
    throw InputError(p.where, fmt::format("the parameter '{}' ({}): {}", p.name, p.address, problem));
  }

  const YamlFile& model_;
  const std::string& text_;
  std::vector<std::size_t> starts_;
};

}  // namespace

SweepModel prepare_sweep_model(const SweepSpec& spec, const std::string& path, const std::string& text) {
  SweepModel model;
  model.path = path;
  model.text = text;
  const ModelFile read = parse_model_text(path, text);  // the model as it is must be valid
  if (read.kind == ModelKind::structure)
    throw InputError(spec.model_where, "a sweep analyses framework and network models; this model is of kind 'structure'");
  model.kind = std::string(kind_name(read.kind));
  const YamlFile file = YamlFile::parse(path, text);
  const SlotFinder finder(file, model.text);
  for (const SweepParameter& p : spec.parameters) {
    const NumberSlot slot = finder.find(p);
    for (std::size_t k = 0; k < model.slots.size(); ++k)
      if (model.slots[k].offset == slot.offset)
        throw InputError(p.where, fmt::format("the parameters '{}' and '{}' vary the same number of the model", spec.parameters[k].name, p.name));
    model.slots.push_back(slot);
  }
  return model;
}

std::string variant_text(const SweepModel& model, const std::vector<std::string>& literals) {
  std::vector<std::size_t> order(model.slots.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return model.slots[a].offset < model.slots[b].offset; });
  std::string text;
  text.reserve(model.text.size() + 32 * literals.size());
  std::size_t at = 0;
  for (const std::size_t k : order) {
    text.append(model.text, at, model.slots[k].offset - at);
    text += literals[k];
    at = model.slots[k].offset + model.slots[k].length;
  }
  text.append(model.text, at, std::string::npos);
  return text;
}

}  // namespace kinestat::io
