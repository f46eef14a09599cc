// SPDX-License-Identifier: BSD-3-Clause
// `kinestat analyze FILE`: nett freedom and constraint of a coupling network or a framework.

#include "cli/commands.hpp"
#include "cli/input_size_option.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

#include <optional>

namespace kinestat::cli {

void register_analyze(CLI::App& app, Action& action) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand(
      "analyze", "Nett degree of freedom and of constraint of a model (kind: network or framework)");
  command->add_option("model", options->model_path, "Model file: kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf or MJCF .xml; '-': "
                      "kinestat YAML / JSON on standard input")->required();
  command->add_flag("--json", options->json, "Machine-readable JSON instead of text");
  command->add_flag("--brief", options->brief, "Print the verdict block alone (with --json: the verdict object alone)");
  command->add_option("-o,--output", options->output_path, "Write the report to this file instead of standard output");
  command->add_option("--tolerance", options->tolerance,
                      "Relative rank tolerance (fraction of the largest singular value); default max(rows,cols)*eps")
      ->check(positive_finite_number());
  command->add_option("--backend", options->backend,
                      "serial (default), or petsc: a framework's or a coupling network's counts and rank evidence decided "
                      "by domain decomposition on every process of "
                      "`mpirun -n P kinestat analyze --backend petsc FILE` (no null vectors; docs/scaling.md)")
      ->check(CLI::IsMember({"serial", "petsc"}));
  command->add_flag("--timings", options->timings,
                    "With --backend petsc: add each stage's wall time and every process's peak memory to the report "
                    "(they change from run to run, so the report is then not reproducible byte for byte)");
  add_fail_unless_option(*command, options->fail_unless);
  register_network_options(*command);
  register_framework_options(*command);
  command->callback([options, &action] {
    action = [options] {
      if (options->backend == "petsc" && !options->fail_unless.empty())
        throw io::InputError({"--fail-unless", 0, 0}, "--fail-unless needs the serial backend's verdict; drop --backend petsc");
      if (options->backend == "petsc") return run_petsc_analysis(*options);
      const io::ModelFormat format = io::model_format(options->model_path);
      if (format != io::ModelFormat::kinestat) {  // the import's notices on standard error and in the JSON report
        const io::ModelFile file = read_model(options->model_path);
        if (file.framework) return run_framework_analysis(*options, *file.framework, options->model_path, file.notices);
        return run_network_analysis(*options, *file.network, options->model_path, file.notices);
      }
      // The parsed tree is let go once the model is read: it is not needed by the analysis
      // (about 0.2 GB for 10^6 bars).
      std::optional<io::YamlFile> model(io::YamlFile::load(options->model_path, model_reading_limits()));
      const io::ModelKind kind = model_kind_of(*model);
      const std::string path = model->path();
      // Older spellings read: on standard error and in the JSON report.
      if (kind == io::ModelKind::network) {
        const auto network = io::keeping_notices(*model, io::read_network_model);
        const std::vector<std::string> notices = print_notices(model->notices());
        model.reset();
        return run_network_analysis(*options, network, path, notices);
      }
      if (kind == io::ModelKind::framework) {
        const framework::FrameworkModel framework = io::keeping_notices(*model, io::read_framework_model);
        const std::vector<std::string> notices = print_notices(model->notices());
        model.reset();
        return run_framework_analysis(*options, framework, path, notices);
      }
      throw io::InputError({options->model_path, 0, 0},
                           "a model of kind 'structure' is analysed with 'kinestat structure'");
    };
  });
}

}  // namespace kinestat::cli
