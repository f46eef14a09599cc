// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/sweep_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "kinestat/design/sweep_grid.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {

namespace {

// "x", "y", "z" as a coordinate index.
std::size_t coordinate_index(const YamlFile& file, const TreeNode& node) {
  const std::string name = file.string(node, "'coordinate'");
  if (name == "x") return 0;
  if (name == "y") return 1;
  if (name == "z") return 2;
  file.fail(node, fmt::format("'coordinate' must be x, y or z, found '{}'", name));
}

class SweepSpecReader {
 public:
  explicit SweepSpecReader(const YamlFile& file) : file_(file) {}

  SweepSpec read() {
    const TreeNode root = file_.root();
    file_.check_keys(root, "the sweep spec", {"kinestat", kSchemaKey, "kind", "name", "description", "model", "parameters", "variants"});
    const TreeNode version = file_.required(root, "kinestat", "the sweep spec");
    if (file_.integer(version, "the format version 'kinestat'") != 1) file_.fail(version, "unsupported format version: expected 'kinestat: 1'");
    const TreeNode kind = file_.required(root, "kind", "the sweep spec");
    if (file_.string(kind, "'kind'") != "sweep")
      file_.fail(kind, fmt::format("a sweep spec has 'kind: sweep', found '{}' (a model file is analysed with 'kinestat analyze')",
                                   kind.scalar()));
    if (auto name = file_.optional(root, "name"); name.defined()) (void)file_.string(name, "'name'");
    if (auto description = file_.optional(root, "description"); description.defined()) (void)file_.string(description, "'description'");
    spec_.path = file_.path();
    const TreeNode model = file_.optional(root, "model"), parameters = file_.optional(root, "parameters"),
                   variants = file_.optional(root, "variants");
    if (variants.defined()) {
      if (model.defined()) file_.fail(model, "a sweep has either 'model' with 'parameters' or 'variants' (a list of model files), not both");
      if (parameters.defined()) file_.fail(parameters, "'parameters' vary a 'model'; with 'variants' every file is one variant as it is");
      read_variants(variants);
    } else {
      if (!model.defined()) file_.fail(root, "the sweep spec is missing 'model' (the model file to vary) or 'variants' (a list of model files)");
      spec_.model = file_.string(model, "'model'");
      spec_.model_where = file_.where(model);
      if (!parameters.defined()) file_.fail(root, "the sweep spec is missing 'parameters' (the numbers of the model to vary)");
      read_parameters(parameters);
    }
    return spec_;
  }

 private:
  void read_variants(const TreeNode& variants) {
    file_.expect_sequence(variants, "'variants'");
    if (variants.size() == 0) file_.fail(variants, "'variants' must name at least one model file");
    for (const TreeNode item : variants.items()) {
      spec_.variants.push_back(file_.string(item, "a variant (a model file)"));
      spec_.variant_where.push_back(file_.where(item));
    }
    spec_.count = spec_.variants.size();
  }

  void read_parameters(const TreeNode& parameters) {
    file_.expect_sequence(parameters, "'parameters'");
    if (parameters.size() == 0) file_.fail(parameters, "'parameters' must list at least one parameter");
    std::vector<std::size_t> sizes;
    for (const TreeNode item : parameters.items()) {
      SweepParameter p = read_parameter(item);
      for (const auto& other : spec_.parameters) {
        if (other.name == p.name) file_.fail(item, fmt::format("the parameter '{}' is named twice", p.name));
        if (other.path == p.path) file_.fail(item, fmt::format("the parameters '{}' and '{}' vary the same number ({})", other.name, p.name, p.address));
      }
      if (p.values.size() > design::kMaxSweepVariants / product_)
        file_.fail(item, fmt::format("the parameters give more than {} variants", design::kMaxSweepVariants));
      product_ *= p.values.size();
      sizes.push_back(p.values.size());
      spec_.parameters.push_back(std::move(p));
    }
    const auto count = design::variant_count(sizes);
    if (!count) file_.fail(parameters, fmt::format("the parameters give more than {} variants", design::kMaxSweepVariants));
    spec_.count = *count;
  }

  SweepParameter read_parameter(const TreeNode& item) {
    const std::string what = "a parameter";
    file_.check_keys(item, what, {"name", "node", "coupling", "coordinate", "path", "from", "to", "steps", "values"});
    SweepParameter p;
    p.where = file_.where(item);
    p.name = file_.string(file_.required(item, "name", what), "the parameter's 'name'");
    read_address(item, p);
    read_values(item, p);
    return p;
  }

