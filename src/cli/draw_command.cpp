// SPDX-License-Identifier: BSD-3-Clause
// `kinestat draw FILE --what graph|mechanism|structure`: static SVG pictures of a model.

#include <fmt/format.h>

#include <memory>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/svg_writer.hpp"
#include "kinestat/pipeline/structure_pipeline.hpp"

namespace kinestat::cli {

namespace {

struct DrawOptions {
  CommonOptions common;
  std::string what;  ///< empty: graph for networks and structures, mechanism for frameworks
  int mode = 1;
  int stress = 1;
};

int run(const DrawOptions& options) {
  const pipeline::ModelPictures loaded = load_scene(options.common.model_path, options.common.tolerance);
  const io::ModelKind kind = loaded.kind;
  std::string what = options.what;
  if (what.empty()) what = kind == io::ModelKind::framework ? "mechanism" : "graph";
  const auto refuse = [&](const std::string& message) {
    throw io::InputError({options.common.model_path, 0, 0}, message);
  };
  if (what == "graph") {
    if (kind == io::ModelKind::framework) refuse("a framework has no coupling graph; draw it with --what mechanism");
    emit(options.common, report::graph_svg(loaded.scene));
  } else if (what == "mechanism") {
    if (kind == io::ModelKind::structure)
      refuse("a model of kind 'structure' has no geometry to draw; use --what graph or --what structure");
    // A sparse network's scene holds only the first basis vectors of its modes and self-stresses.
    const auto how_many = [](std::size_t drawn, std::size_t total, const std::string& states) {
      return total > drawn ? fmt::format("the model has {} {}; the first {} can be drawn", total, states, drawn)
                           : fmt::format("the model has {} {}", drawn, states);
    };
    if (options.mode > static_cast<int>(loaded.scene.modes.size()) && options.mode != 1)
      refuse(fmt::format("--mode {}: {}", options.mode, how_many(loaded.scene.modes.size(), loaded.scene.mode_total, "kinematic mode(s)")));
    if (options.stress > static_cast<int>(loaded.scene.stresses.size()) && options.stress != 1)
      refuse(fmt::format("--stress {}: {}", options.stress,
                         how_many(loaded.scene.stresses.size(), loaded.scene.stress_total, "self-stress state(s)")));
    emit(options.common, report::mechanism_svg(loaded.scene, {options.mode, options.stress}));
  } else {
    if (loaded.structure_error) throw *loaded.structure_error;
    if (!loaded.structure_model) refuse("a framework has no structural diagram; draw it with --what mechanism");
    emit(options.common, report::structure_svg(*loaded.structure_model, loaded.decomposition ? *loaded.decomposition
                                                                                      : pipeline::decompose(*loaded.structure_model)));
  }
  return 0;
}

}  // namespace

void register_draw(CLI::App& app, Action& action) {
  auto options = std::make_shared<DrawOptions>();
  CLI::App* command = app.add_subcommand("draw", "Draw a model as an SVG picture (coupling graph, mechanism, structural diagram)");
  command->add_option("model", options->common.model_path, "Model file of any kind: kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf or MJCF .xml; '-': kinestat YAML / JSON on standard input")->required();
  command->add_option("--what", options->what,
                      "graph: coupling graph with motion and action graphs; mechanism: the model with a mode and a "
                      "self-stress; structure: the structural diagram (default: mechanism for frameworks, graph otherwise)")
      ->check(CLI::IsMember({"graph", "mechanism", "structure"}));
  command->add_option("-o,--output", options->common.output_path, "Write the SVG to this file instead of standard output");
  command->add_option("--mode", options->mode, "Mechanism: kinematic mode drawn as arrows, 1-based (0: none)")
      ->check(non_negative_whole_number())
      ->capture_default_str();
  command->add_option("--stress", options->stress, "Mechanism: self-stress drawn as colours, 1-based (0: none)")
      ->check(non_negative_whole_number())
      ->capture_default_str();
  command->add_option("--tolerance", options->common.tolerance, "Relative rank tolerance (as for analyze)")
      ->check(positive_finite_number());
  command->callback([options, &action] { action = [options] { return run(*options); }; });
}

}  // namespace kinestat::cli
