// SPDX-License-Identifier: BSD-3-Clause
// `kinestat convert IN OUT`: a model from any supported format written as kinestat YAML
// (OUT.yaml) or as a SPACAR input file with kinestat's release proposal (OUT.dat).

#include <memory>

#include "cli/commands.hpp"
#include "cli/input_size_option.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_yaml_writer.hpp"
#include "kinestat/io/output_file.hpp"
#include "kinestat/io/spacar_writer.hpp"

namespace kinestat::cli {

namespace {

struct ConvertOptions {
  std::string input, output;
  bool apply_proposal = false;
  std::optional<double> tolerance;
};

std::string extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find_first_of("/\\", dot) != std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

framework::FrameworkModel read_framework_input(const std::string& path) {
  const io::ModelFormat format = io::model_format(path);
  if (format == io::ModelFormat::spacar || format == io::ModelFormat::bar_table) return read_spacar_model(path);
  const io::YamlFile file = io::YamlFile::load(path, model_reading_limits());  // --max-input-size
  const io::ModelKind kind = model_kind_of(file);
  if (kind != io::ModelKind::framework)
    throw io::InputError({path, 1, 1}, "'kinestat convert' converts frameworks (SPACAR files and kind: framework); this model "
                                       "is of kind '" + std::string(io::kind_name(kind)) + "' and is already kinestat YAML");
  framework::FrameworkModel model = io::read_framework_model(file);
  print_notices(file.notices());  // older spellings read
  return model;
}

int run(const ConvertOptions& options) {
  // Before reading: the input must survive a typo that names it twice.
  io::refuse_output_over_inputs(options.output, {options.input});
  const std::string out = extension(options.output);
  if (out != "dat" && out != "yaml" && out != "yml")
    throw io::InputError({options.output, 0, 0}, "unknown output format: name the output file .dat (SPACAR) or .yaml (kinestat)");
  const io::ModelFormat format = io::model_format(options.input);
  const std::vector<std::string> comments = {"converted by kinestat from " + options.input,
                                             "see docs/formats.md for how each element maps"};
  if (format == io::ModelFormat::urdf || format == io::ModelFormat::sdformat || format == io::ModelFormat::mjcf) {
    if (out == "dat")
      throw io::InputError({options.output, 0, 0}, "a robot description is a coupling network; SPACAR output is for frameworks "
                                                   "(write .yaml instead)");
    io::write_file_atomically(options.output, io::network_yaml(read_imported_network(options.input).model, comments));
    return 0;
  }
  const framework::FrameworkModel model = read_framework_input(options.input);
  if (out != "dat") {
    io::write_file_atomically(options.output, io::framework_yaml(model, comments));
    return 0;
  }
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.tolerance);
  const framework::FrameworkResult analysis = framework::analyse_framework(model, analysis_options);
  io::SpacarWriteOptions write;
  write.source = options.input;
  write.apply_proposal = options.apply_proposal;
  framework::FrameworkModel proposed;
  if (analysis.vectors) {
    proposed = framework::apply_proposal(model, analysis);
    write.proposed = &proposed;
  }
  io::write_file_atomically(options.output, io::spacar_text(model, write));
  return 0;
}

}  // namespace

void register_convert(CLI::App& app, Action& action) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* command = app.add_subcommand(
      "convert", "Write a model read from SPACAR, URDF, SDFormat or MJCF as kinestat YAML (OUT.yaml), or a framework as "
                 "a SPACAR input file with kinestat's release proposal (OUT.dat)");
  command->add_option("input", options->input, "Model file: SPACAR .dat, URDF .urdf, SDFormat .sdf, MJCF .xml, or kinestat YAML / JSON (kind: framework; '-': on standard input)")->required();
  command->add_option("output", options->output, "Output file: .yaml (kinestat) or .dat (SPACAR)")->required();
  command->add_flag("--apply-proposal", options->apply_proposal,
                    "SPACAR output: write the proposed releases as RLSE / INPUTX lines instead of commented lines to paste");
  command->add_option("--tolerance", options->tolerance, "Relative rank tolerance for the proposal (as for analyze)")
      ->check(positive_finite_number());
  command->callback([options, &action] { action = [options] { return run(*options); }; });
}

}  // namespace kinestat::cli
