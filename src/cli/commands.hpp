// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The `kinestat` command is thin: each subcommand parses options, calls a reader in io/, a
// pure analysis, and a writer in report/. Each subcommand lives in its own file.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kinestat/framework/framework_model.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/model_format.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "kinestat/report/scene.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::cli {

/// What a subcommand runs once its options are parsed; returns the exit code.
using Action = std::function<int()>;

/// Options shared by the analysis subcommands.
struct CommonOptions {
  std::string model_path;
  bool json = false;
  std::string output_path;  ///< empty: standard output
  std::optional<double> tolerance;  ///< relative rank tolerance (default: the LAPACK rule)
  std::string backend = "serial";  ///< `analyze --backend`: serial, or petsc (under mpirun)
  bool timings = false;            ///< `analyze --timings`: the petsc backend's times and memory in the report
  bool brief = false;              ///< `--brief`: the verdict block alone (JSON: the `verdict` object alone)
  std::string fail_unless;         ///< `--fail-unless exactly-constrained`: exit 1 on any other verdict
};

/// Parses the command line, runs the chosen subcommand and returns the exit code: 0 success,
/// 2 bad input or usage, 3 internal error or out of memory.
int run(int argc, const char* const* argv);

/// Writes `text` to standard output, or atomically to `output_path` when it is set.
void emit(const CommonOptions& options, const std::string& text);

// Registration functions: each adds one subcommand to `app` and sets `action` when chosen.
void register_analyze(CLI::App& app, Action& action);
void register_structure(CLI::App& app, Action& action);
void register_draw(CLI::App& app, Action& action);
void register_report(CLI::App& app, Action& action);
void register_convert(CLI::App& app, Action& action);
void register_move(CLI::App& app, Action& action);
void register_sweep(CLI::App& app, Action& action);
/// `kinestat fix MODEL -o FIXED` (fix_command.cpp): the verdict's first verified change set applied and
/// written as a kinestat YAML model; exit 4 when already exactly constrained, 5 without a verified set.
void register_fix(CLI::App& app, Action& action);
void register_export(CLI::App& app, Action& action);
/// `kinestat stiffness MODEL --at NODE` (stiffness_command.cpp): linear stiffness of a framework at a node.
void register_stiffness(CLI::App& app, Action& action);

/// Prints `notices` (a model file's: older spellings read, what an import ignored or assumed)
/// to standard error, one line each; returns them (the JSON reports carry them too).
const std::vector<std::string>& print_notices(const std::vector<std::string>& notices);
/// Reads a model file of any format and kind ("-": a kinestat YAML / JSON model on standard
/// input); notices go to standard error (and stay in io::ModelFile::notices).
io::ModelFile read_model(const std::string& path);

/// Adds `--allow-outside-includes` to `command`: SDFormat and MJCF files may then include files
/// outside the model's folder (io::ImportOptions::allow_includes_outside_folder).
void add_import_options(CLI::App& command);
/// Reads a SPACAR file; its notices (what was ignored) go to standard error, one line each.
framework::FrameworkModel read_spacar_model(const std::string& path);
/// Reads a URDF, SDFormat or MJCF file; notices go to standard error, one line each.
io::LoadedNetwork read_imported_network(const std::string& path);

/// The kind of the parsed model file `file` (its `kind:`, network when absent).
io::ModelKind model_kind_of(const io::YamlFile& file);
/// A model of any kind, analysed by the pipeline and turned into a scene for `draw` and
/// `report`. `traced_motion`: frameworks also get the finite motion of their finite modes
/// traced both ways (framework::animation_traces), which the HTML report animates; SVG drawings
/// do not need it.
/// `misfit`: `kinestat report --misfit` (frameworks with elastic data; pipeline::picture_model).
pipeline::ModelPictures load_scene(const std::string& path, std::optional<double> tolerance, bool traced_motion = false,
                                   const std::optional<framework::MisfitTolerance>& misfit = std::nullopt);

// `analyze` dispatches on the model's kind to one of these; each kind adds its own options.
void register_network_options(CLI::App& analyze);
void register_framework_options(CLI::App& analyze);
/// `notices`: the import's notices (io::ModelFile::notices), given in the JSON report too.
int run_network_analysis(const CommonOptions& options, const io::LoadedNetwork& model, const std::string& path,
                         const std::vector<std::string>& notices = {});
/// Names of the kind-specific options given on the command line (e.g. "--primary").
std::vector<std::string> given_network_options();
/// `analyze --pair BODY1:BODY2` (as body indices of `model`, in the order given) and
/// `--coupled-pairs`: the pairs whose freedoms the sparse paths report. Throws io::InputError
/// (exit 2) for a name that is no body of `model` or a pair of one body.
struct PairRequest {
  std::vector<std::pair<int, int>> pairs;
  bool coupled = false;
  bool any() const { return !pairs.empty() || coupled; }
};
PairRequest requested_pairs(const network::Model& model);
std::vector<std::string> given_framework_options();
/// The value of `analyze --vectors` (0 when not given).
long long requested_vectors();
/// Exit 2 when options of another model kind were given: "--primary is an option that is not
/// used by a framework model".
void reject_options(const std::vector<std::string>& given, const std::string& kind, const std::string& path);
/// `notices`: the import's notices (io::ModelFile::notices), given in the JSON report too.
int run_framework_analysis(const CommonOptions& options, const framework::FrameworkModel& model, const std::string& path,
                           const std::vector<std::string>& notices = {});
/// `analyze --backend petsc` (petsc_backend.cpp): initialises MPI, reads the model on every
/// process and decides its counts by domain decomposition; without the backend built, an error (exit 2).
int run_petsc_analysis(const CommonOptions& options);

}  // namespace kinestat::cli
