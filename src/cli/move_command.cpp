// SPDX-License-Identifier: BSD-3-Clause
// `kinestat move FILE`: finite motion (issue 13). A framework: follow kinematic mode N with the
// predictor–corrector and print the path. A network: follow primary motion N the same way
// (--mode), or, planar, solve the positions of all bodies group by group at given input values
// (or over a sweep of one input).

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "kinestat/framework/finite_motion.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/generic_framework.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/finite_motion.hpp"
#include "kinestat/network/second_order.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/io/loaded_network.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/move_report.hpp"
#include "kinestat/report/position_solving.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat::cli {

namespace {

// The largest --amplitude: a path of a thousand characteristic lengths (many turns of any crank).
constexpr double kMaxTraceAmplitude = 1000.0;

struct MoveOptions {
  CommonOptions common;
  long long mode = 0;
  double amplitude = 0.1;
  long long steps = 20;
  std::vector<std::string> inputs;  ///< NAME=VALUE
  std::string sweep;                ///< NAME=FROM:TO:STEPS
  CLI::Option* mode_option = nullptr;
  CLI::Option* amplitude_option = nullptr;
  CLI::Option* steps_option = nullptr;
  CLI::Option* input_option = nullptr;
  CLI::Option* sweep_option = nullptr;
};

// All of `text` as a finite double, or nothing.
std::optional<double> finite_number(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value) || errno == ERANGE) return std::nullopt;
  return value;
}

struct NamedValue {
  std::string name;
  double value = 0.0;
};
using Sweep = report::SweptInput;

std::optional<NamedValue> parse_input(const std::string& text) {
  const auto eq = text.rfind('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  const auto value = finite_number(text.substr(eq + 1));
  if (!value) return std::nullopt;
  return NamedValue{text.substr(0, eq), *value};
}

std::optional<Sweep> parse_sweep(const std::string& text) {
  const auto eq = text.rfind('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  const std::string range = text.substr(eq + 1);
  const auto c1 = range.find(':');
  const auto c2 = c1 == std::string::npos ? c1 : range.find(':', c1 + 1);
  if (c2 == std::string::npos) return std::nullopt;
  const auto from = finite_number(range.substr(0, c1)), to = finite_number(range.substr(c1 + 1, c2 - c1 - 1));
  const std::string count = range.substr(c2 + 1);
  if (!from || !to || count.empty() || count.size() > 7) return std::nullopt;
  for (char c : count)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  const long long steps = std::stoll(count);
  if (steps < 1) return std::nullopt;
  return Sweep{text.substr(0, eq), *from, *to, steps};
}

CLI::Validator named_value_format() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parse_input(text) ? std::string{} : fmt::format("'{}' is not NAME=VALUE with a finite number VALUE (e.g. A=0.5)", text);
      },
      "NAME=VALUE");
}

CLI::Validator sweep_format() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parse_sweep(text) ? std::string{}
                                 : fmt::format("'{}' is not NAME=FROM:TO:STEPS with finite FROM, TO and 1 <= STEPS <= 9999999 "
                                               "(e.g. A=0:6.283185307179586:72)",
                                               text);
      },
      "NAME=FROM:TO:STEPS");
}

std::vector<std::string> given(const std::vector<CLI::Option*>& options) {
  std::vector<std::string> names;
  for (const CLI::Option* option : options)
    if (option != nullptr && option->count() > 0) names.push_back(option->get_name());
  return names;
}

