// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/pipeline/sweep_run.hpp"

#include <fmt/format.h>

#include "kinestat/io/model_file.hpp"
#include "kinestat/io/sweep_model.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/sweep_line.hpp"

namespace kinestat::pipeline {

namespace {

// The line of one variant read from `text` (named `path` in messages); counts a failure.
std::string variant_line(const report::SweepVariant& variant, const std::string& path, const std::string& text,
                         const SweepRunOptions& options, std::uint64_t& failed) {
  try {
    const io::ModelFile model = io::parse_model_text(path, text);
    return report::sweep_line_text(report::sweep_line(variant, analyze_report_json(model, options.tolerance), options.full));
  } catch (const Error& error) {
    ++failed;
    return report::sweep_line_text(report::sweep_error_line(variant, error.what()));
  }
}

}  // namespace

std::uint64_t run_sweep(const io::SweepSpec& spec, const SweepRunOptions& options,
                        const std::function<void(const std::string& line)>& on_line) {
  const design::SweepShard& shard = options.shard;
  std::optional<io::SweepModel> model;
  if (!spec.model.empty()) {
    const std::string path = io::spec_relative_path(spec.path, spec.model);
    std::string text;
    try {
      text = io::read_model_text(path);
    } catch (const io::InputError& error) {
      throw io::InputError(spec.model_where, fmt::format("the model '{}': {}", path, error.problem()));
    }
    model = io::prepare_sweep_model(spec, path, text);
  }
  std::vector<std::size_t> sizes;
  for (const auto& p : spec.parameters) sizes.push_back(p.values.size());
  std::uint64_t failed = 0;
  for (std::uint64_t v = shard.index; v < spec.count; v += shard.count) {
    report::SweepVariant variant{v, spec.count, nullptr, {}};
    if (model) {
      const std::vector<std::size_t> position = design::variant_position(v, sizes);
      variant.parameters = nlohmann::ordered_json::object();
      std::vector<std::string> literals;
      for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
        const double value = spec.parameters[p].values[position[p]];
        variant.parameters[spec.parameters[p].name] = value == 0.0 ? 0.0 : value;  // no -0
        literals.push_back(design::number_literal(value));
      }
      // Messages name the model as the spec writes it, so lines do not depend on the working directory.
      on_line(variant_line(variant, spec.model, io::variant_text(*model, literals), options, failed));
      continue;
    }
    const auto k = static_cast<std::size_t>(v);
    variant.file = spec.variants[k];
    std::string text;
    try {
      text = io::read_model_text(io::spec_relative_path(spec.path, spec.variants[k]));
    } catch (const io::InputError& error) {
      ++failed;
      on_line(report::sweep_line_text(report::sweep_error_line(variant, io::InputError(spec.variant_where[k], error.problem()).what())));
      continue;
    }
    on_line(variant_line(variant, spec.variants[k], text, options, failed));
  }
  return failed;
}

}  // namespace kinestat::pipeline
