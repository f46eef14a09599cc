// SPDX-License-Identifier: BSD-3-Clause
// `kinestat structure FILE`: decomposition of a mechanism into structural groups (seed 004).

#include <cctype>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/input_size_option.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/structure_report.hpp"

namespace kinestat::cli {

namespace {

struct StructureOptions {
  CommonOptions common;
  bool from_stdin = false;
  std::string diagram;  ///< empty, "dot" or "svg"
  std::string method = "matching";
  std::uint64_t max_transformations = 1000;
};

// The seed's search enumerates chains, which grows combinatorially; beyond this size it
// would run for hours, so the option is refused rather than left to hang.
constexpr int kMaxSeedSearchBodies = 40;

bool starts_with_matrix(const std::string& text) {
  bool comment = false;
  for (char c : text) {
    if (comment) {
      comment = c != '\n';
      continue;
    }
    if (c == '#') comment = true;
    else if (!std::isspace(static_cast<unsigned char>(c))) return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+';
  }
  return true;  // empty input: the matrix reader says what is missing
}

// A structure model, or the couplings of a network model with the network itself (whose
// geometric verdict the report gives, as `analyze` does).
struct StructureInput {
  structure::StructureModel model;
  std::optional<io::LoadedNetwork> network;
  std::string path;
  std::vector<std::string> notices{};  // the import's (io::ModelFile::notices), also in the JSON report
};

StructureInput read_yaml_input(const io::YamlFile& file);

StructureInput read_input(const StructureOptions& options) {
  if (options.from_stdin || options.common.model_path == "-") {
    const std::string text = io::read_model_text(std::cin, "<stdin>");
    // A bare matrix starts with a code (after blank lines and '#' comments); anything else
    // is read as a YAML model (kind: structure or network, as from a file).
    if (!starts_with_matrix(text)) return io::keeping_notices(io::YamlFile::parse("<stdin>", text), read_yaml_input);
    return {io::read_adjacency_text(text, "<stdin>"), std::nullopt, "<stdin>"};
  }
  const std::string& path = options.common.model_path;
  const io::ModelFormat format = io::model_format(path);
  if (format == io::ModelFormat::spacar)
    throw io::InputError({path, 1, 1}, "a SPACAR file is a framework of nodes and elements; "
                                       "'kinestat structure' reads mechanisms (kind: structure or network)");
  if (format == io::ModelFormat::bar_table)
    throw io::InputError({path, 1, 1}, "a bar table is a framework of nodes and bars; "
                                       "'kinestat structure' reads mechanisms (kind: structure or network)");
  if (format != io::ModelFormat::kinestat) {
    io::ModelFile file = read_model(path);
    structure::StructureModel model = io::structure_of_network(*file.network, path);
    return {std::move(model), std::move(*file.network), path, std::move(file.notices)};
  }
  return io::keeping_notices(io::YamlFile::load(path, model_reading_limits()), read_yaml_input);
}

// A kinestat YAML / JSON model of kind structure, or network (its couplings' structure).
StructureInput read_yaml_input(const io::YamlFile& file) {
  const io::ModelKind kind = model_kind_of(file);
  if (kind == io::ModelKind::network) {
    io::LoadedNetwork network = io::read_network_model(file);
    structure::StructureModel model = io::structure_of_network(network, file.path());
    return {std::move(model), std::move(network), file.path(), print_notices(file.notices())};
  }
  if (kind != io::ModelKind::structure) {
    throw io::InputError({file.path(), 1, 1}, "'kinestat structure' reads models of kind 'structure' or 'network', found kind '" +
                                                   std::string(io::kind_name(kind)) + "'");
  }
  structure::StructureModel model = io::read_structure_model(file);
  return {std::move(model), std::nullopt, file.path(), print_notices(file.notices())};
}

int run(const StructureOptions& options) {
  StructureInput input = read_input(options);
  const auto method = options.method == "seed" ? structure::SearchMethod::seed_search : structure::SearchMethod::matching;
  if (method == structure::SearchMethod::seed_search && input.model.body_count() > kMaxSeedSearchBodies) {
    throw io::InputError({options.from_stdin ? "<stdin>" : options.common.model_path, 1, 1},
                         "--method seed enumerates chains and is limited to " + std::to_string(kMaxSeedSearchBodies) +
                             " bodies; this model has " + std::to_string(input.model.body_count()) +
                             " (use the default --method matching)");
  }
  if (!options.diagram.empty()) {
    const structure::StructureResult decomposition = pipeline::decompose(input.model, method);
    emit(options.common, options.diagram == "dot" ? report::structure_dot(input.model, decomposition)
                                                  : report::structure_svg(input.model, decomposition));
    return 0;
  }
  pipeline::StructureRequest request;
  request.method = method;
  request.max_transformations = options.max_transformations;
  pipeline::StructureAnalysis analysis;
  if (input.network) {
    // One story across commands: the network's geometric verdict, as `analyze` gives it.
    pipeline::NetworkAnalyses geometric;
    try {
      geometric = pipeline::analyse_network_model(*input.network, input.path, pipeline::NetworkRequest{});
    } catch (const network::ModelError& error) {
      throw io::locate(error, *input.network, input.path);
    }
    analysis = pipeline::analyse_network_structure(std::move(input.model), geometric, request);
  } else {
    analysis = pipeline::analyse_structure(std::move(input.model), request);
  }
  report::StructureReport report = analysis.report();
  report.notices = input.notices;
  emit(options.common, options.common.json ? report::structure_report_json(report) : report::structure_report_text(report));
  return verdict_exit_code(options.common.fail_unless, analysis.verdict);
}

}  // namespace

void register_structure(CLI::App& app, Action& action) {
  auto options = std::make_shared<StructureOptions>();
  CLI::App* command = app.add_subcommand(
      "structure", "Decompose a mechanism into structural groups (Assur groups) and rank the placements of its inputs");
  command->add_option("model", options->common.model_path,
                      "Model file (kind: structure or network: kinestat YAML / JSON, URDF .urdf, SDFormat .sdf or MJCF .xml), or '-' for "
                      "a matrix or model on standard input");
  command->add_flag("--stdin", options->from_stdin, "Read a whitespace-separated adjacency matrix (or a YAML model) from standard input");
  command->add_flag("--json", options->common.json, "Machine-readable JSON instead of text");
  command->add_flag("--brief", options->common.brief, "Print the verdict block alone (with --json: the verdict object alone)");
  command->add_option("-o,--output", options->common.output_path, "Write to this file instead of standard output");
  add_fail_unless_option(*command, options->common.fail_unless);
  command->add_option("--diagram", options->diagram, "Write the structural diagram instead of the report")
      ->check(CLI::IsMember({"dot", "svg"}));
  command->add_option("--method", options->method,
                      "Group search: matching (polynomial, default) or seed (the paper's Algorithms 1-3)")
      ->check(CLI::IsMember({"matching", "seed"}));
  command->add_option("--transformations", options->max_transformations,
                      "Analyse the other placements of the inputs when there are at most this many (0: skip)")
      ->check(non_negative_whole_number())
      ->capture_default_str();
  command->callback([options, &action] {
    if (options->common.model_path.empty() && !options->from_stdin) {
      throw CLI::RequiredError("model (a file, '-' or --stdin)");
    }
    action = [options] { return run(*options); };
  });
}

}  // namespace kinestat::cli