int move_framework(const MoveOptions& options, const framework::FrameworkModel& model, const std::string& path) {
  reject_options(given({options.input_option, options.sweep_option}), "a framework", path);
  if (options.mode_option->count() == 0)
    throw io::InputError({path, 1, 1}, "a framework moves along one of its kinematic modes: give --mode N (modes as 'kinestat analyze' numbers them)");
  framework::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.common.tolerance);
  // The same basis of modes as `kinestat analyze` reports, so --mode N means the same mode.
  const framework::FrameworkResult analysis = framework::analyse_framework_as_reported(model, analysis_options);
  if (!analysis.vectors || analysis.method != framework::RankMethod::dense_svd)
    throw io::InputError({path, 1, 1}, "the framework is too large for the dense analysis that tracing needs");
  const auto modes = static_cast<long long>(analysis.modes.size());
  if (modes == 0) throw io::InputError({path, 1, 1}, "the framework has no kinematic mode: it cannot move (--mode has nothing to follow)");
  if (options.mode < 1 || options.mode > modes)
    throw io::InputError({path, 1, 1}, fmt::format("--mode {}: the framework has {} kinematic mode{}, numbered 1 to {}", options.mode, modes,
                                                   modes == 1 ? "" : "s", modes));
  report::FrameworkMove move;
  move.mode = static_cast<std::size_t>(options.mode - 1);
  move.amplitude_fraction = options.amplitude;
  move.steps = static_cast<int>(options.steps);
  framework::TraceOptions trace;
  trace.amplitude_fraction = options.amplitude;
  trace.steps = move.steps;
  trace.tolerance = linalg::RankTolerance{analysis_options.tolerances.rank};
  move.trace = framework::trace_motion(model, analysis, analysis.modes[move.mode].velocities, trace);
  emit(options.common, options.common.json ? report::json_text(report::framework_move_json(model, analysis, move))
                                           : report::framework_move_text(model, analysis, move));
  return 0;
}

// A network's primary motion N (numbered as `kinestat analyze` lists the primary motions),
// traced on the loop-closure equations.
int trace_network(const MoveOptions& options, const io::LoadedNetwork& loaded, const std::string& path) {
  if (const auto both = given({options.input_option, options.sweep_option}); !both.empty())
    throw io::InputError({path, 1, 1}, fmt::format("--mode and {} exclude each other: --mode follows a primary motion of the network, "
                                                   "--input and --sweep solve its positions at given inputs",
                                                   fmt::join(both, ", ")));
  if (static_cast<int>(loaded.model.couplings.size()) > network::kDenseNetworkLimit)
    throw io::InputError({path, 1, 1}, fmt::format("the network has more than {} couplings: too large for the dense analysis that tracing "
                                                   "needs",
                                                   network::kDenseNetworkLimit));
  network::AnalysisOptions analysis_options;
  analysis_options.tolerances = Tolerances::with_rank(options.common.tolerance);
  network::NetworkResult result;
  try {
    result = network::analyse_network(loaded.model, analysis_options);
  } catch (const network::ModelError& error) {
    throw io::locate(error, loaded, path);
  }
  const auto modes = static_cast<long long>(result.primary_motion.size());
  if (modes == 0) throw io::InputError({path, 1, 1}, "the network has no motion (FN = 0): it cannot move (--mode has nothing to follow)");
  if (options.mode < 1 || options.mode > modes)
    throw io::InputError({path, 1, 1}, fmt::format("--mode {}: the network has {} primary motion{} (FN), numbered 1 to {}", options.mode,
                                                   modes, modes == 1 ? "" : "s", modes));
  report::NetworkMove move;
  move.mode = static_cast<std::size_t>(options.mode - 1);
  move.amplitude_fraction = options.amplitude;
  move.steps = static_cast<int>(options.steps);
  network::NetworkSecondOrderOptions second_order_options;
  second_order_options.trace = false;
  const network::NetworkSecondOrder second_order = network::classify_network_motions(loaded.model, result, second_order_options);
  if (move.mode < second_order.motions.size()) move.second_order = second_order.motions[move.mode];
  network::NetworkTraceOptions trace;
  trace.amplitude_fraction = options.amplitude;
  trace.steps = move.steps;
  trace.tolerance = network::rank_rule_of(loaded.model, analysis_options.tolerances.rank);
  move.trace = network::trace_network_motion(loaded.model, result, result.motion_magnitudes.values.col(static_cast<Eigen::Index>(move.mode)),
                                             trace);
  emit(options.common, options.common.json ? report::json_text(report::network_move_json(loaded.model, result, move))
                                           : report::network_move_text(loaded.model, result, move));
  return 0;
}

