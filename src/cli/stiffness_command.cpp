// SPDX-License-Identifier: BSD-3-Clause
// `kinestat stiffness MODEL --at NODE`: the linear stiffness of a framework at one node (issue 38).

#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/framework/over_constraint_cost.hpp"
#include "kinestat/framework/stiffness.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/pipeline/framework_pipeline.hpp"
#include "kinestat/report/analysed_cost_report.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/stiffness_report.hpp"

namespace kinestat::cli {

namespace {

struct StiffnessOptions {
  CommonOptions common;
  std::string at;                 ///< the node whose stiffness is asked
  std::vector<std::string> misfit;  ///< `--misfit VALUE` / `ELEMENT=VALUE` (issue 38 item 3), model length units
};

// The consistent unit names of a model whose length unit is `length` (docs/stiffness.md).
struct StiffnessUnits {
  std::string length, translation, rotation, coupling;
};

StiffnessUnits stiffness_units(const framework::FrameworkModel& model) {
  const std::string length = model.units.empty() ? "m" : model.units;
  return {length, "N/" + length, "N*" + length + "/rad", "N/rad"};
}

std::string number_text(double value) { return fmt::format("{:.6g}", value); }

std::string matrix_text(const Eigen::MatrixXd& matrix, const std::vector<std::string>& coordinates) {
  std::string out = fmt::format("  {:>4}", "");
  for (const std::string& c : coordinates) out += fmt::format(" {:>13}", c);
  out += "\n";
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    out += fmt::format("  {:>4}", coordinates[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) out += fmt::format(" {:>13}", number_text(report::rounded_for_report(matrix(i, j))));
    out += "\n";
  }
  return out;
}

std::string stiffness_text(const framework::FrameworkModel& model, const framework::NodeStiffness& result) {
  const StiffnessUnits units = stiffness_units(model);
  const std::string& name = model.nodes[result.node].name;
  std::string out = fmt::format("stiffness at node {}{}\n", name, model.name.empty() ? "" : " of " + model.name);
  out += fmt::format("units: length {}, force N; stiffness {} (translations), {} (rotations), {} (coupling)\n", units.length,
                     units.translation, units.rotation, units.coupling);
  if (!result.motion.empty()) {
    std::string motions;
    for (const auto& d : result.motion)
      motions += fmt::format("{}{} {} {}", motions.empty() ? "" : ", ", d.coordinate, number_text(d.stiffness),
                             d.rotation ? units.rotation : units.translation);
    out += "intended motion: " + motions + "\n";
    std::string supports;
    for (const auto& d : result.support)
      supports += fmt::format("{}{} {} {}", supports.empty() ? "" : ", ", d.coordinate, number_text(d.stiffness),
                              d.rotation ? units.rotation : units.translation);
    if (!supports.empty()) out += "support: " + supports + "\n";
    if (result.support_ratio)
      out += fmt::format("support / motion stiffness: {} (the weakest support of the motion's kind over the motion)\n",
                         number_text(*result.support_ratio));
    out += "(each: 1 / compliance along it, every other coordinate free)\n";
  }
  out += "\nmatrix (condensed at the node):\n" + matrix_text(result.matrix, result.coordinates);
  if (result.compliance) {
    out += "\ncompliance (inverse):\n" + matrix_text(*result.compliance, result.coordinates);
  } else {
    out += "\ncompliance: none: the node has a motion of zero stiffness (a mechanism)\n";
  }
  out += fmt::format("\nprincipal stiffnesses (ascending with rotations scaled by the model's size {} {}; direction over {}):\n",
                     number_text(result.length_scale), units.length, fmt::join(result.coordinates, ", "));
  for (const framework::PrincipalStiffness& p : result.principal) {
    std::string direction;
    for (Eigen::Index k = 0; k < p.direction.size(); ++k)
      direction += (k ? ", " : "") + number_text(report::rounded_for_report(p.direction(k)));
    out += fmt::format("  {:>13} {:<12} {:<11} [{}]\n", number_text(report::rounded_for_report(p.stiffness)),
                       p.rotation ? units.rotation : units.translation, p.rotation ? "rotation" : "translation", direction);
  }
  return out;
}

int run_stiffness(const StiffnessOptions& options) {
  const std::string& path = options.common.model_path;
  io::ModelFile file = read_model(path);
  if (!file.framework) {
    throw io::InputError({path, 1, 1}, "'kinestat stiffness' reads framework models (kind: framework, or a SPACAR .dat file)");
  }
  const framework::FrameworkModel& model = *file.framework;
  std::size_t node = model.nodes.size();
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (model.nodes[n].name == options.at) node = n;
  if (node == model.nodes.size()) {
    std::string names;
    for (std::size_t n = 0; n < model.nodes.size() && n < 20; ++n) names += (n ? ", " : "") + model.nodes[n].name;
    if (model.nodes.size() > 20) names += ", ...";
    throw io::InputError({path, 1, 1}, fmt::format("--at: unknown node '{}'; the model's nodes are: {}", options.at, names));
  }
  framework::NodeStiffness result;
  // `--misfit`: the cost of over-constraint (S2's misfit, prestress and frequencies) beside it.
  std::optional<framework::OverConstraintCost> cost;
  try {
    if (const std::optional<framework::MisfitTolerance> misfit = misfit_tolerance(options.misfit)) {
      check_misfit_elements(model, misfit, path);
      // The analysis as every report gives it (the generic answer may re-choose the basis of the
      // self-stresses), without the pipeline's own cost at the intended-motion node: the cost is
      // computed once, here, at --at, and carries the stiffness without the misfit.
      std::optional<framework::GenericFramework> generic;
      const framework::FrameworkResult analysis =
          framework::analyse_framework_as_reported(model, framework::AnalysisOptions{}, &generic);
      cost = framework::over_constraint_cost(model, analysis, node, *misfit);
      result = cost->without;
    } else {
      result = framework::stiffness_at(model, node);
    }
  } catch (const std::invalid_argument& error) {
    throw io::InputError({path, 1, 1}, error.what());
  }
  if (options.common.json) {
    nlohmann::ordered_json report = report::json_object(6);
    report["stiffness"] = report::node_stiffness_json(model, result);
    if (cost) {
      const nlohmann::ordered_json extra = report::over_constraint_json(model, *cost);
      for (auto item = extra.begin(); item != extra.end(); ++item) report[item.key()] = item.value();
    }
    report::add_versions(report);
    emit(options.common, report::json_text(report));
  } else {
    emit(options.common, stiffness_text(model, result) + (cost ? "\n" + report::over_constraint_text(model, *cost) : ""));
  }
  return 0;
}

}  // namespace

void register_stiffness(CLI::App& app, Action& action) {
  auto options = std::make_shared<StiffnessOptions>();
  CLI::App* command = app.add_subcommand(
      "stiffness", "Linear stiffness and compliance of a framework with materials and sections at one node (docs/stiffness.md)");
  command->add_option("model", options->common.model_path, "Framework model: kinestat YAML / JSON (kind: framework) or SPACAR .dat")
      ->required();
  command->add_option("--at", options->at, "The node whose stiffness is condensed (every other free coordinate free)")->required();
  add_misfit_option(*command, options->misfit,
                    "A manufacturing misfit (model length unit): the stress it locks into each redundant constraint, and "
                    "the stiffness and eigenfrequencies without and with it");
  command->add_flag("--json", options->common.json, "Machine-readable output: a `stiffness` object");
  command->add_option("-o,--output", options->common.output_path, "Write to this file instead of standard output");
  command->callback([options, &action] { action = [options] { return run_stiffness(*options); }; });
}

}  // namespace kinestat::cli