  void read_address(const TreeNode& item, SweepParameter& p) {
    const TreeNode node = file_.optional(item, "node"), coupling = file_.optional(item, "coupling"),
                   coordinate = file_.optional(item, "coordinate"), path = file_.optional(item, "path");
    const int given = int{node.defined()} + int{coupling.defined()} + int{path.defined()};
    if (given != 1)
      file_.fail(item, fmt::format("the parameter '{}' needs exactly one of 'node' (with 'coordinate'), 'coupling' (with "
                                   "'coordinate') or 'path' to say which number of the model it varies",
                                   p.name));
    if (path.defined()) {
      if (coordinate.defined()) file_.fail(coordinate, "'coordinate' goes with 'node' or 'coupling'; a 'path' ends at the number itself");
      file_.expect_sequence(path, "'path'");
      if (path.size() == 0) file_.fail(path, "'path' must list the steps to a number, e.g. [nodes, A1, 2]");
      for (const TreeNode step : path.items()) p.path.push_back(file_.string(step, "a step of 'path' (a key, a name or a 0-based index)"));
      p.address = fmt::format("path [{}]", fmt::join(p.path, ", "));
      return;
    }
    if (!coordinate.defined())
      file_.fail(item, fmt::format("the parameter '{}' needs 'coordinate' (x, y or z) of its {}", p.name, node.defined() ? "node" : "coupling's point"));
    const std::size_t c = coordinate_index(file_, coordinate);
    const std::string axis = std::string(1, "xyz"[c]);
    if (node.defined()) {
      const std::string name = file_.string(node, "'node'");
      p.path = {"nodes", name, std::to_string(c)};
      p.address = fmt::format("node {}, coordinate {}", name, axis);
    } else {
      const std::string name = file_.string(coupling, "'coupling'");
      p.path = {"couplings", name, "point", std::to_string(c)};
      p.address = fmt::format("coupling {}, coordinate {} of its point", name, axis);
    }
  }

  void read_values(const TreeNode& item, SweepParameter& p) {
    const TreeNode from = file_.optional(item, "from"), to = file_.optional(item, "to"), steps = file_.optional(item, "steps"),
                   values = file_.optional(item, "values");
    if (values.defined()) {
      for (const TreeNode& other : {from, to, steps})
        if (other.defined()) file_.fail(other, "a parameter takes either 'values' (a list) or 'from', 'to' and 'steps', not both");
      file_.expect_sequence(values, "'values'");
      if (values.size() == 0) file_.fail(values, "'values' must list at least one number");
      if (values.size() > static_cast<std::size_t>(design::kMaxSweepSteps) + 1)
        file_.fail(values, fmt::format("'values' lists more than {} numbers", design::kMaxSweepSteps + 1));
      for (const TreeNode value : values.items()) p.values.push_back(nearest(value, "a value"));
      return;
    }
    if (!from.defined() || !to.defined() || !steps.defined())
      file_.fail(item, fmt::format("the parameter '{}' needs 'from', 'to' and 'steps' (steps + 1 values from 'from' to 'to'), or "
                                   "'values' (a list)",
                                   p.name));
    const double a = nearest(from, "'from'"), b = nearest(to, "'to'");
    const long long n = file_.integer(steps, "'steps'");
    if (n < 1 || n > design::kMaxSweepSteps)
      file_.fail(steps, fmt::format("'steps' must be a whole number from 1 to {} (the parameter takes steps + 1 values)", design::kMaxSweepSteps));
    // Checked before the values are made, so no spec can ask for more memory than one large range.
    if (static_cast<std::uint64_t>(n + 1) > design::kMaxSweepVariants / product_)
      file_.fail(steps, fmt::format("the parameters give more than {} variants", design::kMaxSweepVariants));
    p.values = design::range_values(a, b, n);
  }

  // A number of the spec as the double nearest to its literal (checked by YamlFile::number,
  // whose value is the literal's rational truncated to a double), so that the literal written
  // into each variant is the one the user wrote whenever the value is one of theirs.
  double nearest(const TreeNode& node, std::string_view what) const {
    (void)file_.number(node, what);
    return std::strtod(std::string(node.scalar()).c_str(), nullptr);
  }

  const YamlFile& file_;
  SweepSpec spec_;
  std::uint64_t product_ = 1;  ///< variants of the parameters read so far (at most kMaxSweepVariants)
};

}  // namespace

SweepSpec parse_sweep_spec(const std::string& path, const std::string& text) {
  const YamlFile file = YamlFile::parse(path, text);
  return SweepSpecReader(file).read();
}

SweepSpec read_sweep_spec(const std::string& path) {
  if (path == "-") return parse_sweep_spec("<stdin>", read_model_text(std::cin, "<stdin>"));
  return parse_sweep_spec(path, read_model_text(path));
}

std::string spec_relative_path(const std::string& spec_path, const std::string& written) {
  const std::filesystem::path path(written);
  if (path.is_absolute()) return written;
  return (std::filesystem::path(spec_path).parent_path() / path).lexically_normal().string();
}

}  // namespace kinestat::io