int move_network(const MoveOptions& options, io::LoadedNetwork loaded, const std::string& path) {
  if (options.mode_option->count() > 0) return trace_network(options, loaded, path);
  if (const auto tracing = given({options.amplitude_option, options.steps_option}); !tracing.empty())
    throw io::InputError({path, 1, 1}, fmt::format("{} set{} the trace of a primary motion: give --mode N too (or remove {})",
                                                   fmt::join(tracing, ", "), tracing.size() == 1 ? "s" : "", tracing.size() == 1 ? "it" : "them"));
  std::vector<std::pair<std::string, double>> inputs;
  for (const std::string& text : options.inputs) {
    const NamedValue input = *parse_input(text);
    inputs.emplace_back(input.name, input.value);
  }
  std::optional<report::SweptInput> sweep;
  if (!options.sweep.empty()) sweep = parse_sweep(options.sweep);
  const report::PositionSweep result = report::solve_position_sweep(loaded, path, inputs, sweep,
                                                                    ", or follow one of its primary motions with --mode N");
  emit(options.common, options.common.json ? report::positions_json_text(loaded.model, result)
                                           : report::positions_text(loaded.model, result));
  return 0;
}

int run_move(const MoveOptions& options) {
  const std::string& path = options.common.model_path;
  if (io::model_format(path) == io::ModelFormat::spacar) return move_framework(options, read_spacar_model(path), path);
  if (io::model_format(path) != io::ModelFormat::kinestat)
    throw io::InputError({path, 1, 1}, "'kinestat move' reads kinestat model files (kind: framework or network)");
  const io::YamlFile file = io::YamlFile::load(path);
  const io::ModelKind kind = model_kind_of(file);
  if (kind == io::ModelKind::framework) return move_framework(options, io::read_framework_model(file), file.path());
  if (kind == io::ModelKind::network) return move_network(options, io::read_network_model(file), file.path());
  throw io::InputError({file.path(), 1, 1}, "a model of kind 'structure' has no geometry to move; write the mechanism as a network "
                                            "model (kind: network) with the points and axes of its couplings");
}

}  // namespace

void register_move(CLI::App& app, Action& action) {
  auto options = std::make_shared<MoveOptions>();
  CLI::App* command = app.add_subcommand(
      "move", "Finite motion: trace a framework's kinematic mode or a network's primary motion, or solve a planar mechanism's "
              "positions at given inputs");
  command->add_option("model", options->common.model_path, "Model file (kind: framework or network): kinestat YAML / JSON, SPACAR .dat, URDF .urdf, SDFormat .sdf or MJCF .xml; '-': kinestat YAML / JSON on standard input")->required();
  command->add_flag("--json", options->common.json, "Machine-readable JSON instead of text");
  command->add_option("-o,--output", options->common.output_path, "Write to this file instead of standard output");
  command->add_option("--tolerance", options->common.tolerance,
                      "Traces: relative rank tolerance (fraction of the largest singular value); default max(rows,cols)*eps")
      ->check(positive_finite_number());
  options->mode_option = command->add_option("--mode", options->mode, "Frameworks: the kinematic mode to follow; networks: the primary motion (1-based, as 'analyze' lists them)")
                             ->check(non_negative_whole_number());
  options->amplitude_option =
      command->add_option("--amplitude", options->amplitude,
                          "With --mode: arc length to follow, as a fraction of the characteristic length (at most 1000); "
                          "default 0.1")
          // Beyond a thousand model sizes a step no longer resolves the model: refused, not traced.
          ->check(positive_finite_number() & CLI::Range(0.0, kMaxTraceAmplitude));
  options->steps_option = command->add_option("--steps", options->steps, "With --mode: predictor-corrector steps; default 20")
                              ->check(non_negative_whole_number() & CLI::Range(1LL, 100000LL));
  options->input_option = command->add_option("--input", options->inputs,
                                              "Networks: a driving coupling and its value relative to the file (rad or length), "
                                              "NAME=VALUE; repeat for each input")
                              ->check(named_value_format())
                              ->expected(1)
                              ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  options->sweep_option = command->add_option("--sweep", options->sweep,
                                              "Networks: one driving coupling swept from FROM to TO in STEPS steps, NAME=FROM:TO:STEPS")
                              ->check(sweep_format());
  command->callback([options, &action] { action = [options] { return run_move(*options); }; });
}

}  // namespace kinestat::cli
